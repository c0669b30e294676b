#pragma once
// The corner rule (KRN-3, KRN-6): the highest path velocity at which the
// path may pass from one motion block into the next, so that no axis leaves
// its limits at the block transition. The planner crosses every transition
// with path acceleration 0; what is left is the change of direction and
// of curvature between the blocks, seen by the axes within one cycle:
//
//  - Tangent break (any axis' share of the path changes by more than
//    round-off, a corner): the axis velocity would jump by v * |dt_i|,
//    a jerk of v |dt_i| / T^2 in the sampled setpoints. With j_max of tens
//    of m/s^3 and T = 1 ms that allows hundredths of mm/s: v = 0. (With
//    G261/G61 the look-ahead replaces the corner by a contouring curve
//    first: see contour_builder.hpp.)
//  - Tangent-continuous, curvature changes (line into arc, arc into arc of
//    another radius): the axis acceleration steps by v^2 |dk_i|, which the
//    sampled setpoints show as a jerk of at most v^2 |dk_i| / T. The blocks
//    on both sides get half their path jerk (curvature_step_jerk_share), so
//    the path's own jerk gives the axis at most j_i / 2 there. The rest,
//    j_i / 2, is the step's, together with what the curvature itself adds at
//    the velocity v of the transition: the centripetal acceleration turning
//    with the path, v^3 kappa^2, and 3 kappa v a with the path acceleration
//    of the two cycles around the transition (where a passes 0 at path jerk
//    <= j_i: |a| <= 2 T j_i):
//        v^2 |dk_i| / T + v^3 kappa^2 + 6 kappa v T j_i  <=  j_i / 2.
//    The junction velocity is the highest v that keeps this for every axis
//    (docs/CONTOURING.md works the demo's line/arc joint by hand).
//  - Otherwise (collinear lines, the same circle) the limits of the blocks.
#include "machine_config.hpp"
#include "path_segment.hpp"

namespace hil::cnc {

struct Junction {
  double v_max = 0;             // highest path velocity at the transition
  bool curvature_step = false;  // the blocks on both sides get part of their path jerk
};

// The path jerk share of a block next to a curvature step.
constexpr double curvature_step_jerk_share = 0.5;

Junction junction(const PathSegment& before, const PathSegment& after, const MachineConfig& machine);

// The rule above for one axis: the highest v with
// v^2 dk / T + v^3 kappa^2 + 6 kappa v T j <= (1 - share) j, at most v_cap.
double curvature_step_velocity(double dk, double kappa, double j_max, double cycle_s, double v_cap);

}  // namespace hil::cnc
