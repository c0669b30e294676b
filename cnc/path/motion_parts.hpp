#pragma once
// Parts of a programmed motion: to split a block (M function pre-output)
// and to move along it backward (KRN-5). An arc keeps its centre; a point
// must lie on the motion.
#include <vector>

#include "block.hpp"

namespace hil::cnc {

// From the motion's start to `point`.
Motion motion_until(Motion motion, const std::vector<double>& point);
// From `point` to the motion's end.
Motion motion_from(Motion motion, const std::vector<double>& point);
// The same path the other way: end to start, G02 <-> G03.
Motion reversed(Motion motion);

}  // namespace hil::cnc
