#pragma once
// Parts of a programmed motion: to split a block (M function pre-output)
// and to move along it backward (KRN-5). An arc keeps its centre; a point
// must lie on the motion.
#include <optional>
#include <vector>

#include "block.hpp"
#include "machine_config.hpp"

namespace hil::cnc {

// `a` is `b` but for the round-off of their coordinates (8 eps): any longer
// way between them is moved, however short. The path goes on from where it
// stands, and a jump d shows in the setpoints as a jerk of d / T^3 (fuzz
// AG, AH: 0.8e-9 and 0.58e-9 mm put 0.8 and 0.53 mm/s^3 on a jerk of
// 40,000; the limit check allows 1e-6 of it).
bool same_point(const std::vector<double>& a, const std::vector<double>& b);

// From the motion's start to `point`.
Motion motion_until(Motion motion, const std::vector<double>& point);
// From `point` to the motion's end.
Motion motion_from(Motion motion, const std::vector<double>& point);
// The same path the other way: end to start, G02 <-> G03.
Motion reversed(Motion motion);

// The way from `point` on to the motion's end, or (`backward`) back to its
// start, reversed: the motion's own part where the point lies on it. A rest
// too short to tell an arc's part from its full circle (10 nm), and the way
// from a point off the motion (where delete distance to go ended a short
// cut midway, 50810), are a straight line, so that the path goes on from
// where it stands whatever it stands on. None where the point is there.
// On a closed motion (a full circle) its start is its end:
// `at_end_if_closed` tells which.
std::optional<Motion> rest_of_motion(const Motion& motion, const std::vector<double>& point, bool backward,
                                     const MachineConfig& machine, bool at_end_if_closed = false);

}  // namespace hil::cnc
