#pragma once
// Advanced Lifting's real-time part (LIFT-2): each cycle the lift axis
// rises on towards the summit while it could still land on POS before the
// path can reach the range's end; from the first cycle it could not, it
// lowers to POS on the fastest profile from where it is. The path's time
// to the end is bounded from below by the caller (the range's highest
// programmed velocity at the highest override it accepts, LIFT-8), so the
// lift lands no later than the path arrives; waits of the path (M
// functions, dwell, feed hold) do not stop it.
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

class AdvancedLifting {
 public:
  AdvancedLifting(double z0, double pos, double peak, const Limits& lim, double cycle_s);

  // One cycle on; `earliest_end_s`: the least time in which the path can
  // reach the range's end from now (infinite while it cannot move).
  const MotionState& step(double earliest_end_s);
  // From where it is straight to POS (the path waits, or a short cut
  // leaves the range's rest).
  void land_now();
  const MotionState& state() const { return state_; }
  // The fastest landing on POS from where it is now, s.
  double landing_s() const;
  bool lowering() const { return lowering_; }
  bool landed() const { return lowering_ && since_lowering_ >= fall_.duration(); }

 private:
  MotionState state_;
  double pos_ = 0, peak_ = 0;
  Limits lim_;
  double cycle_s_ = 0;
  bool lowering_ = false;
  MotionProfile fall_;
  double since_lowering_ = 0;
};

}  // namespace hil::cnc
