#include "machine_config.hpp"
#include "file_keys.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <limits>
#include <map>

#include "config_error.hpp"
#include "function_lists.hpp"
#include "hli.hpp"
#include "machine_ranges.hpp"

namespace hil {
namespace {

// The keys each mapping of a machine file may have (config/xyz_machine.yaml
// documents them); any other is refused (ConfigMap).
const std::vector<std::string> machine_keys = {"name", "cycle_time_us", "override_max_percent", "fb_storage_size",
                                               "m_pre_outp", "path_preparation_function", "interpolator_function",
                                               "enable_time_based_lift", "lift_min_dist", "plc_watchdog_cycles",
                                               "max_radius_diff_circle", "max_proz_radius_diff_circle",
                                               "zero_offsets", "axes"};
const std::vector<std::string> zero_offset_names = {"G54", "G55", "G56", "G57", "G58", "G59"};
const std::vector<std::string> axis_keys = {
    "name", "v_max", "v_rapid", "a_max", "j_max", "kv", "velocity_lag_s", "velocity_loop_order",
    "velocity_damping", "velocity_feedforward", "drive_acceleration_limit", "friction_coulomb", "friction_viscous",
    "dyn_monitoring_a_warn", "dyn_monitoring_a_err", "dyn_monitoring_v_warn", "dyn_monitoring_v_err",
    "slep_max", "slep_min", "following_error_monitoring", "swe_neg", "swe_pos", "swe_toleranz",
    "modulo_lower", "modulo_upper", "reference_position", "watchdog_cycles"};

constexpr int64_t int32_max = std::numeric_limits<int32_t>::max();
constexpr int64_t int32_min = std::numeric_limits<int32_t>::min();

// A range in the axis' units: deg where a linear axis has mm (docs/UNITS.md).
Bounds in_units(Bounds bounds, bool rotary) {
  static const std::map<std::string, const char*> deg = {
      {"mm/s", "deg/s"}, {"mm/s^2", "deg/s^2"}, {"mm/s^3", "deg/s^3"}, {"mm", "deg"}};
  if (const auto it = deg.find(bounds.unit); rotary && it != deg.end()) bounds.unit = it->second;
  return bounds;
}

AxisConfig parse_axis(const YAML::Node& node, const std::string& where) {
  const ConfigMap m(node, where, axis_keys);
  AxisConfig axis;
  axis.name = m.text("name");
  if (axis.name.size() != 1 || axis.name.find_first_not_of("ABCUVWXYZ") != std::string::npos)
    throw ConfigError(m.path("name") + ": must be one of the letters A B C U V W X Y Z, not '" + axis.name + "'");
  const std::string at = where + " (axis " + axis.name + ")";
  namespace range = machine_ranges;
  const bool rotary = axis.rotary();
  const auto units = [rotary](Bounds bounds) { return in_units(bounds, rotary); };
  axis.v_max = m.number("v_max", units(range::velocity));
  axis.v_rapid = axis.v_max;
  if (m.get("v_rapid", axis.v_rapid, units(range::velocity)) && axis.v_rapid > axis.v_max)
    throw ConfigError(at + ": 'v_rapid' exceeds 'v_max'");
  axis.a_max = m.number("a_max", units(range::acceleration));
  m.get("watchdog_cycles", axis.watchdog_cycles, range::watchdog_cycles.min, range::watchdog_cycles.max);
  axis.j_max = m.number("j_max", units(range::jerk));
  axis.kv = m.number("kv", range::position_gain);
  axis.velocity_lag_s = m.number("velocity_lag_s", range::velocity_lag);
  m.get("velocity_loop_order", axis.velocity_loop_order, 1, 2);
  m.get("velocity_damping", axis.velocity_damping, range::damping);
  m.get("velocity_feedforward", axis.velocity_feedforward, range::feedforward);
  m.get("reference_position", axis.reference_position, units(range::position));
  m.get("drive_acceleration_limit", axis.drive_acceleration_limit, units(range::acceleration));
  m.get("friction_coulomb", axis.friction_coulomb, units(range::coulomb_friction));
  m.get("friction_viscous", axis.friction_viscous, range::viscous_friction);
  // P-AXIS-00439 .. 00442 in 1/1000 of v_max / a_max. Below 1000 the
  // monitoring limit would be below the limit itself, so planned motion
  // would trip it: almost surely the value was meant as a percentage excess.
  // Refuse rather than guess (docs/UNITS.md). Above 10000 it monitors nothing.
  const auto per_mille = [&](const char* key, const char* parameter, const char* limit, int32_t& value) {
    if (!m.has(key)) return;
    if (m.whole(key, int32_min, int32_max) < range::monitoring_per_mille.min)
      throw ConfigError(at + ": " + parameter + " " + key + " must be >= 1000 (limit = " + limit + " * value / 1000)");
    m.get(key, value, range::monitoring_per_mille.min, range::monitoring_per_mille.max);
  };
  per_mille("dyn_monitoring_a_warn", "P-AXIS-00441", "a_max", axis.dyn_monitoring_a_warn);
  per_mille("dyn_monitoring_a_err", "P-AXIS-00442", "a_max", axis.dyn_monitoring_a_err);
  per_mille("dyn_monitoring_v_warn", "P-AXIS-00439", "v_max", axis.dyn_monitoring_v_warn);
  per_mille("dyn_monitoring_v_err", "P-AXIS-00440", "v_max", axis.dyn_monitoring_v_err);
  if (axis.dyn_monitoring_a_err < axis.dyn_monitoring_a_warn)
    throw ConfigError(at + ": P-AXIS-00442 dyn_monitoring_a_err must be >= P-AXIS-00441 dyn_monitoring_a_warn");
  if (axis.dyn_monitoring_v_err < axis.dyn_monitoring_v_warn)
    throw ConfigError(at + ": P-AXIS-00440 dyn_monitoring_v_err must be >= P-AXIS-00439 dyn_monitoring_v_warn");

  if (m.get("slep_max", axis.slep_max, units(range::following_error))) {
    axis.slep_min = axis.slep_max;
    m.get("slep_min", axis.slep_min, units(range::following_error));
    axis.following_error_monitoring = 4;
  } else if (m.has("slep_min")) {  // would be ignored: monitoring needs slep_max
    throw ConfigError(at + ": P-AXIS-00169 slep_min needs P-AXIS-00168 slep_max");
  }
  m.get("following_error_monitoring", axis.following_error_monitoring, 0, int32_max);
  if (axis.following_error_monitoring != 0 && axis.following_error_monitoring != 4)
    throw ConfigError(at + ": P-AXIS-00172 following_error_monitoring " +
                      std::to_string(axis.following_error_monitoring) +
                      " is not supported (0 = off, 4 = velocity-independent)");
  if (axis.following_error_monitoring == 4 && !(axis.slep_max > 0))
    throw ConfigError(at + ": P-AXIS-00172 following_error_monitoring 4 needs P-AXIS-00168 slep_max");

  if (m.has("swe_neg") || m.has("swe_pos")) {
    if (!m.has("swe_neg") || !m.has("swe_pos"))
      throw ConfigError(at + ": software limit switches need both P-AXIS-00177 swe_neg and P-AXIS-00178 swe_pos");
    axis.software_limits = true;
    axis.swe_neg = m.number("swe_neg", units(range::position));
    axis.swe_pos = m.number("swe_pos", units(range::position));
    if (!(axis.swe_neg < axis.swe_pos))
      throw ConfigError(at + ": P-AXIS-00177 swe_neg must be below P-AXIS-00178 swe_pos");
    m.get("swe_toleranz", axis.swe_toleranz, units(range::limit_switch_tolerance));
  } else if (m.has("swe_toleranz")) {  // would be ignored: nothing to widen
    throw ConfigError(at + ": P-AXIS-00179 swe_toleranz needs P-AXIS-00177 swe_neg and P-AXIS-00178 swe_pos");
  }

  if (m.has("modulo_lower") || m.has("modulo_upper")) {  // KRN-7
    if (!m.has("modulo_lower") || !m.has("modulo_upper"))
      throw ConfigError(at + ": a modulo axis needs both modulo_lower and modulo_upper");
    if (!axis.rotary()) throw ConfigError(at + ": only the rotary axes A, B, C can be modulo axes");
    if (axis.software_limits)
      throw ConfigError(at + ": a modulo axis has no software limit switches (P-AXIS-00177 / 00178)");
    axis.modulo = true;
    axis.modulo_lower = m.number("modulo_lower", units(range::position));
    axis.modulo_upper = m.number("modulo_upper", units(range::position));
    if (!(axis.modulo_lower < axis.modulo_upper))
      throw ConfigError(at + ": modulo_lower must be below modulo_upper");
    if (axis.modulo_range() < range::min_modulo_range)
      throw ConfigError(at + ": modulo_upper - modulo_lower must be at least 1 deg (a revolution: 360)");
  }
  return axis;
}

// zero_offsets: {G54: {X: 100, Y: 50}, G55: ..}: mm per axis (KRN-8).
void read_zero_offsets(const YAML::Node& node, const std::string& where, MachineConfig& config) {
  if (!node.IsMap()) throw ConfigError(where + ": must map G54 .. G59 to {axis: mm}");
  const std::vector<std::string>& names = zero_offset_names;
  std::vector<std::string> axis_names;
  for (const AxisConfig& axis : config.axes) axis_names.push_back(axis.name);
  const ConfigMap tables(node, where, names);
  for (size_t k = 0; k < names.size(); ++k) {
    if (!tables.has(names[k])) continue;
    const ConfigMap table(tables[names[k]], tables.path(names[k]), axis_names);
    for (size_t a = 0; a < config.axes.size(); ++a)
      if (table.has(axis_names[a]))
        config.zero_offsets[k][a] =
            config_number(table[axis_names[a]], table.path(axis_names[a]), machine_ranges::position);
  }
}

MachineConfig read_machine(const YAML::Node& node) {
  const ConfigMap m(node, "machine", machine_keys);
  MachineConfig config;
  config.name = "machine";
  m.get("name", config.name);
  namespace range = machine_ranges;
  m.get("cycle_time_us", config.cycle_time_us, range::cycle_time_us.min, range::cycle_time_us.max);
  m.get("override_max_percent", config.override_max_percent, range::override_max_percent.min,
        range::override_max_percent.max);
  m.get("fb_storage_size", config.fb_storage_size, range::fb_storage_size.min,
        range::fb_storage_size.max);  // P-STUP-00033, bytes
  m.get("plc_watchdog_cycles", config.plc_watchdog_cycles, range::watchdog_cycles.min, range::watchdog_cycles.max);
  if (m.has("m_pre_outp")) {
    const YAML::Node pre_output = m["m_pre_outp"];
    if (!pre_output.IsMap()) throw ConfigError(m.path("m_pre_outp") + ": must map M numbers to 0.1 um");
    for (const auto& item : pre_output) {  // P-CHAN-00070 m_pre_outp[M number], 0.1 um
      const int nr = static_cast<int>(config_whole(item.first, m.path("m_pre_outp"), 0, int32_max));
      const std::string at = index_path(m.path("m_pre_outp"), nr);
      if (config.m_pre_output_mm.count(nr)) throw ConfigError(at + ": given twice");
      config.m_pre_output_mm[nr] = config_number(item.second, at, range::pre_output_path) / hli_units_per_mm;
    }
  }
  // The lift function (TF5200_lift_function.txt 4.2): its method, and
  // P-CHAN-00244 lift_min_dist (UNS32, 0.1 um).
  FunctionLists lists;
  m.get("path_preparation_function", lists.path_preparation);  // P-STUP-00060
  m.get("interpolator_function", lists.interpolator);          // P-STUP-00070
  m.get("enable_time_based_lift", lists.enable_time_based_lift, 0, 1);  // P-CHAN-00345
  config.lift_method = resolve_lift_method(lists, "machine");
  int64_t lift_min_dist = 0;
  m.get("lift_min_dist", lift_min_dist, range::lift_min_dist.min, range::lift_min_dist.max);
  config.lift_min_dist_mm = static_cast<double>(lift_min_dist) / hli_units_per_mm;
  // KRN-8: the arc end point tolerance, P-CHAN-00171 (0.1 um) and P-CHAN-00172 (0.1 %).
  int64_t radius_diff = 50;
  m.get("max_radius_diff_circle", radius_diff, range::max_radius_diff_circle.min, range::max_radius_diff_circle.max);
  config.max_radius_diff_circle_mm = static_cast<double>(radius_diff) / hli_units_per_mm;
  m.get("max_proz_radius_diff_circle", config.max_proz_radius_diff_circle, range::max_proz_radius_diff_circle);
  const YAML::Node axes = m["axes"];
  if (!axes || !axes.IsSequence() || axes.size() == 0) throw ConfigError("machine.axes: must be a non-empty list");
  for (size_t i = 0; i < axes.size(); ++i) {
    config.axes.push_back(parse_axis(axes[i], index_path("machine.axes", i)));
    if (config.axis_index(config.axes.back().name) != static_cast<int>(i))
      throw ConfigError(index_path("machine.axes", i) + ".name: axis " + config.axes.back().name + " is defined twice");
  }
  for (std::vector<double>& table : config.zero_offsets) table.assign(config.axes.size(), 0.0);
  if (m.has("zero_offsets")) read_zero_offsets(m["zero_offsets"], m.path("zero_offsets"), config);
  return config;
}

}  // namespace

double AxisConfig::in_modulo_range(double position) const {
  if (!modulo) return position;
  const double range = modulo_range();
  double shifted = std::fmod(position - modulo_lower, range);
  if (shifted < 0) shifted += range;
  if (shifted >= range) shifted = 0;  // round-off of fmod + range
  return modulo_lower + shifted;
}

int MachineConfig::axis_index(const std::string& axis_name) const {
  for (size_t i = 0; i < axes.size(); ++i)
    if (axes[i].name == axis_name) return static_cast<int>(i);
  return -1;
}

MachineConfig parse_machine_config(const YAML::Node& node) {
  try {
    return read_machine(node);
  } catch (const YAML::Exception& e) {  // what the checks above do not foresee
    throw ConfigError(std::string("machine: ") + e.what());
  }
}

const std::vector<std::string>& file_keys::machine() { return machine_keys; }
const std::vector<std::string>& file_keys::axis() { return axis_keys; }
const std::vector<std::string>& file_keys::zero_offset_tables() { return zero_offset_names; }

}  // namespace hil
