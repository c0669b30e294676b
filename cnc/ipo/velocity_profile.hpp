#pragma once
// Time-optimal change of velocity under acceleration and jerk limits
// (KRN-3): from any (v, a) to a target velocity with acceleration 0. The
// velocity-target mode for feed hold, override and stop, and the building
// block of the position planner.
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

// Ramp to a plateau (SIN2: via a = 0), hold it, ramp back to 0.
struct VelocityChange {
  InlineList<Phase, 4> phases;
  int count() const { return static_cast<int>(phases.size()); }
  const Phase& phase(int i) const { return phases[static_cast<size_t>(i)]; }
  double duration() const;
  // State at the end, begun in `s`.
  MotionState end(const MotionState& s) const;
  // Appends the phases to `out`.
  void append_to(PhaseList& out) const;
};

// From (v, a) to (v_target, 0), fastest under lim.a and lim.j for the slope
// type. The start acceleration, where it has to shrink (above lim.a, or
// carrying v past v_target), is brought back at full jerk (unwind_rate):
// for SIN2 a linear ramp, since the state may be in the middle of a sin²
// pulse; the velocity overshoot that remains cannot be avoided. lim.v is
// not applied here: the caller chooses v_target.
VelocityChange velocity_change(double v, double a, double v_target, const Limits& lim, SlopeType slope);

// The same, every slope type by the one construction: what TRAPEZ's closed
// form (trapez_change.hpp, issue 36) is tested against, to the bit.
VelocityChange velocity_change_reference(double v, double a, double v_target, const Limits& lim, SlopeType slope);

// velocity_change(v, a, ...).end(s) for s = (p, v, a), without storing
// the phases (the position planner's searches evaluate it many times);
// TRAPEZ in closed form (trapez_change.hpp), to the same bit.
MotionState velocity_change_end(const MotionState& s, double v_target, const Limits& lim, SlopeType slope);

// The velocity-target mode: v_target is clamped to [-lim.v, lim.v].
MotionProfile velocity_profile(const MotionState& start, double v_target, const Limits& lim, SlopeType slope);

}  // namespace hil::cnc
