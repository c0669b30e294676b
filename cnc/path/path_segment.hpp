#pragma once
// Geometry of one motion block (line, or helical arc in the G17/G18/G19 plane) over
// its path length s, and the path limits (velocity, acceleration, jerk)
// under which every axis stays within its own limits (KRN-3).
// Path positions s run from 0 at the start to length() at the end.
#include <array>
#include <memory>
#include <vector>

#include "block.hpp"
#include "contour_curve.hpp"
#include "machine_config.hpp"
#include "slope.hpp"

namespace hil::cnc {

// X, Y or Z: a main axis (DPS-1, PATH_DEV); without std::string's compare
// (every block asks, for every axis).
bool is_main_axis(const std::string& name);

// The machine axes of an arc's plane (Motion::plane; -1: X and Y, G17).
std::array<int, 2> arc_plane_axes(const Motion& motion, const MachineConfig& machine);

class PathSegment {
 public:
  PathSegment(const Motion& motion, const MachineConfig& machine);
  // A part [s_from, s_to] of a contouring curve (KRN-6), from s_to to
  // s_from if `reversed`; its programmed velocity and covered distance are
  // those of the halves it lies on.
  PathSegment(std::shared_ptr<const ContourJoint> joint, double s_from, double s_to, bool reversed,
              const MachineConfig& machine);

  double length() const { return length_; }
  // Dynamic limits of the path from the axes' limits (G00: v from the rapid
  // velocities); the programmed feed is not one of them.
  const Limits& limits() const { return limits_; }
  // The path velocity programmed: F, or for G00 the rapid limit.
  double programmed_velocity() const { return programmed_velocity_; }
  // What the block adds to the distance from program start (DPS-1): its
  // path length over the main axes X Y Z; without main axis motion, the
  // travel of the axis that moves at its dynamic limit.
  double covered_distance() const { return covered_distance_; }
  // A part of a programmed block covers its share of it (KRN-6).
  void set_covered_distance(double distance) { covered_distance_ = distance; }
  bool is_contour_curve() const { return joint_ != nullptr; }
  bool is_arc() const { return arc_; }
  // Of a contouring curve's part: the curve, and where path length s of the
  // part lies on it.
  const std::shared_ptr<const ContourJoint>& joint() const { return joint_; }
  double curve_position(double s) const { return reversed_ ? s_from_ + length_ - s : s_from_ + s; }
  bool reversed() const { return reversed_; }
  const AxisValues& end() const { return end_; }

  // Axis positions at path length s; first and second derivatives by s.
  std::vector<double> position(double s) const;
  std::vector<double> tangent(double s) const;
  // The same into t[0 .. axes): without allocating, for the corner rule
  // at every block transition.
  void tangent(double s, double* t) const;
  std::vector<double> curvature(double s) const;
  // Position, tangent and curvature at s: a contouring curve's end there.
  ContourCurve::End curve_end(double s) const { return {position(s), tangent(s), curvature(s)}; }
  // How far its tangent at either end may be off the one the programmer
  // meant, by the program's rounding (rad): its end points' rounding
  // across its length and, of an arc, an end radius off its start radius
  // (a spiral, within the end point tolerance). 0 for a contouring curve.
  double direction_rounding() const;
  // Of a line or arc: the path length s at which the motion passes the
  // point nearest to `point` along it (a line's projection, an arc's
  // angle), in [0, length] where the point lies within the motion's span,
  // above length where an arc's angle lies beyond its end. Whether the
  // point lies on the motion is the caller's: compare position(s).
  double length_to(const AxisValues& point) const;

 private:
  double angle_at(double s) const { return angle0_ + direction_ * sweep_ * s / length_; }
  double radius_at(double s) const { return radius_ + (radius_end_ - radius_) * s / length_; }
  void set_line_limits(const Motion& motion, const MachineConfig& machine);
  void set_arc_limits(const Motion& motion, const MachineConfig& machine);
  void set_covered_distance(const MachineConfig& machine);
  void set_contour_limits(const MachineConfig& machine, double programmed_velocity);
  void widen_on_a_gentle_curve(double k, double dk, double v_drive, double a_axis, double j_axis);

  bool arc_ = false;
  AxisValues start_, end_, unit_;  // unit_: d(axis)/ds of the linear axes
  int ix_ = -1, iy_ = -1;                   // arc plane axes
  double cx_ = 0, cy_ = 0, radius_ = 0, radius_end_ = 0, angle0_ = 0;
  double sweep_ = 0;      // rad, > 0 along the direction
  double direction_ = 1;  // +1 counter-clockwise (G03), -1 clockwise (G02)
  double planar_ = 0;     // share of the path length in the arc's plane (bounds |d(x, y)/ds|)
  double length_ = 0;
  double programmed_velocity_ = 0;
  double covered_distance_ = 0;
  Limits limits_;
  std::shared_ptr<const ContourJoint> joint_;  // a contouring curve's part from s_from_
  double s_from_ = 0;
  bool reversed_ = false;
};

}  // namespace hil::cnc
