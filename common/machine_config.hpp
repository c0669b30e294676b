#pragma once
// Machine parameters: the channel and its axes. Units inside: mm, s.
#include <cstdint>
#include <string>
#include <vector>

namespace YAML { class Node; }

namespace hil {

struct AxisConfig {
  std::string name;
  double v_max = 0;          // mm/s, feed velocity limit
  double v_rapid = 0;        // mm/s, G00 velocity (<= v_max)
  double a_max = 0;          // mm/s^2
  double j_max = 0;          // mm/s^3
  double kv = 0;             // 1/s, position loop gain (P-AXIS-00099 style)
  double velocity_lag_s = 0; // s, velocity loop modelled as first-order lag
  // P-AXIS-00441 / 00442 in units of 1/1000 of a_max: the monitoring limit is
  // a_max * value / 1000, as TF5200_lift_function.txt and SPEC RIG-3 write it
  // (see docs/UNITS.md). 1500 / 2000 mean 1.5 x and 2.0 x a_max.
  int32_t dyn_monitoring_a_warn = 1500;
  int32_t dyn_monitoring_a_err = 2000;
  double following_error_max = 0;  // mm, 0 = not checked offline

  double accel_warning_limit() const { return a_max * dyn_monitoring_a_warn / 1000.0; }
  double accel_error_limit() const { return a_max * dyn_monitoring_a_err / 1000.0; }
};

struct MachineConfig {
  std::string name;
  int32_t cycle_time_us = 1000;
  // Highest feed override the PLC may set, in %; above 100 only if configured.
  int32_t override_max_percent = 100;
  std::vector<AxisConfig> axes;

  double cycle_time_s() const { return cycle_time_us * 1e-6; }
  // Index of the axis called `name`, -1 if there is none.
  int axis_index(const std::string& name) const;
};

// Reads and validates; throws ConfigError naming the field and why.
MachineConfig parse_machine_config(const YAML::Node& node);

}  // namespace hil
