#include "lift_profile.hpp"

#include <algorithm>
#include <cmath>

#include "position_profile.hpp"

namespace hil::cnc {
namespace {

MotionProfile positioning(double from, double to, const Limits& lim) {
  return position_profile(MotionState{from, 0, 0, 0}, to, lim, SlopeType::trapez);
}

double largest_speed(const MotionProfile& profile) {
  double v = 0;
  for (size_t i = 0; i <= profile.phases().size(); ++i) v = std::max(v, std::abs(profile.phase_start(i).v));
  return v;
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
    for (int i = 0; i < 100 && std::abs(too_high - ok) > 1e-12 * (1 + std::abs(ok)); ++i) {
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
  p.max_speed_ = std::max(largest_speed(p.rise_), largest_speed(p.fall_));
  return p;
}

MotionState LiftProfile::at(double tau) const {
  tau = std::clamp(tau, 0.0, duration_);
  if (tau >= fall_start_) return fall_.at(tau - fall_start_);
  if (tau >= rise_.duration()) return MotionState{summit_, 0, 0, 0};
  return rise_.at(tau);
}

}  // namespace hil::cnc
