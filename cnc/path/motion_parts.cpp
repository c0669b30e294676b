#include "motion_parts.hpp"

#include <utility>

namespace hil::cnc {

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

}  // namespace hil::cnc
