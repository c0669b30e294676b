#pragma once
// A machining coordinate system (#CS ON [v1,v2,v3,φ1,φ2,φ3], #CS OFF):
// program coordinates offset by v and rotated against the workpiece
// coordinates, rotation sequence ZYX (P-CHAN-00394's default: φ3 about Z,
// then φ2 about the new Y, then φ1 about the new X), angles in degrees.
// It acts on the main axes X, Y, Z.
#include <string>

#include <Eigen/Geometry>

#include "parameter_expression.hpp"

namespace hil::cnc {

class CoordinateSystem {
 public:
  // `components`: what stands between the brackets, "10,0,0,0,0,45";
  // missing or empty components are 0. Throws std::invalid_argument.
  static CoordinateSystem parse(const std::string& components, const ParameterValues& parameters);

  Eigen::Vector3d to_workpiece(const Eigen::Vector3d& program) const { return transform_ * program; }
  Eigen::Vector3d to_program(const Eigen::Vector3d& workpiece) const { return transform_.inverse() * workpiece; }
  // Only rotated about Z: arcs in the XY plane (G17) stay in it.
  bool keeps_xy_plane() const;
  // Main axis k (0 X, 1 Y, 2 Z) keeps its direction: the rotation is
  // about it only (LIFT-6: a lift axis may not be affected, error 21071).
  bool keeps_axis(int k) const;

 private:
  Eigen::Isometry3d transform_ = Eigen::Isometry3d::Identity();
};

}  // namespace hil::cnc
