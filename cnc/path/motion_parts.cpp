#include "motion_parts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "axis_vector.hpp"
#include "path_segment.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

constexpr double on_motion_mm = tolerance::no_length_mm;
using tolerance::shortest_part_mm;

// How far along the motion the point lies from its start; none if it is off it.
std::optional<double> along(const Motion& motion, const PathSegment& whole, const std::vector<double>& point,
                            bool at_end_if_closed) {
  const bool at_start = distance(point, motion.start) <= on_motion_mm;
  const bool at_end = distance(point, motion.end) <= on_motion_mm;
  if (at_start && at_end) return at_end_if_closed ? whole.length() : 0.0;
  if (at_start) return 0.0;
  if (at_end) return whole.length();
  const double s = whole.length_to(point);
  if (!(s <= whole.length()) || distance(whole.position(s), point) > on_motion_mm) return std::nullopt;
  return s;
}

}  // namespace

bool same_point(const std::vector<double>& a, const std::vector<double>& b) {
  double scale = 1;
  for (double x : b) scale = std::max(scale, std::abs(x));
  return distance(a, b) <= 8 * std::numeric_limits<double>::epsilon() * scale;
}

Motion motion_until(Motion motion, const std::vector<double>& point) {
  motion.end = point;
  return motion;
}

Motion motion_from(Motion motion, const std::vector<double>& point) {
  motion.start = point;
  return motion;
}

Motion reversed(Motion motion) {
  std::swap(motion.start, motion.end);
  if (motion.type == MotionType::arc_cw) motion.type = MotionType::arc_ccw;
  else if (motion.type == MotionType::arc_ccw) motion.type = MotionType::arc_cw;
  return motion;
}

std::optional<Motion> rest_of_motion(const Motion& motion, const std::vector<double>& point, bool backward,
                                     const MachineConfig& machine, bool at_end_if_closed) {
  const AxisValues& target = backward ? motion.start : motion.end;
  const PathSegment whole(motion, machine);
  if (const std::optional<double> s = along(motion, whole, point, at_end_if_closed)) {
    const double rest = backward ? *s : whole.length() - *s;
    if (rest > shortest_part_mm) return backward ? reversed(motion_until(motion, point)) : motion_from(motion, point);
  }
  if (same_point(point, target)) return std::nullopt;
  Motion line = motion;  // G00 stays G00: with no F programmed a G01 line would not move
  if (line.type != MotionType::rapid) line.type = MotionType::linear;
  line.start = point;
  line.end = target;
  return line;
}

}  // namespace hil::cnc
