#include "corner_rule.hpp"

#include <algorithm>
#include <cmath>

namespace hil::cnc {
namespace {
// Unit tangents from a decoder's lines differ by this much when collinear.
constexpr double tangent_round_off = 1e-12;
}  // namespace

Junction junction(const PathSegment& before, const PathSegment& after, const MachineConfig& machine) {
  const std::vector<double> t1 = before.tangent(before.length()), t2 = after.tangent(0);
  const std::vector<double> k1 = before.curvature(before.length()), k2 = after.curvature(0);
  Junction j{std::min(before.limits().v, after.limits().v), false};
  double dk_max = 0;
  for (size_t i = 0; i < t1.size(); ++i) {
    if (std::abs(t2[i] - t1[i]) > tangent_round_off) return {0.0, false};
    dk_max = std::max(dk_max, std::abs(k2[i] - k1[i]));
  }
  const double cycle = machine.cycle_time_s();
  for (size_t i = 0; i < t1.size(); ++i) {
    // An axis along the tangent has no share of the curvature but round-off.
    const double dk = std::abs(k2[i] - k1[i]);
    if (dk <= tangent_round_off * dk_max) continue;
    j.curvature_step = true;
    j.v_max = std::min(j.v_max, std::sqrt(machine.axes[i].j_max * cycle / (6 * dk)));
  }
  return j;
}

}  // namespace hil::cnc
