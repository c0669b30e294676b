#pragma once
// The physical range of every number of a machine file (RIG-11). A value
// outside is refused when the file is read, naming the key, the value and
// the range: a j_max of 1e-320 mm/s^3 or a kv of 2^31 1/s used to pass, the
// axis never moved and the run timed out naming nothing. Inclusive bounds,
// wide enough for any machine from a microscope stage to a linear-motor
// portal, narrow enough to catch a unit or an exponent gone wrong; every
// machine of config/, scenarios/ and tests/ lies well inside. Why each
// bound: docs/SCENARIOS.md, "Machine file ranges". Rotary axes (A, B, C)
// count in deg where a unit says mm (docs/UNITS.md).
#include <cstdint>

#include "config_error.hpp"

namespace hil::machine_ranges {

// v_max, v_rapid: a creep feed of 0.06 mm/min .. 6,000 m/min, 20 times the
// fastest linear-motor axes.
inline constexpr Bounds velocity{1e-3, 1e5, false, "mm/s"};
// a_max, drive_acceleration_limit: .. 1e7 mm/s^2 = 1,000 g (linear motors
// reach some 20 g).
inline constexpr Bounds acceleration{1e-2, 1e7, false, "mm/s^2"};
// j_max: 0.1 mm/s^3 .. 1e9 mm/s^3, at most 100,000 g/s.
inline constexpr Bounds jerk{1e-1, 1e9, false, "mm/s^3"};
// kv (position loop gain): drives have 10 .. 100 1/s; above 1e4 1/s the loop
// closes within 0.1 ms, faster than any rig cycle.
inline constexpr Bounds position_gain{0.1, 1e4, false, "1/s"};
// velocity_lag_s: 10 us (a current loop) .. 10 s.
inline constexpr Bounds velocity_lag{1e-5, 10, false, "s"};
// velocity_damping (zeta): almost undamped .. heavily overdamped.
inline constexpr Bounds damping{0.01, 10, false, ""};
// velocity_feedforward: a fraction of the commanded velocity.
inline constexpr Bounds feedforward{0, 1, false, ""};
// friction_coulomb: a deceleration, no larger than an acceleration may be.
inline constexpr Bounds coulomb_friction{0, 1e7, false, "mm/s^2"};
// friction_viscous: a rate, no faster than the fastest position loop.
inline constexpr Bounds viscous_friction{0, 1e4, false, "1/s"};
// slep_max, slep_min (P-AXIS-00168 / 00169): 0.1 um, the HLI's resolution, .. 1 m.
inline constexpr Bounds following_error{1e-4, 1e3, false, "mm"};
// swe_neg, swe_pos, reference_position, modulo_lower, modulo_upper: the
// decoder's coordinates (|x| <= 1 km, cnc/decoder/value_ranges.hpp), so a
// G74 to the reference point or a move to a limit switch can be programmed.
inline constexpr Bounds position{-1e6, 1e6, false, "mm"};
// swe_toleranz (P-AXIS-00179): .. 1 m past a limit switch.
inline constexpr Bounds limit_switch_tolerance{0, 1e3, false, "mm"};
// modulo_upper - modulo_lower: a revolution (360) or an indexing step; below
// 1 deg the positions would repeat within a setpoint's step.
inline constexpr double min_modulo_range = 1;
// m_pre_outp values, in 0.1 um: .. 1 km, the decoder's PRE_OUTP_PATH bound.
inline constexpr Bounds pre_output_path{0, 1e10, false, "x 0.1 um"};

// Whole numbers.
struct Whole {
  int64_t min, max;
};
inline constexpr Whole cycle_time_us{100, 100000};           // 0.1 .. 100 ms
inline constexpr Whole override_max_percent{100, 200};       // TF5200's override range
inline constexpr Whole fb_storage_size{0, 4294967295};       // bytes: 0 .. 4 GiB of contour memory
inline constexpr Whole lift_min_dist{0, 4294967295};         // 0.1 um, an UNS32 (429 m)
inline constexpr Whole max_radius_diff_circle{0, 10000};    // 0.1 um, P-CHAN-00171 (1 mm)
inline constexpr Bounds max_proz_radius_diff_circle{0, 500, false, "x 0.1 %"};  // P-CHAN-00172
inline constexpr Whole watchdog_cycles{1, 100000};           // 100 s at 1 ms
inline constexpr Whole monitoring_per_mille{1000, 10000};    // P-AXIS-00439 .. 00442: 1 .. 10 x the limit

}  // namespace hil::machine_ranges
