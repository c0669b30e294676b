#include "scenario.hpp"
#include "file_keys.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "config_error.hpp"
#include "hli_names.hpp"
#include "yaml_error.hpp"

namespace hil {
namespace {

namespace fs = std::filesystem;

// The keys each mapping of a scenario may have (docs/SCENARIOS.md); any
// other is refused (ConfigMap). Triggers and expectations also take the
// HLI state fields by name (hli_names.hpp).
const std::vector<std::string> scenario_keys = {"name", "description", "requirements", "machine", "nc_program",
                                                "nc_file", "run", "plc", "expect", "expect_events",
                                                "faults", "fault_seed",
                                                "expect_violations", "variants", "compare"};
const std::vector<std::string> run_keys = {"max_time_s", "settle_time_s", "allow_errors", "realtime"};
const std::vector<std::string> plc_keys = {"timeline", "m_function_ack_cycles"};
const std::vector<std::string> step_keys = {"when", "set"};
const std::vector<std::string> event_keys = {"id", "parameter", "severity", "nc_line", "count_min", "absent"};
const std::vector<std::string> violation_keys = {"axis", "quantity"};

// `keys` and the fields of Record not among them (a key's own meaning wins).
template <typename Record>
std::vector<std::string> with_hli_fields(std::vector<std::string> keys) {
  for (const HliField<Record>& field : hli_fields<Record>())
    if (std::find(keys.begin(), keys.end(), field.name) == keys.end()) keys.push_back(field.name);
  return keys;
}
// The bounds on an axis' extremes over an expectation's window.
struct ExtremeKey {
  const char* key;
  bool highest;
  ExtremeCheck::Bound bound;
};
constexpr ExtremeKey extreme_keys[] = {
    {"axis_max_mm", true, ExtremeCheck::Bound::equal},
    {"axis_max_at_least_mm", true, ExtremeCheck::Bound::at_least},
    {"axis_max_at_most_mm", true, ExtremeCheck::Bound::at_most},
    {"axis_min_mm", false, ExtremeCheck::Bound::equal},
    {"axis_min_at_least_mm", false, ExtremeCheck::Bound::at_least},
    {"axis_min_at_most_mm", false, ExtremeCheck::Bound::at_most},
};
const ExtremeKey* find_extreme_key(const std::string& key) {
  for (const ExtremeKey& k : extreme_keys)
    if (key == k.key) return &k;
  return nullptr;
}

// An expectation's own keys, then the condition keys it checks at `when`.
const std::vector<std::string>& expectation_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> own = {"when", "since", "until", "never", "always", "tolerance_mm",
                                    "time_s_at_least", "time_s_at_most", "path_velocity_max_at_least_mm_s",
                                    "path_velocity_max_at_most_mm_s"};
    for (const ExtremeKey& k : extreme_keys) own.push_back(k.key);
    for (const std::string& key : condition_keys())
      if (std::find(own.begin(), own.end(), key) == own.end()) own.push_back(key);
    return own;
  }();
  return keys;
}
// A never: / always: expectation watches a condition over a window: its
// other keys belong to an expectation at a moment.
const std::vector<std::string> watch_keys = {"never", "always", "since", "until"};
const std::vector<std::string>& control_keys() {
  static const std::vector<std::string> keys = with_hli_fields<HliControl>({});
  return keys;
}

constexpr int64_t int32_max = std::numeric_limits<int32_t>::max();
// Simulated seconds: the cycle count and the rig's wall-clock bound
// (20 s a simulated second) stay far inside 64 bits.
constexpr double max_run_time_s = 1e6;

// A file's text; a directory or a missing file is named as such (an
// ifstream "reads" a directory as empty: an NC program of no blocks).
std::string read_text_file(const fs::path& path, const std::string& what) {
  std::error_code error;
  if (!fs::exists(path, error)) throw ConfigError(path.string() + ": no such " + what);
  if (fs::is_directory(path, error)) throw ConfigError(path.string() + ": " + what + " is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path.string() + ": cannot read the " + what + " (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

YAML::Node load_yaml_file(const fs::path& path, const std::string& what) {
  const std::string text = read_text_file(path, what);
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path.string() + ": " + explain_yaml_error(text, e));
  }
}

// A value for a named HLI field (hli_names.hpp): true / false or a whole
// number the field's type holds (a UDINT 0 .. 2^32-1, a BOOL 0 or 1).
template <typename Record>
int64_t hli_field_value(const std::string& key, const YAML::Node& node, const std::string& where) {
  const HliField<Record>* field = find_hli_field<Record>(key);
  if (!field) throw unknown_key(where, key, with_hli_fields<Record>({}), "HLI field");
  bool flag = false;
  int64_t value = 0;
  if (!node.IsScalar()) throw ConfigError(where + ": '" + key + "' takes true, false or a whole number");
  if (YAML::convert<bool>::decode(node, flag)) value = flag ? 1 : 0;
  else if (!YAML::convert<int64_t>::decode(node, value))
    throw ConfigError(where + ": '" + key + "' takes true, false or a whole number, not '" + node.Scalar() + "'");
  if (!field->holds(value))
    throw ConfigError(where + ": '" + key + "' is " + field->type_text() + ", not " + node.Scalar());
  return value;
}

// A map of axis names to values, `{Z: 30}`; each axis once.
template <typename Value, typename Parse>
std::map<std::string, Value> axis_map(const YAML::Node& node, const std::string& where, const char* what,
                                      Parse parse) {
  if (!node.IsMap()) throw ConfigError(where + ": must map axis names to " + what);
  std::map<std::string, Value> out;
  for (const auto& axis : node) {
    const std::string name = config_text(axis.first, where);
    if (out.count(name)) throw ConfigError(key_path(where, name) + ": given twice");
    out[name] = parse(axis.second, key_path(where, name));
  }
  return out;
}
std::map<std::string, double> axis_mm_map(const YAML::Node& node, const std::string& where) {
  return axis_map<double>(node, where, "positions in mm",
                          [](const YAML::Node& n, const std::string& w) { return config_number(n, w); });
}

TimelineStep parse_step(const YAML::Node& node, const std::string& where) {
  const ConfigMap m(node, where, step_keys);
  TimelineStep step;
  if (!m.has("when")) throw ConfigError(where + ": 'when' is missing");
  step.when = parse_condition(m["when"], m.path("when"));
  if (!m.has("set") || !m["set"].IsMap()) throw ConfigError(where + ": 'set' must map control unit fields to values");
  const ConfigMap fields(m["set"], m.path("set"), control_keys(), "HLI field");  // refuses unknown fields
  for (const auto& item : m["set"]) {
    const std::string key = item.first.Scalar();
    step.set.push_back({key, hli_field_value<HliControl>(key, item.second, where)});
  }
  return step;
}

Expectation parse_expectation(const YAML::Node& node, const std::string& where) {
  const ConfigMap m(node, where, expectation_keys());
  Expectation e;
  if (m.has("since")) e.since = parse_condition(m["since"], m.path("since"));
  if (m.has("never") || m.has("always")) {
    if (m.has("never") && m.has("always")) throw ConfigError(where + ": give 'never' or 'always', not both");
    for (const auto& item : node) {
      const std::string key = item.first.Scalar();
      if (std::find(watch_keys.begin(), watch_keys.end(), key) == watch_keys.end())
        throw ConfigError(m.path(key) + ": a never/always expectation takes only never or always, since and until");
    }
    const char* key = m.has("never") ? "never" : "always";
    e.kind = m.has("never") ? Expectation::Kind::never : Expectation::Kind::always;
    e.watched = parse_condition(m[key], m.path(key));
    if (m.has("until")) e.until = parse_condition(m["until"], m.path("until"));
    return e;
  }
  if (m.has("until")) throw ConfigError(m.path("until") + ": ends the window of never: or always: (give 'when' here)");
  if (!m.has("when")) throw ConfigError(where + ": 'when' is missing (or give 'never' or 'always')");
  e.when = parse_condition(m["when"], m.path("when"));
  m.get("tolerance_mm", e.tolerance_mm, non_negative);  // before the positions it widens
  for (const auto& item : node) {
    const std::string key = item.first.Scalar();
    if (key == "when" || key == "since" || key == "tolerance_mm") continue;
    if (key == "time_s_at_least") e.time_s_at_least = m.number(key, non_negative);
    else if (key == "time_s_at_most") e.time_s_at_most = m.number(key, non_negative);
    else if (key == "path_velocity_max_at_least_mm_s")
      e.path_velocity_max_at_least_mm_s = m.number(key, non_negative);
    else if (key == "path_velocity_max_at_most_mm_s")
      e.path_velocity_max_at_most_mm_s = m.number(key, non_negative);
    else if (const ExtremeKey* extreme = find_extreme_key(key)) {
      for (const auto& [axis, mm] : axis_mm_map(item.second, m.path(key)))
        e.extremes.push_back({key, axis, extreme->highest, extreme->bound, mm});
    } else {
      parse_condition_key(e.checks, key, item.second, m.path(key), PlainNumber::exactly, e.tolerance_mm);
    }
  }
  // A window no time fits is a mistake in the file, not a check.
  if (e.time_s_at_least && e.time_s_at_most && *e.time_s_at_least > *e.time_s_at_most)
    throw ConfigError(where + ": time_s_at_least is more than time_s_at_most");
  return e;
}

EventExpectation parse_event_expectation(const YAML::Node& node, const std::string& where) {
  const ConfigMap m(node, where, event_keys);
  EventExpectation e;
  if (!m.has("id") && !m.has("parameter")) throw ConfigError(where + ": give 'id' and/or 'parameter'");
  if (m.has("id")) e.id = static_cast<int32_t>(m.whole("id", 0, int32_max));
  m.get("parameter", e.parameter);
  std::string severity;
  if (m.get("severity", severity)) {
    if (severity == "warning") e.severity = Severity::warning;
    else if (severity == "error") e.severity = Severity::error;
    else if (severity == "info") e.severity = Severity::info;
    else throw ConfigError(m.path("severity") + ": must be info, warning or error, not " + severity);
  }
  m.get("nc_line", e.nc_line, 0);
  m.get("count_min", e.count_min, 0);
  m.get("absent", e.absent);
  // absent ignores count_min: both given is a contradiction, not a check.
  if (e.absent && m.has("count_min")) throw ConfigError(where + ": give 'count_min' or 'absent: true', not both");
  return e;
}

ViolationExpectation parse_violation_expectation(const YAML::Node& node, const std::string& where) {
  const ConfigMap m(node, where, violation_keys);
  if (!m.has("axis") || !m.has("quantity")) throw ConfigError(where + ": give 'axis' and 'quantity'");
  ViolationExpectation v{m.text("axis"), m.text("quantity")};
  // An empty part is a part of every quantity: it would excuse any violation of the axis.
  if (v.quantity.empty()) throw ConfigError(m.path("quantity") + ": must not be empty");
  return v;
}

template <typename T, typename Parse>
std::vector<T> parse_list(const YAML::Node& node, const std::string& name, Parse parse) {
  std::vector<T> items;
  if (!node) return items;
  if (!node.IsSequence()) throw ConfigError(name + ": must be a list");
  for (size_t i = 0; i < node.size(); ++i) items.push_back(parse(node[i], index_path(name, i)));
  return items;
}

}  // namespace

std::string nc_text_problem(const std::string& text) {
  size_t line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\n') ++line;
    // Bytes >= 0x80 pass: comments in UTF-8 or Latin-1 are text.
    if ((byte < 0x20 && byte != '\n' && byte != '\r' && byte != '\t') || byte == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02X", byte);
      return "line " + std::to_string(line) + ": byte " + code + (byte == 0 ? " (NUL)" : "") +
             " is not text: an NC program is a text file";
    }
  }
  return "";
}

namespace {

// `machine`: the machine already read from its own file, or nullptr.
Scenario read_scenario(const YAML::Node& root, const MachineConfig* machine) {
  const ConfigMap m(root, "", scenario_keys);
  for (const char* key : {"variants", "compare"})  // scenario_set.hpp takes them off before this
    if (m.has(key)) throw ConfigError(std::string(key) + ": a scenario with variants is read by load_scenario_set");
  Scenario s;
  s.name = "scenario";
  m.get("name", s.name);
  m.get("description", s.description);
  if (m.has("requirements")) {
    const YAML::Node requirements = m["requirements"];
    if (!requirements.IsSequence()) throw ConfigError("requirements: must be a list of SPEC IDs");
    for (size_t i = 0; i < requirements.size(); ++i)
      s.requirements.push_back(config_text(requirements[i], index_path("requirements", i)));
  }
  if (!m.has("machine") || !m["machine"].IsMap())
    throw ConfigError("machine: must be a mapping (in a scenario file also a file name)");
  s.machine = machine ? *machine : parse_machine_config(m["machine"]);
  if (!m.has("nc_program")) throw ConfigError("'nc_program' or 'nc_file' is missing");
  s.nc_program = m.text("nc_program");
  if (const std::string problem = nc_text_problem(s.nc_program); !problem.empty())
    throw ConfigError("nc_program: " + problem);
  if (m.has("run")) {
    const ConfigMap run(m["run"], "run", run_keys);
    run.get("max_time_s", s.max_time_s, Bounds{0, max_run_time_s, true});
    run.get("settle_time_s", s.settle_time_s, Bounds{0, max_run_time_s});
    run.get("allow_errors", s.allow_errors);
    run.get("realtime", s.realtime);
  }
  if (m.has("plc")) {
    const ConfigMap plc(m["plc"], "plc", plc_keys);
    s.timeline = parse_list<TimelineStep>(plc["timeline"], "plc.timeline", parse_step);
    plc.get("m_function_ack_cycles", s.m_function_ack_cycles, 0);
  }
  s.faults = parse_fault_plan(m["faults"], m["fault_seed"], s.machine);  // RIG-8
  s.expectations = parse_list<Expectation>(m["expect"], "expect", parse_expectation);
  s.expected_events = parse_list<EventExpectation>(m["expect_events"], "expect_events", parse_event_expectation);
  s.expected_violations = parse_list<ViolationExpectation>(m["expect_violations"], "expect_violations",
                                                           parse_violation_expectation);
  for (const auto& v : s.expected_violations)
    if (s.machine.axis_index(v.axis) < 0)
      throw ConfigError("expect_violations: axis '" + v.axis + "' is not on the machine");
  auto on_machine = [&](const std::string& axis, const std::string& where) {
    if (s.machine.axis_index(axis) < 0) throw ConfigError(where + ": axis '" + axis + "' is not on the machine");
  };
  auto axes_on_machine = [&](const Condition& c, const std::string& where) {
    for (const auto& [key, axis] : c.axes()) on_machine(axis, key_path(where, key));
  };
  for (size_t i = 0; i < s.timeline.size(); ++i) axes_on_machine(s.timeline[i].when, index_path("plc.timeline", i) + ".when");
  for (size_t i = 0; i < s.expectations.size(); ++i) {
    const Expectation& e = s.expectations[i];
    const std::string where = index_path("expect", i);
    for (const ExtremeCheck& x : e.extremes) on_machine(x.axis, where + "." + x.key);
    axes_on_machine(e.when, where + ".when");
    if (e.since) axes_on_machine(*e.since, where + ".since");
    if (e.until) axes_on_machine(*e.until, where + ".until");
    axes_on_machine(e.watched, where + (e.kind == Expectation::Kind::never ? ".never" : ".always"));
    axes_on_machine(e.checks, where);
  }
  s.resolved = root;
  return s;
}

}  // namespace

Scenario parse_scenario(const YAML::Node& root) {
  try {
    return read_scenario(root, nullptr);
  } catch (const YAML::Exception& e) {  // what the checks above do not foresee
    throw ConfigError(std::string("scenario: ") + e.what());
  }
}

YAML::Node load_scenario_yaml(const std::string& path) {
  try {
    return load_yaml_file(path, "scenario");
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

Scenario load_scenario_file(const std::string& path) {
  try {
    const YAML::Node root = load_yaml_file(path, "scenario");
    Scenario scenario = load_scenario_node(root, path);
    locate_nc_program(scenario, root, path);
    return scenario;
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

namespace {

Scenario read_scenario_named(const YAML::Node& root, const MachineConfig* machine, const std::string& path) {
  try {
    return read_scenario(root, machine);
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

}  // namespace

Scenario load_scenario_node(YAML::Node root, const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  // A file the scenario names: its errors name that file, then the scenario.
  auto named_by_scenario = [&](const std::string& key, auto read) {
    try {
      return read();
    } catch (const ConfigError& e) {
      throw ConfigError(std::string(e.what()) + " (the " + key + " of " + path + ")");
    }
  };
  try {
    if (!root.IsMap()) throw ConfigError(path + ": expected a mapping at the top");
    std::optional<MachineConfig> machine;
    if (root["machine"] && root["machine"].IsScalar()) {
      const fs::path machine_file = dir / root["machine"].Scalar();
      machine = named_by_scenario("machine", [&] {
        root["machine"] = load_yaml_file(machine_file, "machine file");
        try {
          return parse_machine_config(root["machine"]);  // its keys' paths begin with "machine"
        } catch (const ConfigError& e) {
          throw ConfigError(machine_file.string() + ": " + e.what());
        }
      });
    }
    if (root["nc_file"]) {
      if (root["nc_program"]) throw ConfigError(path + ": give either 'nc_program' or 'nc_file', not both");
      const fs::path nc_file = dir / config_text(root["nc_file"], path + ": nc_file");
      root["nc_program"] = named_by_scenario("nc_file", [&] {
        std::string program = read_text_file(nc_file, "NC program");
        if (const std::string problem = nc_text_problem(program); !problem.empty())
          throw ConfigError(nc_file.string() + ": " + problem);
        return program;
      });
      root.remove("nc_file");
      Scenario s = read_scenario_named(root, machine ? &*machine : nullptr, path);
      s.nc_source = nc_file.string();
      return s;
    }
    return read_scenario_named(root, machine ? &*machine : nullptr, path);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

void locate_nc_program(Scenario& scenario, const YAML::Node& root, const std::string& path) {
  if (!root.IsMap() || root["nc_file"] || !root["nc_program"]) return;
  const YAML::Mark mark = root["nc_program"].Mark();
  if (mark.is_null()) return;
  std::ifstream in(path);
  std::string line;
  for (int k = 0; k <= mark.line && std::getline(in, line); ++k) {
  }
  if (!in) return;
  // A block scalar (| or >) begins on the line after its indicator.
  const bool block = static_cast<size_t>(mark.column) < line.size() &&
                     (line[static_cast<size_t>(mark.column)] == '|' || line[static_cast<size_t>(mark.column)] == '>');
  scenario.nc_source = path;
  scenario.nc_source_line = mark.line + (block ? 2 : 1);
}

std::string nc_line_place(const Scenario& scenario, int64_t nc_line) {
  const std::string line = " line " + std::to_string(nc_line);
  if (scenario.nc_source.empty()) return "NC program" + line;
  if (scenario.nc_source_line <= 0) return scenario.nc_source + line;
  return "nc_program" + line + " (scenario file line " + std::to_string(scenario.nc_source_line + nc_line - 1) + ")";
}

std::string to_yaml(const Scenario& scenario) {
  YAML::Emitter out;
  out << scenario.resolved;
  return out.c_str();
}

const std::vector<std::string>& file_keys::scenario() { return scenario_keys; }
const std::vector<std::string>& file_keys::run() { return run_keys; }
const std::vector<std::string>& file_keys::plc() { return plc_keys; }
const std::vector<std::string>& file_keys::timeline_step() { return step_keys; }
const std::vector<std::string>& file_keys::control() { return control_keys(); }
const std::vector<std::string>& file_keys::expectation() { return expectation_keys(); }
const std::vector<std::string>& file_keys::condition() { return condition_keys(); }
const std::vector<std::string>& file_keys::event_expectation() { return event_keys; }
const std::vector<std::string>& file_keys::violation_expectation() { return violation_keys; }

}  // namespace hil
