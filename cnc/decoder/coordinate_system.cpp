#include "coordinate_system.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "value_ranges.hpp"
#include "tolerances.hpp"

namespace hil::cnc {

CoordinateSystem CoordinateSystem::parse(const std::string& components, const ParameterValues& parameters) {
  std::array<double, 6> value{};
  size_t index = 0, begin = 0;
  for (;;) {
    const size_t comma = components.find(',', begin);
    const std::string part = components.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    if (index == value.size()) throw std::invalid_argument("#CS takes at most 6 components v1,v2,v3,φ1,φ2,φ3");
    if (part.find_first_not_of(' ') != std::string::npos) value[index] = evaluate_expression(part, parameters);
    ++index;
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  for (size_t k = 0; k < 3; ++k) decoding::checked_length(value[k], "#CS offset v" + std::to_string(k + 1));
  for (size_t k = 3; k < 6; ++k)
    if (!(std::abs(value[k]) <= decoding::max_cs_angle_deg))
      throw std::invalid_argument("#CS angle φ" + std::to_string(k - 2) + " must be within ±" +
                                  std::to_string(static_cast<int>(decoding::max_cs_angle_deg)) + "°");
  constexpr double degree = M_PI / 180.0;
  CoordinateSystem cs;
  cs.transform_ = Eigen::Translation3d(value[0], value[1], value[2]) *
                  Eigen::AngleAxisd(value[5] * degree, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(value[4] * degree, Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(value[3] * degree, Eigen::Vector3d::UnitX());
  return cs;
}

bool CoordinateSystem::keeps_xy_plane() const { return keeps_axis(2); }

bool CoordinateSystem::keeps_axis(int k) const { return std::abs(transform_.linear()(k, k) - 1.0) < tolerance::direction; }

}  // namespace hil::cnc
