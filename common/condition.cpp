#include "condition.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "config_error.hpp"
#include "hli_names.hpp"

namespace hil {
namespace {

constexpr int64_t int32_max = std::numeric_limits<int32_t>::max();
constexpr int64_t int64_max = std::numeric_limits<int64_t>::max();

ChannelState channel_state_of(const YAML::Node& node, const std::string& where) {
  ChannelState state{};
  if (!parse_channel_state(config_text(node, where), state))
    throw ConfigError(where + ": channel_state must be READY, ACTIVE, PROGRAM_END or ERROR");
  return state;
}

std::vector<std::string> stop_condition_name_list() {
  std::vector<std::string> names;
  for (const StopConditionName& n : stop_condition_names()) names.push_back(n.name);
  return names;
}

// [FEEDHOLD, HLI_SC_M00_OR_M01] -> their bits; an unknown name is refused
// with the closest known one.
int32_t stop_condition_bits(const YAML::Node& node, const std::string& where) {
  if (!node.IsSequence()) throw ConfigError(where + ": must be a list of stop condition names, e.g. [FEEDHOLD]");
  int32_t bits = 0;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::string item = index_path(where, i);
    const std::string name = config_text(node[i], item);
    const int32_t bit = find_stop_condition(name);
    if (bit == 0) {
      std::string upper = name;
      std::transform(upper.begin(), upper.end(), upper.begin(),
                     [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
      if (upper.rfind("HLI_SC_", 0) == 0) upper.erase(0, 7);
      const std::string near = closest_key(upper, stop_condition_name_list());
      throw ConfigError(item + ": unknown stop condition '" + name + "'" +
                        (near.empty() ? "" : ", did you mean " + near + "?"));
    }
    if (bits & bit) throw ConfigError(item + ": " + name + " given twice");
    bits |= bit;
  }
  return bits;
}

// A number, `[NAMES]` (exactly these bits) or `{contains: [NAMES]}`.
StopConditionMatch stop_condition_match(const YAML::Node& node, const std::string& where) {
  StopConditionMatch m;
  if (node.IsScalar()) {
    m.bits = static_cast<int32_t>(config_whole(node, where, std::numeric_limits<int32_t>::min(), int32_max));
  } else if (node.IsSequence()) {
    m.bits = stop_condition_bits(node, where);
  } else if (node.IsMap()) {
    const ConfigMap map(node, where, {"contains"});
    if (!map.has("contains")) throw ConfigError(where + ": 'contains' is missing");
    m.bits = stop_condition_bits(map["contains"], map.path("contains"));
    // No bits to contain holds always: a mistake, not a check.
    if (m.bits == 0) throw ConfigError(map.path("contains") + ": name at least one stop condition");
    m.contains = true;
  } else {
    throw ConfigError(where + ": must be a number, a list of stop condition names or {contains: [..]}");
  }
  return m;
}

// A named HLI state field's value: true / false or a whole number its type
// holds, or a range of whole numbers within its type.
ValueRange hli_field_range(const std::string& key, const YAML::Node& node, const std::string& where) {
  const HliField<HliState>* field = find_hli_field<HliState>(key);
  if (node.IsMap()) return parse_whole_range(node, where, field->min, field->max);
  // The field's name has dots of its own: the message quotes it after its mapping's path.
  const bool ends_with_key = where.size() > key.size() && where.compare(where.size() - key.size(), key.size(), key) == 0;
  const std::string named = (ends_with_key ? where.substr(0, where.size() - key.size() - 1) : where) + ": '" + key + "'";
  bool flag = false;
  int64_t value = 0;
  if (!node.IsScalar()) throw ConfigError(named + " takes true, false, a whole number or a range {min: .., max: ..}");
  if (YAML::convert<bool>::decode(node, flag)) value = flag ? 1 : 0;
  else if (!YAML::convert<int64_t>::decode(node, value))
    throw ConfigError(named + " takes true, false or a whole number, not '" + node.Scalar() + "'");
  if (!field->holds(value)) throw ConfigError(named + " is " + field->type_text() + ", not " + node.Scalar());
  return ValueRange::exactly(static_cast<double>(value));
}

// A number or a range; `plain` says what a number means.
void number_or_range(const YAML::Node& node, const std::string& where) {
  if (!node.IsScalar() && !node.IsMap()) throw ConfigError(where + ": must be a number or a range {min: .., max: ..}");
}
ValueRange number_range(const YAML::Node& node, const std::string& where, ValueRange (*plain)(double),
                        Bounds bounds = any_finite) {
  number_or_range(node, where);
  if (node.IsMap()) return parse_value_range(node, where, bounds);
  return plain(config_number(node, where, bounds));
}
ValueRange whole_range(const YAML::Node& node, const std::string& where, ValueRange (*plain)(double), int64_t lo,
                       int64_t hi) {
  number_or_range(node, where);
  if (node.IsMap()) return parse_whole_range(node, where, lo, hi);
  return plain(static_cast<double>(config_whole(node, where, lo, hi)));
}

double mm_of(double hli_units) { return hli_units / hli_units_per_mm; }

std::optional<double> axis_position(const HliState& s, const std::string& axis) {
  for (size_t i = 0; i < s.axis_name.size() && i < s.axis_position_r.size(); ++i)
    if (s.axis_name[i] == axis) return mm_of(static_cast<double>(s.axis_position_r[i]));
  return std::nullopt;
}

const char* bool_text(bool value) { return value ? "true" : "false"; }

// Walks a condition's predicates: each with its name, the value read in `s`
// (as text) and whether it holds. Stops early when `visit` returns false.
template <typename Visit>
void each_predicate(const Condition& c, const HliState& s, double cycle_time_s, Visit visit) {
  auto range = [&](const std::string& name, const std::optional<ValueRange>& r, double value, double slack = 0) {
    if (!r) return true;
    const ValueRange widened{r->min ? std::optional<double>(*r->min - slack) : std::nullopt,
                             r->max ? std::optional<double>(*r->max + slack) : std::nullopt};
    return visit(name, number_text(value), r->describe(name), widened.contains(value), r->min && r->max && *r->min == *r->max);
  };
  auto flag = [&](const std::string& name, const std::optional<bool>& want, bool value) {
    if (!want) return true;
    return visit(name, std::string(bool_text(value)), name + "=" + bool_text(*want), value == *want, true);
  };
  const double time_s = static_cast<double>(s.cycle) * cycle_time_s;
  // time_s: round-off of cycle * cycle time must not decide the cycle.
  if (!range("cycle", c.cycle, static_cast<double>(s.cycle))) return;
  if (!range("time_s", c.time_s, time_s, 1e-12)) return;
  if (!range("block_nr_r", c.block_nr_r, static_cast<double>(s.block_nr_r))) return;
  if (!range("block_count_r", c.block_count_r, static_cast<double>(s.block_count_r))) return;
  if (!range("dist_prog_start_mm", c.dist_prog_start_mm, mm_of(s.dist_prog_start))) return;
  if (!range("path_velocity_mm_s", c.path_velocity_mm_s, s.path_velocity)) return;
  if (c.path_standing &&
      !visit("path_standing", std::string(bool_text(s.path_velocity == 0)),
             std::string("path_standing=") + bool_text(*c.path_standing), (s.path_velocity == 0) == *c.path_standing,
             true))
    return;
  if (c.channel_state && !visit("channel_state", std::string(to_string(s.channel_state)),
                                std::string("channel_state=") + to_string(*c.channel_state),
                                s.channel_state == *c.channel_state, true))
    return;
  if (!flag("delete_distance_to_go_active_r", c.delete_distance_to_go_active_r, s.delete_distance_to_go_active_r))
    return;
  if (c.m_function_nr_r &&
      !visit("m_function_nr_r",
             s.m_function_request_r ? std::to_string(s.m_function_nr_r) : std::string("none waiting"),
             "m_function_nr_r=" + std::to_string(*c.m_function_nr_r),
             s.m_function_request_r && s.m_function_nr_r == *c.m_function_nr_r, true))
    return;
  if (c.stop_conditions_r &&
      !visit("stop_conditions_r", stop_conditions_text(s.stop_conditions_r), c.stop_conditions_r->describe(),
             c.stop_conditions_r->matches(s.stop_conditions_r), !c.stop_conditions_r->contains))
    return;
  for (const auto& [name, r] : c.fields) {
    const std::optional<int64_t> value = read_hli_field(s, name);
    if (!range(name, r, static_cast<double>(value.value_or(0)))) return;
  }
  for (const auto& [axis, r] : c.axis_position_mm) {
    const std::optional<double> mm = axis_position(s, axis);
    const std::string name = "axis_position_mm." + axis;
    if (!mm) {
      if (!visit(name, std::string("missing"), r.describe(name), false, false)) return;
    } else if (!range(name, r, *mm)) {
      return;
    }
  }
  for (const auto& [name, axes] : c.axis_flags) {
    const HliAxisFlag* f = find_hli_axis_flag(name);
    for (const auto& [axis, want] : axes) {
      const std::optional<bool> value = f ? f->read(s, axis) : std::nullopt;
      // value_or, not *value: g++ 12 -O2 takes *value for a read of an unset bool.
      const bool seen = value.has_value(), flag = value.value_or(false);
      const std::string full = name + "." + axis;
      if (!visit(full, seen ? std::string(bool_text(flag)) : std::string("missing"), full + "=" + bool_text(want),
                 seen && flag == want, true))
        return;
    }
  }
}

const std::vector<std::string>& own_condition_keys() {
  static const std::vector<std::string> keys = {
      "cycle", "time_s", "block_nr_r", "block_count_r", "dist_prog_start_mm", "path_velocity_mm_s", "path_standing",
      "channel_state", "delete_distance_to_go_active_r", "m_function_nr_r", "stop_conditions_r", "axis_position_mm"};
  return keys;
}

}  // namespace

std::string StopConditionMatch::describe() const {
  return contains ? "stop_conditions_r contains " + stop_conditions_text(bits)
                  : "stop_conditions_r=" + stop_conditions_text(bits);
}

const std::vector<std::string>& condition_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> keys = own_condition_keys();
    for (const HliField<HliState>& field : hli_fields<HliState>())
      if (std::find(keys.begin(), keys.end(), field.name) == keys.end()) keys.push_back(field.name);
    for (const HliAxisFlag& flag : hli_axis_flags()) keys.push_back(flag.name);
    return keys;
  }();
  return keys;
}

bool parse_condition_key(Condition& c, const std::string& key, const YAML::Node& value, const std::string& where,
                         PlainNumber plain, double tolerance_mm) {
  const bool trigger = plain == PlainNumber::trigger;
  // A trigger waits for a value to be reached; a check wants the value.
  ValueRange (*reached)(double) = trigger ? &ValueRange::at_least : &ValueRange::exactly;
  if (key == "cycle") c.cycle = whole_range(value, where, reached, 0, int64_max);
  else if (key == "time_s") c.time_s = number_range(value, where, reached, non_negative);
  else if (key == "block_nr_r") c.block_nr_r = whole_range(value, where, &ValueRange::exactly, 0, int64_max);
  else if (key == "block_count_r") c.block_count_r = whole_range(value, where, &ValueRange::exactly, 0, int64_max);
  else if (key == "dist_prog_start_mm") {
    if (trigger || value.IsMap()) c.dist_prog_start_mm = number_range(value, where, reached);
    else c.dist_prog_start_mm = ValueRange::around(config_number(value, where), tolerance_mm);
  } else if (key == "path_velocity_mm_s") c.path_velocity_mm_s = number_range(value, where, reached);
  else if (key == "path_standing") c.path_standing = config_bool(value, where);
  else if (key == "channel_state") c.channel_state = channel_state_of(value, where);
  else if (key == "delete_distance_to_go_active_r") c.delete_distance_to_go_active_r = config_bool(value, where);
  // A trigger waits for this M function; a check reads the field as it is.
  else if (key == "m_function_nr_r" && trigger)
    c.m_function_nr_r = static_cast<int32_t>(config_whole(value, where, 0, int32_max));
  else if (key == "stop_conditions_r") c.stop_conditions_r = stop_condition_match(value, where);
  else if (key == "axis_position_mm") {
    if (!value.IsMap()) throw ConfigError(where + ": must map axis names to positions in mm");
    for (const auto& axis : value) {
      const std::string name = config_text(axis.first, where);
      const std::string path = key_path(where, name);
      if (c.axis_position_mm.count(name)) throw ConfigError(path + ": given twice");
      if (axis.second.IsMap()) c.axis_position_mm[name] = parse_value_range(axis.second, path);
      // A position met exactly in some cycle is luck in a trigger: it takes a range.
      else if (trigger) throw ConfigError(path + ": give a range {min: .., max: ..} (a trigger on an exact position rarely fires)");
      else c.axis_position_mm[name] = ValueRange::around(config_number(axis.second, path), tolerance_mm);
    }
  } else if (find_hli_axis_flag(key)) {
    if (!value.IsMap()) throw ConfigError(where + ": must map axis names to true or false");
    auto& axes = c.axis_flags[key];
    for (const auto& axis : value) {
      const std::string name = config_text(axis.first, where);
      if (axes.count(name)) throw ConfigError(key_path(where, name) + ": given twice");
      axes[name] = config_bool(axis.second, key_path(where, name));
    }
  } else if (find_hli_field<HliState>(key)) {
    c.fields[key] = hli_field_range(key, value, where);
  } else {
    return false;
  }
  return true;
}

Condition parse_condition(const YAML::Node& node, const std::string& where) {
  Condition c;
  if (node.IsScalar() && node.Scalar() == "program_end") {
    c.channel_state = ChannelState::program_end;
    return c;
  }
  if (!node.IsMap()) throw ConfigError(where + ": must be a mapping or 'program_end'");
  const ConfigMap m(node, where, condition_keys());
  for (const auto& item : node) {
    const std::string key = item.first.Scalar();
    parse_condition_key(c, key, item.second, m.path(key), PlainNumber::trigger);
  }
  return c;
}

bool Condition::empty() const {
  return !cycle && !time_s && !block_nr_r && !block_count_r && !dist_prog_start_mm && !path_velocity_mm_s &&
         !path_standing && !channel_state && !delete_distance_to_go_active_r && !m_function_nr_r &&
         !stop_conditions_r && fields.empty() && axis_position_mm.empty() && axis_flags.empty();
}

bool Condition::check(const HliState& s, double cycle_time_s, std::string* broken) const {
  bool all = true;
  each_predicate(*this, s, cycle_time_s,
                 [&](const std::string& name, const std::string& value, const std::string& wanted, bool ok,
                     bool exact) {
                   if (ok) return true;
                   all = false;
                   if (!broken) return false;  // holds() needs no more
                   // "block_nr_r 3 != 40"; a range: "X 100.0021, expected X<=100".
                   if (exact) *broken += " " + name + " " + value + " != " + wanted.substr(wanted.find('=') + 1) + ";";
                   else *broken += " " + name + " " + value + ", expected " + wanted + ";";
                   return true;
                 });
  return all;
}

std::string Condition::seen(const HliState& s, double cycle_time_s) const {
  std::string out;
  each_predicate(*this, s, cycle_time_s,
                 [&](const std::string& name, const std::string& value, const std::string&, bool, bool) {
                   out += (out.empty() ? "" : " ") + name + "=" + value;
                   return true;
                 });
  return out;
}

std::string Condition::describe() const {
  std::ostringstream out;
  const char* sep = "";
  auto range = [&](const char* name, const std::optional<ValueRange>& r) {
    if (r) out << sep << r->describe(name), sep = " ";
  };
  range("cycle", cycle);
  range("time_s", time_s);
  range("block_nr_r", block_nr_r);
  range("block_count_r", block_count_r);
  range("dist_prog_start_mm", dist_prog_start_mm);
  range("path_velocity_mm_s", path_velocity_mm_s);
  if (path_standing) out << sep << "path_standing=" << bool_text(*path_standing), sep = " ";
  if (channel_state) out << sep << "channel_state=" << to_string(*channel_state), sep = " ";
  if (delete_distance_to_go_active_r)
    out << sep << "delete_distance_to_go_active_r=" << bool_text(*delete_distance_to_go_active_r), sep = " ";
  if (m_function_nr_r) out << sep << "m_function_nr_r=" << *m_function_nr_r, sep = " ";
  if (stop_conditions_r) out << sep << stop_conditions_r->describe(), sep = " ";
  for (const auto& [name, r] : fields) out << sep << r.describe(name), sep = " ";
  for (const auto& [axis, r] : axis_position_mm) out << sep << r.describe("axis_position_mm." + axis), sep = " ";
  for (const auto& [name, axes] : axis_flags)
    for (const auto& [axis, value] : axes) out << sep << name << "." << axis << "=" << bool_text(value), sep = " ";
  return out.str();
}

std::vector<std::pair<std::string, std::string>> Condition::axes() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& entry : axis_position_mm) out.emplace_back("axis_position_mm", entry.first);
  for (const auto& [name, axes] : axis_flags)
    for (const auto& entry : axes) out.emplace_back(name, entry.first);
  return out;
}

}  // namespace hil
