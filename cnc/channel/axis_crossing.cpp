#include "axis_crossing.hpp"

#include <algorithm>
#include <cmath>

#include "path_segment.hpp"
#include "tolerances.hpp"

namespace hil::cnc {

// Lines are affine in s, so the first sample interval with a sign change
// holds the crossing; an arc is sampled every 0.1 mm of path at least, and
// the crossing found by bisection (a circle that only touches the position
// between two samples is missed: below 0.1 mm of path, ~1e-3 mm in axis).
std::optional<double> covered_until_axis_reaches(const std::vector<Motion>& motions, size_t axis, double position,
                                                 const MachineConfig& machine, bool modulo) {
  constexpr double on = tolerance::standing_on_mm;
  double covered = 0;
  for (const Motion& motion : motions) {
    const PathSegment seg(motion, machine);
    const double length = seg.length();
    if (!std::isfinite(length)) return std::nullopt;
    // A modulo axis is no arc axis (A, B, C): it moves one way on a block,
    // so the position it meets first lies ahead of it in that way.
    double target = position;
    if (modulo) {
      const double range = machine.axes[axis].modulo_range(), from = seg.position(0)[axis];
      const bool up = seg.end()[axis] >= from;
      double ahead = std::fmod(up ? position - from : from - position, range);
      if (ahead < 0) ahead += range;
      if (range - ahead <= on) ahead = 0;
      target = up ? from + ahead : from - ahead;
    }
    auto f = [&](double s) { return seg.position(s)[axis] - target; };
    if (std::abs(f(0)) <= on) return covered;
    const int n = motion.type == MotionType::arc_cw || motion.type == MotionType::arc_ccw
                      ? static_cast<int>(std::clamp(std::ceil(length / 0.1), 16.0, 1e5))
                      : 1;
    double s0 = 0, f0 = f(0);
    for (int i = 1; i <= n && length > 0; ++i) {
      const double s1 = length * i / n, f1 = f(s1);
      if (std::abs(f1) <= on || (f0 < 0) != (f1 < 0)) {
        double lo = s0, hi = s1;
        if (std::abs(f1) > on)
          for (int k = 0; k < 100 && hi - lo > tolerance::bisection_share; ++k) {
            const double mid = 0.5 * (lo + hi);
            if ((f(mid) < 0) == (f0 < 0)) lo = mid;
            else hi = mid;
          }
        return covered + seg.covered_distance() * hi / length;
      }
      s0 = s1;
      f0 = f1;
    }
    covered += seg.covered_distance();
  }
  return std::nullopt;
}

}  // namespace hil::cnc
