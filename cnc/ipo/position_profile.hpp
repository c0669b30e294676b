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
//
// Where it can be, the switching instant is closed-form (issue 17): from
// rest to rest (TRAPEZ, STEP) the profile is symmetric and the distance
// gives it directly (a cube root without acceleration plateau, a quadratic
// with one). Elsewhere (TRAPEZ, STEP) the drive phase holding it is found
// from the values at the phase ends, and within that phase, where the
// function is smooth, TRAPEZ takes bracketed Newton steps on its
// closed-form velocity change (issue 36: trapez_change.hpp) and STEP a
// regula falsi with Anderson-Bjoerck weights and bisection safeguard.
// SIN2 keeps the search over the whole drive. No path allocates: the
// profile holds its phases in place.
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

// How the switching instant is found: `fast` is the product's; `reference`
// is the solver before issue 17 (Illinois regula falsi and bisection over
// the whole drive, down to adjacent doubles), kept so that tests can check
// the fast one against it.
enum class SwitchSearch { fast, reference };

// States outside the limits (|v| > lim.v or |a| > lim.a) are brought back
// at full jerk first.
MotionProfile position_profile(const MotionState& start, double target, const Limits& lim, SlopeType slope,
                               SwitchSearch search = SwitchSearch::fast);

// How a block profile arrives at its end, as a value the caller acts on
// (issue 35; as Ruckig's Result), instead of a guess from the profile's end.
enum class Arrival {
  as_asked,  // on end_position with end_velocity, a = 0
  slower,    // on end_position, slower than end_velocity (braking, a lower one can need less way)
  held,      // short of end_position at rest: lim.v = 0 (feed hold, override 0)
  too_fast,  // the distance is too short to slow to end_velocity: faster, or beyond end_position
};

// end_velocity is the most a block transition allows: every arrival but
// too_fast keeps it.
inline bool keeps_end(Arrival arrival) { return arrival != Arrival::too_fast; }

struct BlockProfile {
  MotionProfile profile;
  Arrival arrival = Arrival::as_asked;
};

// Forward along a path: from `start` (v >= 0) to `end_position`, arriving
// with `end_velocity` (clamped to [0, lim.v]) and a = 0, cruising at lim.v.
// From any state there is a profile: where end_velocity cannot be reached
// within the distance (too_fast), it brakes at full jerk and arrives with
// the reachable velocity closest to it (and if even ramping a to 0 passes
// the end, it does that). lim.v = 0 stops short (held).
BlockProfile block_profile(const MotionState& start, double end_position, double end_velocity, const Limits& lim,
                           SlopeType slope, SwitchSearch search = SwitchSearch::fast);

// Rest-to-rest from p = 0 to p = distance.
MotionProfile rest_to_rest(double distance, const Limits& lim, SlopeType slope = SlopeType::trapez);

}  // namespace hil::cnc
