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
//  - Near-tangent (issue 36): the tangents differ by no more than the
//    program's rounding can tilt them (near_tangent_angle: a line's end
//    points rounded to 0.0001 mm across its length, an arc's end radius off
//    its start radius). Passed as a curvature step whose axes also see the
//    tangent's step: the axis velocity steps by v |dt_i| between two
//    samples, which the sampled setpoints show as an acceleration of at
//    most v |dt_i| / T for one cycle and a jerk of at most v |dt_i| / T^2;
//    both join the budget above (the acceleration with 2 T j_i for the
//    path's own around a = 0 and kappa_i v^2). A kink's jerk shows in the
//    three samples whose positions straddle it, so the next kink (or any
//    other step) must lie three cycles away: kink_spacing_velocity. A
//    corner beyond near_tangent_angle stops.
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

// What one axis sees step at a transition: its curvature (dk, 1/mm), at a
// near-tangent joint its tangent (dt), and the larger of its curvatures
// on either side (kappa).
struct AxisStep {
  double dk = 0, dt = 0, kappa = 0;
};

// The rule above for one axis: the highest v with
// v^2 dk / T + v^3 kappa^2 + 6 kappa v T j + v dt / T^2 <= (1 - share) j
// and, at a near-tangent joint, v dt / T + kappa_i v^2 + 2 T j <= a_max;
// at most v_cap. `kappa`: of the path, on the larger side.
double curvature_step_velocity(const AxisStep& step, double kappa, const AxisConfig& axis, double cycle_s,
                               double v_cap);

// The highest v at a near-tangent joint that puts three cycles between it
// and anything at the far ends of `before` and `after` (fuzz seeds contour
// 23000750, 23000886: kinks of 0.003 mm blocks, Y jerk 46,565 for 40,000).
// The path crosses the joint with a = 0, so in t it covers at most
// v t + J t^3 / 6 (J: the blocks' path jerk); t >= 3 T on a block of
// length L where v <= (L - 4.5 J T^3) / (3 T).
double kink_spacing_velocity(const PathSegment& before, const PathSegment& after, double cycle_s);

// The largest angle between the tangents at which `before` and `after`
// still meet tangentially but for the program's rounding (their
// direction_rounding() added, at most 3 degrees): a near-tangent joint.
double near_tangent_angle(const PathSegment& before, const PathSegment& after);

}  // namespace hil::cnc
