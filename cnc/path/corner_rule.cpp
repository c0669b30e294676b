#include "corner_rule.hpp"

#include <algorithm>
#include <cmath>

#include "axis_vector.hpp"
#include "bisect.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {
// Unit tangents from a decoder's lines differ by this much when collinear.
constexpr double tangent_round_off = tolerance::direction;
// Curvatures of the same circle, or of a contouring curve's end and the
// path it joins, differ by round-off relative to their size.
constexpr double curvature_round_off = tolerance::curvature_share;

// A kink whose jerk at the blocks' highest velocity stays below this share
// of an axis' jerk limit is round-off: tangent, passed with the blocks'
// full jerk. A tenth of what the limit check allows (1e-6): a path at its
// jerk limit meets such a kink (mixed seed 26001680: collinear blocks,
// one begun 1e-8 mm off its line, kinked by 1.6e-9, added 0.11 mm/s^3 to
// Z's 30,000 under a share of 1e-3). Pieces of a split line in the
// engraving program met at 1.2e-12 rad, just above tolerance::direction,
// and were passed as kinks at 1.3 mm/s.
constexpr double negligible_kink_share = 1e-7;
}  // namespace

double curvature_step_velocity(const AxisStep& step, double kappa, const AxisConfig& axis, double cycle_s,
                               double v_cap) {
  const double j_max = axis.j_max, budget = (1 - curvature_step_jerk_share) * j_max;
  const double dk = step.dk, dt = step.dt, t = cycle_s;
  auto fits = [&](double v) {
    if (v * v * dk / t + v * v * v * kappa * kappa + 6 * kappa * v * t * j_max + v * dt / (t * t) > budget)
      return false;
    return dt == 0 || v * dt / t + step.kappa * v * v + 2 * t * j_max <= axis.a_max;
  };
  if (fits(v_cap)) return v_cap;
  if (!fits(0)) return 0;
  return last_fitting(0.0, v_cap, fits);
}

Junction junction(const PathSegment& before, const PathSegment& after, const MachineConfig& machine) {
  // The tangents on the stack for up to 16 axes: the corner rule runs at
  // every block transition, and most of a polyline's are corners.
  const size_t axes = before.end().size();
  double stack[2][16];
  std::vector<double> heap;
  double* t1 = stack[0];
  double* t2 = stack[1];
  if (axes > 16) {
    heap.resize(2 * axes);
    t1 = heap.data();
    t2 = heap.data() + axes;
  }
  before.tangent(before.length(), t1);
  after.tangent(0, t2);
  Junction j{std::min(before.limits().v, after.limits().v), false};
  const double cycle = machine.cycle_time_s();
  bool tangent = true;
  double turn = 0;  // |t2 - t1|: the angle the path turns by (rad, small)
  for (size_t i = 0; i < axes; ++i) {
    const double d = std::abs(t2[i] - t1[i]);
    if (d > tangent_round_off && d * j.v_max / (cycle * cycle) > negligible_kink_share * machine.axes[i].j_max)
      tangent = false;
    turn += d * d;
  }
  // A corner needs no curvatures; a near-tangent joint is passed as a
  // curvature step whose axes also see their tangent's step.
  if (!tangent && !(std::sqrt(turn) <= near_tangent_angle(before, after))) return {0.0, false};
  const std::vector<double> k1 = before.curvature(before.length()), k2 = after.curvature(0);
  const double kappa = std::max(norm(k1), norm(k2));
  if (!tangent) j.v_max = std::min(j.v_max, kink_spacing_velocity(before, after, cycle));
  for (size_t i = 0; i < k1.size(); ++i) {
    // An axis along the tangent has no share of the curvature but round-off.
    AxisStep step;
    step.dk = std::abs(k2[i] - k1[i]);
    step.dt = tangent ? 0.0 : std::abs(t2[i] - t1[i]);
    step.kappa = std::max(std::abs(k1[i]), std::abs(k2[i]));
    if (step.dk <= curvature_round_off * kappa && step.dt <= tangent_round_off) continue;
    if (step.dk <= curvature_round_off * kappa) step.dk = 0;
    j.curvature_step = true;
    j.v_max = curvature_step_velocity(step, kappa, machine.axes[i], cycle, j.v_max);
  }
  return j;
}

double kink_spacing_velocity(const PathSegment& before, const PathSegment& after, double cycle_s) {
  const double shorter = std::min(before.length(), after.length());
  const double jerk = std::max(before.limits().j, after.limits().j);
  return std::max(0.0, (shorter - 4.5 * jerk * cycle_s * cycle_s * cycle_s) / (3 * cycle_s));
}

double near_tangent_angle(const PathSegment& before, const PathSegment& after) {
  return std::min(before.direction_rounding() + after.direction_rounding(), tolerance::near_tangent_max_rad);
}

}  // namespace hil::cnc
