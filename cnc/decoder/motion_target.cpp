#include "motion_target.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {
namespace {

int main_axis(const DecoderState& state, int k) { return state.machine.axis_index(std::string(1, "XYZ"[k])); }

// Main axes of a machine position in the active #CS, and back.
Eigen::Vector3d to_program(const DecoderState& state, const AxisValues& machine) {
  Eigen::Vector3d workpiece;
  for (int k = 0; k < 3; ++k) workpiece[k] = machine[main_axis(state, k)] - state.offset[main_axis(state, k)];
  return state.cs->to_program(workpiece);
}
Eigen::Vector3d to_machine(const DecoderState& state, const Eigen::Vector3d& program) {
  Eigen::Vector3d machine = state.cs->to_workpiece(program);
  for (int k = 0; k < 3; ++k) machine[k] += state.offset[main_axis(state, k)];
  return machine;
}

// G165: the nearest centre on the perpendicular bisector of start and end.
void correct_centre(Motion& m, int x, int y) {
  const double chord_x = m.end[x] - m.start[x], chord_y = m.end[y] - m.start[y];
  const double chord = std::hypot(chord_x, chord_y);
  if (!(chord > 1e-9)) return;  // a full circle (end = start) has no bisector
  const double mid_x = (m.start[x] + m.end[x]) / 2, mid_y = (m.start[y] + m.end[y]) / 2;
  const double nx = -chord_y / chord, ny = chord_x / chord;
  const double along = (m.center_x - mid_x) * nx + (m.center_y - mid_y) * ny;
  m.center_x = mid_x + along * nx;
  m.center_y = mid_y + along * ny;
}

void check_on_circle(const Motion& m, int x, int y) {
  const double r_start = std::hypot(m.start[x] - m.center_x, m.start[y] - m.center_y);
  const double r_end = std::hypot(m.end[x] - m.center_x, m.end[y] - m.center_y);
  if (r_start < 1e-6) throw LineError{"arc radius is zero"};
  checked_length(r_start, "arc radius");
  if (std::abs(r_start - r_end) > 1e-3 + 1e-6 * r_start) {
    std::ostringstream msg;
    msg << "arc end point does not lie on the circle (start radius " << r_start << " mm, end radius " << r_end
        << " mm; G165 corrects the centre)";
    throw LineError{msg.str()};
  }
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
    if (axis_words[main_axis(state, k)]) point[k] = programmed(point[k], *axis_words[main_axis(state, k)]);
  const Eigen::Vector3d machine = to_machine(state, point);
  for (int k = 0; k < 3; ++k) {
    const int a = main_axis(state, k);
    target[a] = std::abs(machine[k] - position[a]) > 1e-9 ? machine[k] : position[a];
  }
  return target;
}

void set_arc_centre(Motion& m, std::optional<double> i, std::optional<double> j, const DecoderState& state) {
  const int x = state.machine.axis_index("X"), y = state.machine.axis_index("Y");
  if (x < 0 || y < 0) throw LineError{"G02/G03 need axes X and Y (plane G17)"};
  if (!i && !j) throw LineError{"G02/G03 need the centre I/J (R is not supported yet)"};
  const AxisValues& offset = state.offset;
  if (state.cs) {
    if (!state.cs->keeps_xy_plane())
      throw LineError{"G02/G03 in a #CS rotated out of the XY plane are not supported yet"};
    const Eigen::Vector3d start = to_program(state, m.start);
    const Eigen::Vector3d centre =
        state.modal.centre_absolute
            ? Eigen::Vector3d(i.value_or(start.x()), j.value_or(start.y()), start.z())
            : Eigen::Vector3d(start.x() + i.value_or(0), start.y() + j.value_or(0), start.z());
    const Eigen::Vector3d machine = to_machine(state, centre);
    m.center_x = machine.x();
    m.center_y = machine.y();
  } else if (state.modal.centre_absolute) {  // G161: in program coordinates
    m.center_x = i.value_or(m.start[x] - offset[x]) + offset[x];
    m.center_y = j.value_or(m.start[y] - offset[y]) + offset[y];
  } else {
    m.center_x = m.start[x] + i.value_or(0);
    m.center_y = m.start[y] + j.value_or(0);
  }
  if (state.modal.centre_correction) correct_centre(m, x, y);
  checked_length(m.center_x, "arc centre X");
  checked_length(m.center_y, "arc centre Y");
  check_on_circle(m, x, y);
}

}  // namespace hil::cnc::decoding
