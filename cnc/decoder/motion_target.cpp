#include "motion_target.hpp"

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "value_ranges.hpp"
#include "words.hpp"
#include "tolerances.hpp"

namespace hil::cnc::decoding {
namespace {

int main_axis(const DecoderState& state, int k) { return state.machine.axis_index(std::string(1, "XYZ"[k])); }
// An index known to be one (>= 0).
size_t at(int i) { return static_cast<size_t>(i); }

// The main axes of a machine position in program coordinates (zero
// offsets, G92, the active #CS), and back; a main axis the machine lacks
// is 0.
Eigen::Vector3d to_program(const DecoderState& state, const AxisValues& machine) {
  Eigen::Vector3d workpiece = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (const int a = main_axis(state, k); a >= 0) workpiece[k] = machine[at(a)] - state.offset[at(a)];
  return state.cs ? state.cs->to_program(workpiece) : workpiece;
}
Eigen::Vector3d to_machine(const DecoderState& state, const Eigen::Vector3d& program) {
  Eigen::Vector3d machine = state.cs ? state.cs->to_workpiece(program) : program;
  for (int k = 0; k < 3; ++k)
    if (const int a = main_axis(state, k); a >= 0) machine[k] += state.offset[at(a)];
  return machine;
}

// G165: the nearest centre on the perpendicular bisector of start and end.
void correct_centre(Motion& m) {
  const size_t x = at(m.plane[0]), y = at(m.plane[1]);
  const double chord_x = m.end[x] - m.start[x], chord_y = m.end[y] - m.start[y];
  const double chord = std::hypot(chord_x, chord_y);
  if (!(chord > tolerance::length_mm)) return;  // a full circle (end = start) has no bisector
  const double mid_x = (m.start[x] + m.end[x]) / 2, mid_y = (m.start[y] + m.end[y]) / 2;
  const double nx = -chord_y / chord, ny = chord_x / chord;
  const double along = (m.center[0] - mid_x) * nx + (m.center[1] - mid_y) * ny;
  m.center[0] = mid_x + along * nx;
  m.center[1] = mid_y + along * ny;
}

void check_on_circle(const Motion& m, const DecoderState& state) {
  const size_t x = at(m.plane[0]), y = at(m.plane[1]);
  const double r_start = std::hypot(m.start[x] - m.center[0], m.start[y] - m.center[1]);
  const double r_end = std::hypot(m.end[x] - m.center[0], m.end[y] - m.center[1]);
  if (r_start < tolerance::no_length_mm) throw LineError{"arc radius is zero"};
  checked_length(r_start, "arc radius");
  const double limit = state.machine.radius_difference_limit(r_start);
  if (std::abs(r_start - r_end) > limit) {
    std::ostringstream msg;
    msg << std::setprecision(10) << "maximum difference between radii exceeded: start radius " << r_start
        << " mm, end radius " << r_end << " mm differ by " << std::abs(r_start - r_end) << " mm, more than the "
        << limit << " mm P-CHAN-00171 max_radius_diff_circle / P-CHAN-00172 max_proz_radius_diff_circle allow"
        << " (the end point lies off the circle; G165 corrects the centre)";
    throw LineError{msg.str(), 21758};
  }
}

// Where a plane's main axes are: G17 X Y, G18 Z X, G19 Y Z, and the
// normal (main axis numbers, 0 X 1 Y 2 Z).
struct PlaneAxes {
  int first, second, normal;
};
PlaneAxes plane_axes(Plane plane) {
  switch (plane) {
    case Plane::g18: return {2, 0, 1};
    case Plane::g19: return {1, 2, 0};
    default: return {0, 1, 2};
  }
}

const char* plane_name(Plane plane) { return plane == Plane::g18 ? "G18" : plane == Plane::g19 ? "G19" : "G17"; }

// R: the centre on the bisector of the chord, on the side that makes the
// arc at most 180 degrees for R > 0 and more for R < 0 (TF5200 "Circular
// interpolation").
Eigen::Vector2d centre_by_radius(const Eigen::Vector2d& start, const Eigen::Vector2d& end, double r, bool ccw,
                                 const DecoderState& state) {
  const Eigen::Vector2d chord = end - start;
  const double half = chord.norm() / 2;
  if (!(half > tolerance::length_mm)) throw LineError{"a full circle cannot be programmed with R: give its centre (I J K)"};
  const double radius = std::abs(r);
  if (radius < half - state.machine.radius_difference_limit(radius)) {
    std::ostringstream msg;
    msg << std::setprecision(10) << "R" << r << ": the end point lies " << 2 * half
        << " mm from the start, farther than the diameter " << 2 * radius << " mm";
    throw LineError{msg.str()};
  }
  const double height = std::sqrt(std::max(0.0, radius * radius - half * half));
  const Eigen::Vector2d left(-chord.y() / (2 * half), chord.x() / (2 * half));
  const double side = (ccw ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
  return (start + end) / 2 + side * height * left;
}

}  // namespace

AxisValues programmed_target(const std::vector<std::optional<double>>& axis_words,
                             const DecoderState& state) {
  return programmed_target(axis_words, state, state.modal.absolute);
}

AxisValues programmed_target(const std::vector<std::optional<double>>& axis_words,
                             const DecoderState& state, bool absolute) {
  const AxisValues& position = state.position;
  AxisValues target = position;
  auto programmed = [&](double current, double word) { return absolute ? word : current + word; };
  for (size_t a = 0; a < axis_words.size(); ++a)
    if (axis_words[a]) target[a] = programmed(position[a], *axis_words[a]) + (absolute ? state.offset[a] : 0.0);
  // KRN-7: G90 on a modulo axis goes to the position shifted into the
  // modulo range, the shorter way round (half a revolution: positive); G91
  // may turn several revolutions.
  for (size_t a = 0; a < axis_words.size(); ++a) {
    const AxisConfig& axis = state.machine.axes[a];
    if (!axis_words[a] || !absolute || !axis.modulo) continue;
    const double range = axis.modulo_range();
    double turn = axis.in_modulo_range(target[a]) - axis.in_modulo_range(position[a]);
    if (turn > range / 2) turn -= range;
    else if (turn <= -range / 2) turn += range;
    target[a] = position[a] + turn;
  }
  if (!state.cs) return target;
  // In a #CS one main axis word can move all three main axes.
  Eigen::Vector3d point = to_program(state, position);
  for (int k = 0; k < 3; ++k)
    if (const auto& word = axis_words[at(main_axis(state, k))]) point[k] = programmed(point[k], *word);  // #CS: X Y Z exist
  const Eigen::Vector3d machine = to_machine(state, point);
  for (int k = 0; k < 3; ++k) {
    const size_t a = at(main_axis(state, k));
    target[a] = std::abs(machine[k] - position[a]) > tolerance::length_mm ? machine[k] : position[a];
  }
  return target;
}

void set_arc_centre(Motion& m, const ArcWords& words, const DecoderState& state) {
  const Plane plane = state.modal.plane;
  const PlaneAxes axes = plane_axes(plane);
  const int first = main_axis(state, axes.first), second = main_axis(state, axes.second);
  if (first < 0 || second < 0)
    throw LineError{std::string("G02/G03 in ") + plane_name(plane) + " need axes " + "XYZ"[axes.first] + " and " +
                    "XYZ"[axes.second]};
  m.plane = {first, second};
  const std::array<std::optional<double>, 3> centre_words{words.i, words.j, words.k};
  if (centre_words[at(axes.normal)])
    throw LineError{std::string("'") + "IJK"[axes.normal] + "' is no centre word in " + plane_name(plane) +
                    ": its arcs take " + "IJK"[axes.first] + " and " + "IJK"[axes.second]};
  const bool has_centre = centre_words[at(axes.first)] || centre_words[at(axes.second)];
  if (words.r && has_centre) throw LineError{"an arc takes its centre (I J K) or its radius R, not both"};
  if (!words.r && !has_centre)
    throw LineError{std::string("G02/G03 need the centre ") + "IJK"[axes.first] + " " + "IJK"[axes.second] +
                    " or the radius R"};
  if (state.cs && !state.cs->keeps_axis(axes.normal))
    throw LineError{std::string("G02/G03 in ") + plane_name(plane) +
                    " in a #CS rotated out of that plane are not supported yet"};
  const Eigen::Vector3d start = to_program(state, m.start);
  Eigen::Vector3d centre = start;
  if (words.r) {
    const Eigen::Vector3d end = to_program(state, m.end);
    const Eigen::Vector2d c = centre_by_radius({start[axes.first], start[axes.second]},
                                               {end[axes.first], end[axes.second]}, checked_length(*words.r, "R"),
                                               m.type == MotionType::arc_ccw, state);
    centre[axes.first] = c.x();
    centre[axes.second] = c.y();
  } else {
    for (const int k : {axes.first, axes.second}) {
      const std::optional<double>& word = centre_words[at(k)];
      if (!word) continue;
      // G161: the centre in program coordinates; G162: seen from the start.
      centre[k] = state.modal.centre_absolute ? *word : start[k] + *word;
    }
  }
  const Eigen::Vector3d machine = to_machine(state, centre);
  m.center = {machine[axes.first], machine[axes.second]};
  if (state.modal.centre_correction && !words.r) correct_centre(m);
  checked_length(m.center[0], std::string("arc centre ") + "XYZ"[axes.first]);
  checked_length(m.center[1], std::string("arc centre ") + "XYZ"[axes.second]);
  check_on_circle(m, state);
}

}  // namespace hil::cnc::decoding
