#include "profile_check.hpp"

#include <algorithm>
#include <cmath>

namespace hil::cnc {

ProfileExtremes extremes(const MotionProfile& profile) {
  ProfileExtremes x;
  auto take = [&](const MotionState& s) {
    x.finite = x.finite && std::isfinite(s.p) && std::isfinite(s.v) && std::isfinite(s.a);
    x.max_v = std::max(x.max_v, std::abs(s.v));
    x.max_a = std::max(x.max_a, std::abs(s.a));
  };
  take(profile.start());
  const auto& phases = profile.phases();
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const Phase& ph = phases[i];
    const MotionState s = profile.phase_start(i), e = profile.phase_start(i + 1);
    take(e);
    if (!(ph.duration >= 0)) x.durations_valid = false;
    if (!(ph.duration > 0)) continue;
    // The acceleration is monotone within a phase; where it crosses zero the
    // velocity has an extreme.
    if ((s.a < 0 && e.a > 0) || (s.a > 0 && e.a < 0)) {
      double lo = 0, hi = ph.duration;
      for (int k = 0; k < 200 && lo < hi; ++k) {
        const double mid = (lo + hi) / 2;
        if (mid <= lo || mid >= hi) break;
        ((advance(s, ph, mid).a > 0) == (s.a > 0) ? lo : hi) = mid;
      }
      take(advance(s, ph, lo));
      take(advance(s, ph, hi));
    }
    double jerk = std::abs(ph.jerk);
    if (ph.shape == Phase::Shape::sin2) {
      // The pulse peaks at u = 1/2; elsewhere the piece's ends bound it.
      const double u1 = ph.u0 + ph.duration / ph.ramp_time;
      jerk = (ph.u0 <= 0.5 && u1 >= 0.5) ? 2 * std::abs(ph.ramp_delta_a) / ph.ramp_time
                                         : std::max(std::abs(advance(s, ph, 0).j), std::abs(advance(s, ph, ph.duration).j));
    }
    x.finite = x.finite && std::isfinite(jerk);
    x.max_j = std::max(x.max_j, jerk);
  }
  return x;
}

bool meets(const MotionProfile& profile, double target, const Limits& lim, SlopeType slope, double tolerance,
           double relative) {
  const ProfileExtremes x = extremes(profile);
  const MotionState start = profile.start(), end = profile.end();
  if (!x.finite || !x.durations_valid || !std::isfinite(profile.duration())) return false;
  if (std::abs(end.p - target) > tolerance || std::abs(end.v) > tolerance || std::abs(end.a) > tolerance)
    return false;
  // Outside the limits at the start the profile may only come back; an
  // acceleration that still drives |v| up adds a|a|/2 per ramp rate.
  const double a_allowed = std::max(lim.a, std::abs(start.a));
  const double v_allowed =
      std::max({lim.v, std::abs(start.v), std::abs(velocity_after_ramp_to_zero(start.v, start.a, lim, slope))});
  if (x.max_v > v_allowed * (1 + relative)) return false;
  if (x.max_a > a_allowed * (1 + relative)) return false;
  if (slope != SlopeType::step && x.max_j > lim.j * (1 + relative)) return false;
  return true;
}

}  // namespace hil::cnc
