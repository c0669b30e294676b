#pragma once
// Vectors over a channel's axes (positions, unit tangents, curvatures): the
// few operations the path geometry needs, in one place.
#include <cmath>
#include <cstddef>
#include <vector>

namespace hil::cnc {

inline double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

inline double norm(const std::vector<double>& v) { return std::sqrt(dot(v, v)); }

inline double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

}  // namespace hil::cnc
