#include "contour_fit.hpp"

#include <algorithm>

#include "axis_vector.hpp"

namespace hil::cnc::contour_fit {

bool tangent_break(const std::vector<double>& t1, const std::vector<double>& t2) {
  for (size_t i = 0; i < t1.size(); ++i)
    if (std::abs(t2[i] - t1[i]) > tolerance::direction) return true;
  return false;
}
bool curvature_step(const std::vector<double>& k1, const std::vector<double>& k2) {
  const double kappa = std::max(norm(k1), norm(k2));
  for (size_t i = 0; i < k1.size(); ++i)
    if (std::abs(k2[i] - k1[i]) > tolerance::curvature_share * kappa) return true;
  return false;
}
bool needs_curve(const PathSegment& a, const PathSegment& b) {
  return tangent_break(a.tangent(a.length()), b.tangent(0)) || curvature_step(a.curvature(a.length()), b.curvature(0));
}

double deviation(const ContourCurve& curve, const PathSegment& a, double a_from, const PathSegment& b, double b_to) {
  constexpr int samples = 32;
  double worst = 0;
  for (int k = 1; k < samples; ++k) {
    const std::vector<double> q = curve.position(curve.length() * k / samples);
    const double on_a = std::clamp(a.length_to(q), a_from, a.length());
    const double on_b = std::clamp(b.length_to(q), 0.0, b_to);
    worst = std::max(worst, std::min(distance(q, a.position(on_a)), distance(q, b.position(on_b))));
  }
  return worst;
}

double deviation_from(const ContourCurve& curve, const PathSegment& block) {
  constexpr int samples = 32;
  double worst = 0;
  for (int k = 1; k < samples; ++k) {
    const std::vector<double> q = curve.position(curve.length() * k / samples);
    worst = std::max(worst, distance(q, block.position(std::clamp(block.length_to(q), 0.0, block.length()))));
  }
  return worst;
}

bool fits_block(const ContourCurve& curve, const PathSegment& block, double d, const Corner& corner, double budget) {
  return curve.length() <= d * longest_share &&
         (corner.mode.type != ContourMode::Type::dev || deviation_from(curve, block) <= budget);
}

}  // namespace hil::cnc::contour_fit
