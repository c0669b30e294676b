#pragma once
// The lift axis' motion over a lift range planned in advance: from z0 at
// rest up to a summit and down to the landing position at rest, in a given
// time, jerk-limited (TF5200_lift_function.txt). Lifting (path-based,
// LIFT-3) runs it over the path parameter; a suppressed lift (LIFT-4) and a
// lift without path motion run its direct form.
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

class LiftProfile {
 public:
  LiftProfile() = default;
  // The highest summit towards `peak` (beyond max(z0, pos), or below their
  // minimum for a lowering) whose rise and fall fit in `duration`: it rises
  // at once, waits there, and lands at `duration`. If not even the direct
  // move fits, the direct move: duration() is then longer than asked.
  static LiftProfile plan(double z0, double pos, double peak, double duration, const Limits& lim);

  double duration() const { return duration_; }
  double summit() const { return summit_; }
  // Largest |velocity| of the lift axis on it.
  double max_speed() const { return max_speed_; }
  // State at time tau (clamped to [0, duration()]).
  MotionState at(double tau) const;

 private:
  MotionProfile rise_, fall_;
  double fall_start_ = 0;
  double duration_ = 0;
  double summit_ = 0;
  double max_speed_ = 0;
};

// Time of the fastest move between two positions at rest.
double positioning_time(double from, double to, const Limits& lim);

}  // namespace hil::cnc
