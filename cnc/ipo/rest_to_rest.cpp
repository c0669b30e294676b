#include "rest_to_rest.hpp"

#include <cmath>

namespace hil::cnc {

JerkProfile rest_to_rest(double distance, const Limits& lim) {
  if (!(distance > 0)) return JerkProfile(MotionState{}, {});
  const double j = lim.j;
  // Peak velocity vp and the acceleration reached ap, from the three cases:
  // (1) v limit reached, (2) a limit reached but not v, (3) neither.
  double vp = lim.v;
  double ap = (vp * j >= lim.a * lim.a) ? lim.a : std::sqrt(vp * j);
  // Accelerating 0 -> vp takes ap/j + vp/ap and covers vp * that / 2.
  const double accel_distance = vp * (ap / j + vp / ap) / 2;
  if (2 * accel_distance > distance) {
    const double k = lim.a * lim.a / j;
    vp = (-k + std::sqrt(k * k + 4 * lim.a * distance)) / 2;
    if (vp * j >= lim.a * lim.a) {
      ap = lim.a;
    } else {
      const double tj = std::cbrt(distance / (2 * j));
      ap = j * tj;
      vp = j * tj * tj;
    }
  }
  const double tj = ap / j;
  const double ta = std::max(0.0, vp / ap - tj);                  // constant acceleration
  const double tv = std::max(0.0, distance / vp - (2 * tj + ta));  // cruise
  return JerkProfile(MotionState{},
                     {{tj, j}, {ta, 0}, {tj, -j}, {tv, 0}, {tj, -j}, {ta, 0}, {tj, j}});
}

}  // namespace hil::cnc
