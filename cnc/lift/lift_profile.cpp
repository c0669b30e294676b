#include "lift_profile.hpp"

#include <algorithm>
#include <cmath>

#include "position_profile.hpp"
#include "profile_check.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

MotionProfile positioning(double from, double to, const Limits& lim) {
  return position_profile(MotionState{from, 0, 0, 0}, to, lim, SlopeType::trapez);
}

}  // namespace

double positioning_time(double from, double to, const Limits& lim) { return positioning(from, to, lim).duration(); }

LiftProfile LiftProfile::plan(double z0, double pos, double peak, double duration, const Limits& lim) {
  const bool up = peak >= std::min(z0, pos);
  const double direct = up ? std::max(z0, pos) : std::min(z0, pos);
  if (up) peak = std::max(peak, direct);
  else peak = std::min(peak, direct);
  auto time_over = [&](double summit) { return positioning_time(z0, summit, lim) + positioning_time(summit, pos, lim); };
  double summit = direct;
  if (time_over(peak) <= duration) {
    summit = peak;
  } else if (time_over(direct) < duration) {
    // The time over a summit grows with its height: bisect it.
    double ok = direct, too_high = peak;
    for (int i = 0; i < 100 && std::abs(too_high - ok) > tolerance::bisection_share * (1 + std::abs(ok)); ++i) {
      const double mid = 0.5 * (ok + too_high);
      (time_over(mid) <= duration ? ok : too_high) = mid;
    }
    summit = ok;
  }
  LiftProfile p;
  p.rise_ = positioning(z0, summit, lim);
  p.fall_ = positioning(summit, pos, lim);
  p.summit_ = summit;
  p.duration_ = std::max(duration, p.rise_.duration() + p.fall_.duration());
  p.fall_start_ = p.duration_ - p.fall_.duration();
  // Also inside a phase: without a cruise the acceleration runs from +a to
  // -a in one, and the speed peaks there (phase ends alone said 38.5 mm/s
  // of a 76 mm/s rise; Lifting's jerk caps, sized by it, let the lift axis
  // reach 1.008 j_max: fuzz lift seed 13010605).
  p.max_speed_ = std::max(extremes(p.rise_).max_v, extremes(p.fall_).max_v);
  return p;
}

MotionState LiftProfile::at(double tau) const {
  tau = std::clamp(tau, 0.0, duration_);
  if (tau >= fall_start_) return fall_.at(tau - fall_start_);
  if (tau >= rise_.duration()) return MotionState{summit_, 0, 0, 0};
  return rise_.at(tau);
}

}  // namespace hil::cnc
