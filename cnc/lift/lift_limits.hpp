#pragma once
// The lift axis' own limits per method (TF5200_lift_function.txt, LIFT-2,
// LIFT-3; docs/LIFT.md "The lift axis' limits"). Its jerk stays within
// j_max in every method ("the Z axis moves with jerk limiting").
#include "machine_config.hpp"
#include "slope.hpp"

namespace hil::cnc {

// Advanced Lifting plans up to a_max * P-AXIS-00442 / 1000 (the overload
// range) and j_max, less what the axis' drive overshoots: the rig monitors
// the actual acceleration, which follows a jerk-limited command with an
// overshoot that depends on the drive (kv, the velocity loop, friction).
// The acceleration is the largest the machine file's drive model follows
// within 99.5 % of that limit (axis/drive_response); memoised per thread.
Limits advanced_lifting_limits(const AxisConfig& axis, double cycle_time_s);
// Computes them for every axis of a machine that lifts time-based, on this
// thread, ahead of the run: 10-50 ms an axis, which a real-time run would
// otherwise spend in the cycle that decodes its first LIFT_START.
void prepare_advanced_lifting_limits(const MachineConfig& machine);

// Lifting (path-based) couples the lift axis to the path parameter q: its
// acceleration is z_qq v^2 + z_q a_path, its jerk z_qqq v^3 + 3 z_qq v
// a_path + z_q j_path. The profile is planned at half the budget (a:
// half the overload range, at most a_max, so that at constant path
// velocity it stays within a_max; j: half of j_max), and the path's
// acceleration and jerk in the range are capped to the other half.
// `factor`: P-AXIS-00442 / 1000, or 1 for a suppressed lift (within a_max).
Limits lifting_limits(const AxisConfig& axis, double factor);
// Lifting: the profile's share of j_max; the path's cross terms get the rest.
constexpr double lifting_profile_jerk_share = 0.5;

}  // namespace hil::cnc
