#include "corner_rule.hpp"

#include <algorithm>
#include <cmath>

#include "bisect.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {
// Unit tangents from a decoder's lines differ by this much when collinear.
constexpr double tangent_round_off = tolerance::direction;
// Curvatures of the same circle, or of a contouring curve's end and the
// path it joins, differ by round-off relative to their size.
constexpr double curvature_round_off = tolerance::curvature_share;

// Whether the tangents agree where `before` meets `after`. On the stack for
// up to 16 axes: the corner rule runs at every block transition, and most
// of a polyline's are corners.
bool same_tangent(const PathSegment& before, const PathSegment& after) {
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
  for (size_t i = 0; i < axes; ++i)
    if (std::abs(t2[i] - t1[i]) > tangent_round_off) return false;
  return true;
}

double norm(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum);
}
}  // namespace

double curvature_step_velocity(double dk, double kappa, double j_max, double cycle_s, double v_cap) {
  const double budget = (1 - curvature_step_jerk_share) * j_max;
  auto fits = [&](double v) { return v * v * dk / cycle_s + v * v * v * kappa * kappa + 6 * kappa * v * cycle_s * j_max <= budget; };
  if (fits(v_cap)) return v_cap;
  return last_fitting(0.0, v_cap, fits);
}

Junction junction(const PathSegment& before, const PathSegment& after, const MachineConfig& machine) {
  if (!same_tangent(before, after)) return {0.0, false};
  // A corner needs no curvatures.
  const std::vector<double> k1 = before.curvature(before.length()), k2 = after.curvature(0);
  Junction j{std::min(before.limits().v, after.limits().v), false};
  const double kappa = std::max(norm(k1), norm(k2));
  const double cycle = machine.cycle_time_s();
  for (size_t i = 0; i < k1.size(); ++i) {
    // An axis along the tangent has no share of the curvature but round-off.
    const double dk = std::abs(k2[i] - k1[i]);
    if (dk <= curvature_round_off * kappa) continue;
    j.curvature_step = true;
    j.v_max = curvature_step_velocity(dk, kappa, machine.axes[i].j_max, cycle, j.v_max);
  }
  return j;
}

}  // namespace hil::cnc
