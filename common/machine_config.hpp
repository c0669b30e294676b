#pragma once
// Machine parameters: the channel and its axes. Units inside: mm, s.
#include <cstdint>
#include <map>
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
  double velocity_lag_s = 0; // s, velocity loop time constant (T, or 1/omega for order 2)
  // The drive model (RIG-3, axis_sim/drive_model.hpp); checked for a stable
  // closed loop when a run starts.
  int32_t velocity_loop_order = 1;        // 1: first-order lag, 2: second-order
  double velocity_damping = 0.7;          // zeta of a second-order velocity loop
  double velocity_feedforward = 1;        // 0 .. 1
  double drive_acceleration_limit = 0;    // mm/s^2, torque limit / inertia; 0 = none
  double friction_coulomb = 0;            // mm/s^2, friction force / inertia
  double friction_viscous = 0;            // 1/s
  // P-AXIS-00441 / 00442 in units of 1/1000 of a_max: the monitoring limit is
  // a_max * value / 1000, as TF5200_lift_function.txt and SPEC RIG-3 write it
  // (see docs/UNITS.md). 1500 / 2000 mean 1.5 x and 2.0 x a_max.
  int32_t dyn_monitoring_a_warn = 1500;
  int32_t dyn_monitoring_a_err = 2000;
  // P-AXIS-00439 / 00440, the same way of v_max: 1050 / 1090 are the
  // TF5200 defaults (5 % / 9 % above v_max).
  int32_t dyn_monitoring_v_warn = 1050;
  int32_t dyn_monitoring_v_err = 1090;
  // Following error monitoring, P-AXIS-00172: 0 off, 4 velocity-independent
  // (|FE| <= slep_max while the axis moves, <= slep_min at standstill).
  int32_t following_error_monitoring = 0;
  double slep_max = 0;  // mm, P-AXIS-00168 (also the offline check's limit; 0 = none)
  double slep_min = 0;  // mm, P-AXIS-00169
  // Software limit switches P-AXIS-00177 (swe_neg) / 00178 (swe_pos): the
  // setpoint must stay within them, the actual position within them widened
  // by P-AXIS-00179 swe_toleranz. Not monitored unless configured.
  bool software_limits = false;
  double swe_neg = 0, swe_pos = 0;  // mm
  double swe_toleranz = 0.1;        // mm
  // KRN-7: a rotary modulo axis (A, B or C; units deg instead of mm): its
  // positions repeat every modulo_upper - modulo_lower (a C axis: 0 and
  // 360). Commanded and driven continuously (many revolutions); shown on
  // the HLI, programmed absolute (G90) and searched by an absolute insert
  // stop (ISC-4) within [modulo_lower, modulo_upper).
  bool modulo = false;
  double modulo_lower = 0, modulo_upper = 0;
  // mm, machine coordinates: where a G74 homing run ends; the rig
  // simulates the reference signal there (DPS-3, docs/BLOCK_SEARCH.md).
  double reference_position = 0;
  // Cycles the drive may leave without an answer before the CNC stops the
  // channel with a watchdog error (real-time mode, faults; RIG-6, RIG-8).
  int64_t watchdog_cycles = 20;

  double modulo_range() const { return modulo_upper - modulo_lower; }
  // A B C: degrees where a linear axis has mm (docs/UNITS.md); only these may be modulo axes.
  bool rotary() const { return name == "A" || name == "B" || name == "C"; }
  // The position shifted into the modulo range; itself on a linear axis.
  double in_modulo_range(double position) const;

  double accel_warning_limit() const { return a_max * dyn_monitoring_a_warn / 1000.0; }
  double accel_error_limit() const { return a_max * dyn_monitoring_a_err / 1000.0; }
  double velocity_warning_limit() const { return v_max * dyn_monitoring_v_warn / 1000.0; }
  double velocity_error_limit() const { return v_max * dyn_monitoring_v_err / 1000.0; }
};

// The lift function's method (TF5200_lift_function.txt, 4.2.1): none in
// the basic setting; Lifting (path-based) with FCT_LIFT_UP in P-STUP-00060;
// Advanced Lifting (time-based) with FCT_LIFT_UP_TIME in P-STUP-00060 and
// P-STUP-00070 and P-CHAN-00345 enable_time_based_lift = 1.
enum class LiftMethod { none, path_based, time_based };

struct MachineConfig {
  std::string name;
  int32_t cycle_time_us = 1000;
  // Highest feed override the PLC may set, in %; above 100 only if configured.
  int32_t override_max_percent = 100;
  // P-STUP-00033 fb_storage_size: memory for backward motion on the path,
  // bytes; delete distance to go needs it > 0 (DDTG-11). TF5200's default 0.
  int64_t fb_storage_size = 0;
  // P-CHAN-00070 m_pre_outp[i]: M function i goes out this far (mm; the
  // file gives 0.1 um) along the path before its block. The NC program can
  // change it: V.G.M_FCT[i].PRE_OUTP_PATH = <mm>.
  std::map<int, double> m_pre_output_mm;
  // P-STUP-00060 path_preparation.function, P-STUP-00070
  // interpolator.function (identifiers joined by |), P-CHAN-00345: resolved
  // to the lift method at load, contradictions refused there.
  LiftMethod lift_method = LiftMethod::none;
  // P-CHAN-00244 lift_min_dist (the file gives 0.1 um): a lift range whose
  // path is shorter suppresses the lift (LIFT-4). 0: never.
  double lift_min_dist_mm = 0;
  // Cycles the PLC may leave without an answer before the watchdog error.
  int64_t plc_watchdog_cycles = 20;
  // How far an arc's end may lie off its circle (G164; KRN-8, error 21758):
  // P-CHAN-00171 max_radius_diff_circle (the file gives 0.1 um; default 50
  // = 5 um) or P-CHAN-00172 max_proz_radius_diff_circle (the file gives
  // 0.1 % of the radius; default 0.1 = 0.01 %), whichever allows more.
  double max_radius_diff_circle_mm = 0.005;
  double max_proz_radius_diff_circle = 0.1;  // 0.1 %
  // G54..G59 (TF5200 "Zero offsets"; the zero offset data's
  // np_grp[1..6].achse[j].versch, here in mm per machine axis): machine -
  // program while the G function is in force; G53 (initial) deselects.
  std::vector<std::vector<double>> zero_offsets = std::vector<std::vector<double>>(6);
  std::vector<AxisConfig> axes;

  double radius_difference_limit(double radius) const {
    const double relative = max_proz_radius_diff_circle * 1e-3 * radius;
    return relative > max_radius_diff_circle_mm ? relative : max_radius_diff_circle_mm;
  }

  double cycle_time_s() const { return cycle_time_us * 1e-6; }
  // Index of the axis called `name`, -1 if there is none.
  int axis_index(const std::string& name) const;
};

// Reads and validates; throws ConfigError naming the field and why.
MachineConfig parse_machine_config(const YAML::Node& node);

}  // namespace hil
