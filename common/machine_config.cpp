#include "machine_config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>

#include "config_error.hpp"
#include "hli.hpp"

namespace hil {
namespace {

double positive(const YAML::Node& node, const std::string& key, const std::string& where) {
  if (!node[key]) throw ConfigError(where + ": '" + key + "' is missing");
  double value = 0;
  try {
    value = node[key].as<double>();
  } catch (const YAML::Exception&) {
    throw ConfigError(where + ": '" + key + "' is not a number");
  }
  if (!(value > 0) || !std::isfinite(value))
    throw ConfigError(where + ": '" + key + "' must be > 0");
  return value;
}

AxisConfig parse_axis(const YAML::Node& node, size_t index) {
  AxisConfig axis;
  const std::string where = "axes[" + std::to_string(index) + "]";
  if (!node["name"]) throw ConfigError(where + ": 'name' is missing");
  axis.name = node["name"].as<std::string>();
  const std::string at = "axis " + axis.name;
  if (axis.name.empty() || axis.name.find_first_not_of("ABCUVWXYZ") != std::string::npos ||
      axis.name.size() != 1)
    throw ConfigError(at + ": name must be one of the letters A B C U V W X Y Z");
  axis.v_max = positive(node, "v_max", at);
  axis.v_rapid = node["v_rapid"] ? positive(node, "v_rapid", at) : axis.v_max;
  if (axis.v_rapid > axis.v_max) throw ConfigError(at + ": 'v_rapid' exceeds 'v_max'");
  axis.a_max = positive(node, "a_max", at);
  axis.j_max = positive(node, "j_max", at);
  axis.kv = positive(node, "kv", at);
  axis.velocity_lag_s = positive(node, "velocity_lag_s", at);
  auto integer = [&](const char* key, int32_t& value) {
    if (node[key]) value = node[key].as<int32_t>();
  };
  auto at_least_zero = [&](const char* key, double& value) {
    if (!node[key]) return;
    value = node[key].as<double>();
    if (!(value >= 0) || !std::isfinite(value)) throw ConfigError(at + ": '" + key + "' must be >= 0");
  };
  integer("velocity_loop_order", axis.velocity_loop_order);
  if (axis.velocity_loop_order != 1 && axis.velocity_loop_order != 2)
    throw ConfigError(at + ": 'velocity_loop_order' must be 1 or 2");
  if (node["velocity_damping"]) axis.velocity_damping = positive(node, "velocity_damping", at);
  at_least_zero("velocity_feedforward", axis.velocity_feedforward);
  if (axis.velocity_feedforward > 1) throw ConfigError(at + ": 'velocity_feedforward' must be within 0 .. 1");
  if (node["drive_acceleration_limit"])
    axis.drive_acceleration_limit = positive(node, "drive_acceleration_limit", at);
  at_least_zero("friction_coulomb", axis.friction_coulomb);
  at_least_zero("friction_viscous", axis.friction_viscous);
  integer("dyn_monitoring_a_warn", axis.dyn_monitoring_a_warn);
  integer("dyn_monitoring_a_err", axis.dyn_monitoring_a_err);
  integer("dyn_monitoring_v_warn", axis.dyn_monitoring_v_warn);
  integer("dyn_monitoring_v_err", axis.dyn_monitoring_v_err);
  // Values below 1000 would put the monitoring limit below a_max (v_max), so
  // planned motion would trip it: almost surely the value was meant as a
  // percentage excess. Refuse rather than guess (docs/UNITS.md).
  if (axis.dyn_monitoring_a_warn < 1000)
    throw ConfigError(at + ": P-AXIS-00441 dyn_monitoring_a_warn must be >= 1000 (limit = a_max * value / 1000)");
  if (axis.dyn_monitoring_a_err < axis.dyn_monitoring_a_warn)
    throw ConfigError(at + ": P-AXIS-00442 dyn_monitoring_a_err must be >= P-AXIS-00441 dyn_monitoring_a_warn");
  if (axis.dyn_monitoring_v_warn < 1000)
    throw ConfigError(at + ": P-AXIS-00439 dyn_monitoring_v_warn must be >= 1000 (limit = v_max * value / 1000)");
  if (axis.dyn_monitoring_v_err < axis.dyn_monitoring_v_warn)
    throw ConfigError(at + ": P-AXIS-00440 dyn_monitoring_v_err must be >= P-AXIS-00439 dyn_monitoring_v_warn");

  if (node["slep_max"]) {
    axis.slep_max = positive(node, "slep_max", at);
    axis.slep_min = node["slep_min"] ? positive(node, "slep_min", at) : axis.slep_max;
    axis.following_error_monitoring = 4;
  }
  integer("following_error_monitoring", axis.following_error_monitoring);
  if (axis.following_error_monitoring != 0 && axis.following_error_monitoring != 4)
    throw ConfigError(at + ": P-AXIS-00172 following_error_monitoring " +
                      std::to_string(axis.following_error_monitoring) +
                      " is not supported (0 = off, 4 = velocity-independent)");
  if (axis.following_error_monitoring == 4 && !(axis.slep_max > 0))
    throw ConfigError(at + ": P-AXIS-00172 following_error_monitoring 4 needs P-AXIS-00168 slep_max");

  if (node["swe_neg"] || node["swe_pos"]) {
    if (!node["swe_neg"] || !node["swe_pos"])
      throw ConfigError(at + ": software limit switches need both P-AXIS-00177 swe_neg and P-AXIS-00178 swe_pos");
    axis.software_limits = true;
    axis.swe_neg = node["swe_neg"].as<double>();
    axis.swe_pos = node["swe_pos"].as<double>();
    if (!(axis.swe_neg < axis.swe_pos))
      throw ConfigError(at + ": P-AXIS-00177 swe_neg must be below P-AXIS-00178 swe_pos");
    if (node["swe_toleranz"]) axis.swe_toleranz = node["swe_toleranz"].as<double>();
    if (!(axis.swe_toleranz >= 0)) throw ConfigError(at + ": P-AXIS-00179 swe_toleranz must be >= 0");
  }
  return axis;
}

}  // namespace

int MachineConfig::axis_index(const std::string& axis_name) const {
  for (size_t i = 0; i < axes.size(); ++i)
    if (axes[i].name == axis_name) return static_cast<int>(i);
  return -1;
}

MachineConfig parse_machine_config(const YAML::Node& node) {
  if (!node.IsMap()) throw ConfigError("machine: expected a mapping");
  MachineConfig config;
  try {
    config.name = node["name"] ? node["name"].as<std::string>() : "machine";
    if (node["cycle_time_us"]) config.cycle_time_us = node["cycle_time_us"].as<int32_t>();
    if (config.cycle_time_us < 100 || config.cycle_time_us > 100000)
      throw ConfigError("machine: cycle_time_us must be within 100 .. 100000");
    if (node["override_max_percent"]) config.override_max_percent = node["override_max_percent"].as<int32_t>();
    if (config.override_max_percent < 100 || config.override_max_percent > 200)
      throw ConfigError("machine: override_max_percent must be within 100 .. 200");
    if (node["fb_storage_size"]) config.fb_storage_size = node["fb_storage_size"].as<int64_t>();
    if (config.fb_storage_size < 0) throw ConfigError("machine: P-STUP-00033 fb_storage_size must be >= 0");
    if (const YAML::Node pre_output = node["m_pre_outp"]) {
      if (!pre_output.IsMap()) throw ConfigError("machine: m_pre_outp must map M numbers to 0.1 um");
      for (const auto& item : pre_output) {
      const int nr = item.first.as<int>();
      const double value = item.second.as<double>();
      if (nr < 0 || value < 0) throw ConfigError("machine: P-CHAN-00070 m_pre_outp[" + std::to_string(nr) + "] must be >= 0");
      config.m_pre_output_mm[nr] = value / hli_units_per_mm;
      }
    }
    const YAML::Node axes = node["axes"];
    if (!axes || !axes.IsSequence() || axes.size() == 0)
      throw ConfigError("machine: 'axes' must be a non-empty list");
    for (size_t i = 0; i < axes.size(); ++i) {
      config.axes.push_back(parse_axis(axes[i], i));
      if (config.axis_index(config.axes.back().name) != static_cast<int>(i))
        throw ConfigError("machine: axis " + config.axes.back().name + " is defined twice");
    }
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("machine: ") + e.what());
  }
  return config;
}

}  // namespace hil
