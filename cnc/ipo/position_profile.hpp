#pragma once
// Time-optimal motion from any state (p, v, a) to a target position at
// rest (v = a = 0) under velocity, acceleration and jerk limits (KRN-3).
//
// The fastest way there is to drive towards the target as hard as the
// limits allow (the velocity change to ±v_max, then cruise) and to brake at
// the one instant from which the fastest stop ends exactly on the target.
// Both parts are closed-form velocity changes; the switching instant is the
// root of a monotone function, found to round-off. This covers every
// profile case of the 7-segment family (with or without acceleration or
// velocity plateau, moves that start by braking or by turning back) without
// a case table, and so has no boundaries where a case can be missed.
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

// States outside the limits (|v| > lim.v or |a| > lim.a) are brought back
// at full jerk first.
MotionProfile position_profile(const MotionState& start, double target, const Limits& lim, SlopeType slope);

// Forward along a path: from `start` (v >= 0) to `end_position`, arriving
// with `end_velocity` (clamped to [0, lim.v]) and a = 0, cruising at lim.v.
// Where end_velocity cannot be reached within the distance, it arrives with
// the reachable velocity closest to it (and if even ramping a to 0 passes
// the end, it does that). lim.v = 0 (feed hold, override 0) stops short.
MotionProfile block_profile(const MotionState& start, double end_position, double end_velocity,
                            const Limits& lim, SlopeType slope);

// Rest-to-rest from p = 0 to p = distance.
MotionProfile rest_to_rest(double distance, const Limits& lim, SlopeType slope = SlopeType::trapez);

}  // namespace hil::cnc
