#pragma once
// The corner rule (KRN-3): the highest path velocity at which the path may
// pass from one motion block into the next, so that no axis leaves its
// limits at the block transition. The planner crosses every transition
// with path acceleration 0; what is left is the change of direction and
// of curvature between the blocks, seen by the axes within one cycle:
//
//  - Tangent break (any axis' share of the path changes by more than
//    round-off, a corner): the axis velocity would jump by v * |dt_i|,
//    a jerk of v |dt_i| / T^2 in the sampled setpoints. With j_max of tens
//    of m/s^3 and T = 1 ms that allows hundredths of mm/s: v = 0.
//  - Tangent-continuous, curvature changes (line into arc, arc into arc of
//    another radius): the axis acceleration steps by v^2 |dk_i|, a sampled
//    jerk of v^2 |dk_i| / T on top of what the path's own jerk gives the
//    axis. The blocks on both sides get half their path jerk (a line's path
//    jerk then gives an axis at most j_i / 2, an arc's terms at most 5/6 j_i),
//    and the step gets the rest of the smaller: v^2 |dk_i| / T <= j_i / 6.
//  - Otherwise (collinear lines, the same circle) the limits of the blocks.
#include "machine_config.hpp"
#include "path_segment.hpp"

namespace hil::cnc {

struct Junction {
  double v_max = 0;             // highest path velocity at the transition
  bool curvature_step = false;  // the blocks on both sides get half their path jerk
};

// The path jerk share of a block next to a curvature step.
constexpr double curvature_step_jerk_share = 0.5;

Junction junction(const PathSegment& before, const PathSegment& after, const MachineConfig& machine);

}  // namespace hil::cnc
