#include "scenario.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "config_error.hpp"
#include "hli_names.hpp"

namespace hil {
namespace {

namespace fs = std::filesystem;

std::string read_text_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

ChannelState channel_state_of(const YAML::Node& node, const std::string& where) {
  ChannelState state{};
  if (!parse_channel_state(node.as<std::string>(), state))
    throw ConfigError(where + ": channel_state must be READY, ACTIVE, PROGRAM_END or ERROR");
  return state;
}

// A value for a named HLI field (hli_names.hpp): true / false or a whole
// number the field's type holds (a UDINT 0 .. 2^32-1, a BOOL 0 or 1).
template <typename Record>
int64_t hli_field_value(const std::string& key, const YAML::Node& node, const std::string& where) {
  const HliField<Record>* field = find_hli_field<Record>(key);
  if (!field) throw ConfigError(where + ": unknown HLI field '" + key + "' (known: " + hli_field_names<Record>() + ")");
  bool flag = false;
  int64_t value = 0;
  if (YAML::convert<bool>::decode(node, flag)) value = flag ? 1 : 0;
  else if (!YAML::convert<int64_t>::decode(node, value))
    throw ConfigError(where + ": '" + key + "' takes true, false or a whole number, not '" +
                      node.as<std::string>() + "'");
  if (!field->holds(value))
    throw ConfigError(where + ": '" + key + "' is " + field->type_text() + ", not " + node.as<std::string>());
  return value;
}

Condition parse_condition(const YAML::Node& node, const std::string& where) {
  Condition c;
  if (node.IsScalar() && node.as<std::string>() == "program_end") {
    c.channel_state = ChannelState::program_end;
    return c;
  }
  if (!node.IsMap()) throw ConfigError(where + ": 'when' must be a mapping or 'program_end'");
  for (const auto& item : node) {
    const std::string key = item.first.as<std::string>();
    if (key == "cycle") c.cycle = item.second.as<int64_t>();
    else if (key == "time_s") c.time_s = item.second.as<double>();
    else if (key == "block_nr_r") c.block_nr_r = item.second.as<int64_t>();
    else if (key == "block_count_r") c.block_count_r = item.second.as<int64_t>();
    else if (key == "dist_prog_start_mm") c.dist_prog_start_mm = item.second.as<double>();
    else if (key == "channel_state") c.channel_state = channel_state_of(item.second, where);
    else if (key == "delete_distance_to_go_active_r") c.delete_distance_to_go_active_r = item.second.as<bool>();
    else if (key == "m_function_nr_r") c.m_function_nr_r = item.second.as<int32_t>();
    else c.fields[key] = hli_field_value<HliState>(key, item.second, where);
  }
  return c;
}

TimelineStep parse_step(const YAML::Node& node, const std::string& where) {
  TimelineStep step;
  if (!node["when"]) throw ConfigError(where + ": 'when' is missing");
  step.when = parse_condition(node["when"], where);
  const YAML::Node set = node["set"];
  if (!set || !set.IsMap()) throw ConfigError(where + ": 'set' must map control unit fields to values");
  for (const auto& item : set) {
    const std::string key = item.first.as<std::string>();
    step.set.push_back({key, hli_field_value<HliControl>(key, item.second, where)});
  }
  return step;
}

Expectation parse_expectation(const YAML::Node& node, const std::string& where) {
  Expectation e;
  if (!node["when"]) throw ConfigError(where + ": 'when' is missing");
  e.when = parse_condition(node["when"], where);
  for (const auto& item : node) {
    const std::string key = item.first.as<std::string>();
    if (key == "when") continue;
    if (key == "channel_state") e.channel_state = channel_state_of(item.second, where);
    else if (key == "block_nr_r") e.block_nr_r = item.second.as<int64_t>();
    else if (key == "block_count_r") e.block_count_r = item.second.as<int64_t>();
    else if (key == "dist_prog_start_mm") e.dist_prog_start_mm = item.second.as<double>();
    else if (key == "tolerance_mm") e.tolerance_mm = item.second.as<double>();
    else if (key == "delete_distance_to_go_active_r") e.delete_distance_to_go_active_r = item.second.as<bool>();
    else if (key == "axis_position_mm") {
      for (const auto& axis : item.second)
        e.axis_position_mm[axis.first.as<std::string>()] = axis.second.as<double>();
    } else {
      e.fields[key] = hli_field_value<HliState>(key, item.second, where);
    }
  }
  return e;
}

EventExpectation parse_event_expectation(const YAML::Node& node, const std::string& where) {
  EventExpectation e;
  if (!node["id"] && !node["parameter"]) throw ConfigError(where + ": give 'id' and/or 'parameter'");
  if (node["id"]) e.id = node["id"].as<int32_t>();
  if (node["parameter"]) e.parameter = node["parameter"].as<std::string>();
  if (node["severity"]) {
    const std::string s = node["severity"].as<std::string>();
    if (s == "warning") e.severity = Severity::warning;
    else if (s == "error") e.severity = Severity::error;
    else if (s == "info") e.severity = Severity::info;
    else throw ConfigError(where + ": severity must be info, warning or error");
  }
  if (node["nc_line"]) e.nc_line = node["nc_line"].as<int64_t>();
  if (node["count_min"]) e.count_min = node["count_min"].as<int>();
  if (node["absent"]) e.absent = node["absent"].as<bool>();
  return e;
}

ViolationExpectation parse_violation_expectation(const YAML::Node& node, const std::string& where) {
  if (!node["axis"] || !node["quantity"]) throw ConfigError(where + ": give 'axis' and 'quantity'");
  return {node["axis"].as<std::string>(), node["quantity"].as<std::string>()};
}

template <typename T, typename Parse>
std::vector<T> parse_list(const YAML::Node& node, const std::string& name, Parse parse) {
  std::vector<T> items;
  if (!node) return items;
  if (!node.IsSequence()) throw ConfigError(name + " must be a list");
  for (size_t i = 0; i < node.size(); ++i)
    items.push_back(parse(node[i], name + "[" + std::to_string(i) + "]"));
  return items;
}

}  // namespace

bool Condition::holds(const HliState& s, double cycle_time_s) const {
  if (cycle && s.cycle < *cycle) return false;
  if (time_s && s.cycle * cycle_time_s + 1e-12 < *time_s) return false;
  if (block_nr_r && s.block_nr_r != *block_nr_r) return false;
  if (block_count_r && s.block_count_r != *block_count_r) return false;
  if (dist_prog_start_mm && s.dist_prog_start / hli_units_per_mm < *dist_prog_start_mm) return false;
  if (channel_state && s.channel_state != *channel_state) return false;
  if (delete_distance_to_go_active_r && s.delete_distance_to_go_active_r != *delete_distance_to_go_active_r)
    return false;
  if (m_function_nr_r && !(s.m_function_request_r && s.m_function_nr_r == *m_function_nr_r)) return false;
  for (const auto& [name, value] : fields)
    if (read_hli_field(s, name) != value) return false;
  return true;
}

std::string Condition::describe() const {
  std::ostringstream out;
  const char* sep = "";
  if (cycle) out << sep << "cycle>=" << *cycle, sep = " ";
  if (time_s) out << sep << "time_s>=" << *time_s, sep = " ";
  if (block_nr_r) out << sep << "block_nr_r=" << *block_nr_r, sep = " ";
  if (block_count_r) out << sep << "block_count_r=" << *block_count_r, sep = " ";
  if (dist_prog_start_mm) out << sep << "dist_prog_start_mm>=" << *dist_prog_start_mm, sep = " ";
  if (channel_state) out << sep << "channel_state=" << to_string(*channel_state), sep = " ";
  if (delete_distance_to_go_active_r)
    out << sep << "delete_distance_to_go_active_r=" << (*delete_distance_to_go_active_r ? "true" : "false"), sep = " ";
  if (m_function_nr_r) out << sep << "m_function_nr_r=" << *m_function_nr_r, sep = " ";
  for (const auto& [name, value] : fields) out << sep << name << "=" << value, sep = " ";
  return out.str();
}

Scenario parse_scenario(const YAML::Node& root) {
  if (!root.IsMap()) throw ConfigError("scenario: expected a mapping at the top");
  Scenario s;
  try {
    s.name = root["name"] ? root["name"].as<std::string>() : "scenario";
    if (root["description"]) s.description = root["description"].as<std::string>();
    if (root["requirements"])
      for (const auto& r : root["requirements"]) s.requirements.push_back(r.as<std::string>());
    if (!root["machine"] || !root["machine"].IsMap())
      throw ConfigError("scenario: 'machine' (a mapping or a file name) is missing");
    s.machine = parse_machine_config(root["machine"]);
    if (!root["nc_program"]) throw ConfigError("scenario: 'nc_program' or 'nc_file' is missing");
    s.nc_program = root["nc_program"].as<std::string>();
    if (const YAML::Node run = root["run"]) {
      if (run["max_time_s"]) s.max_time_s = run["max_time_s"].as<double>();
      if (run["settle_time_s"]) s.settle_time_s = run["settle_time_s"].as<double>();
      if (run["allow_errors"]) s.allow_errors = run["allow_errors"].as<bool>();
    }
    if (!(s.max_time_s > 0)) throw ConfigError("scenario: run.max_time_s must be > 0");
    if (s.settle_time_s < 0) throw ConfigError("scenario: run.settle_time_s must be >= 0");
    const YAML::Node plc = root["plc"];
    if (plc) s.timeline = parse_list<TimelineStep>(plc["timeline"], "plc.timeline", parse_step);
    if (plc && plc["m_function_ack_cycles"]) s.m_function_ack_cycles = plc["m_function_ack_cycles"].as<int>();
    if (s.m_function_ack_cycles < 0) throw ConfigError("scenario: plc.m_function_ack_cycles must be >= 0");
    s.expectations = parse_list<Expectation>(root["expect"], "expect", parse_expectation);
    s.expected_events = parse_list<EventExpectation>(root["expect_events"], "expect_events",
                                                     parse_event_expectation);
    s.expected_violations = parse_list<ViolationExpectation>(root["expect_violations"], "expect_violations",
                                                             parse_violation_expectation);
    for (const auto& v : s.expected_violations)
      if (s.machine.axis_index(v.axis) < 0)
        throw ConfigError("expect_violations: axis '" + v.axis + "' is not on the machine");
    for (const auto& e : s.expectations)
      for (const auto& axis : e.axis_position_mm)
        if (s.machine.axis_index(axis.first) < 0)
          throw ConfigError("expect: axis '" + axis.first + "' is not on the machine");
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("scenario: ") + e.what());
  }
  s.resolved = root;
  return s;
}

Scenario load_scenario_file(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + ": " + e.what());
  }
  if (!root.IsMap()) throw ConfigError(path + ": expected a mapping at the top");
  const fs::path dir = fs::path(path).parent_path();
  try {
    if (root["machine"] && root["machine"].IsScalar()) {
      const fs::path machine_file = dir / root["machine"].as<std::string>();
      try {
        root["machine"] = YAML::LoadFile(machine_file.string());
      } catch (const YAML::Exception& e) {
        throw ConfigError(machine_file.string() + ": " + e.what());
      }
    }
    if (root["nc_file"]) {
      if (root["nc_program"]) throw ConfigError("give either 'nc_program' or 'nc_file', not both");
      root["nc_program"] = read_text_file(dir / root["nc_file"].as<std::string>());
      root.remove("nc_file");
    }
    return parse_scenario(root);
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

std::string to_yaml(const Scenario& scenario) {
  YAML::Emitter out;
  out << scenario.resolved;
  return out.c_str();
}

}  // namespace hil
