#include "assignments.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include "line_cursor.hpp"
#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {
namespace {

// What the left side of an assignment names: P<n>, the pre-output path of
// M<m>, or axis `axis` of zero offset `zero_offset` (1..6: G54..G59).
struct AssignmentTarget {
  std::optional<int64_t> parameter, m_function, zero_offset;
  int axis = -1;
};

// P<n>, V.G.M_FCT[<m>].PRE_OUTP_PATH or V.G.NP[<1..6>].V.<axis> after an
// optional N number, and nothing else; a number out of range or an axis
// the machine lacks is none.
AssignmentTarget assignment_target(std::string_view left, const DecoderState& state) {
  LineCursor cursor(left);
  cursor.skip_block_nr();
  AssignmentTarget target;
  if (cursor.take_keyword("V.G.NP")) {  // V.G.NP[<n>].V.<axis> (TF5200 "Zero offsets")
    if (!cursor.take('[')) return {};
    cursor.skip_blanks();
    const std::optional<int64_t> group = whole_number(cursor.take_digits(), 6);
    if (!group || *group < 1 || !(cursor.take(']') && cursor.take('.') && cursor.take('V') && cursor.take('.'))) return {};
    cursor.skip_blanks();
    const std::string_view axis = cursor.rest();
    const size_t end = axis.find_first_of(" \t");
    const std::string name = upper_words(axis.substr(0, end));
    target.axis = state.machine.axis_index(name);
    if (target.axis < 0) return {};
    LineCursor after(axis.substr(name.size()));
    if (!after.at_end()) return {};
    target.zero_offset = group;
    return target;
  }
  if (cursor.take_keyword("V.G.M_FCT")) {
    if (!cursor.take('[')) return {};
    cursor.skip_blanks();
    target.m_function = whole_number(cursor.take_digits(), max_m_function);
    if (!cursor.take_keyword("].PRE_OUTP_PATH")) return {};
  } else if (cursor.take('P')) {
    target.parameter = whole_number(cursor.take_digits(), max_p_parameter);
  }
  if (!cursor.at_end()) return {};
  return target;
}

}  // namespace

void assign_parameter(std::string_view code, size_t equals, DecoderState& state) {
  const AssignmentTarget target = assignment_target(code.substr(0, equals), state);
  if (!target.parameter && !target.m_function && !target.zero_offset)
    throw LineError{"'=' is only allowed in P<n> = <expression> (n 0.." + std::to_string(max_p_parameter) +
                    "), V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm> and V.G.NP[<1..6>].V.<axis> = <mm>"};
  double value = 0;
  try {
    value = state.evaluate(std::string(code.substr(equals + 1)));
  } catch (const std::invalid_argument& e) {
    throw LineError{e.what()};
  }
  if (target.parameter) {
    state.parameters[static_cast<int>(*target.parameter)] = value;
  } else if (target.zero_offset) {
    // G54..G59's table entry (mm, inch under G70): from this line on.
    const size_t axis = static_cast<size_t>(target.axis), table = static_cast<size_t>(*target.zero_offset - 1);
    const double unit = state.modal.inch && !state.machine.axes[axis].rotary() ? mm_per_inch : 1.0;
    state.zero_offset_tables[table][axis] = checked_length(value * unit, "zero offset");
    state.update_offset();
  } else {
    if (value < 0) throw LineError{"PRE_OUTP_PATH must be >= 0 mm"};
    state.pre_output_mm[static_cast<int>(*target.m_function)] = checked_length(value, "PRE_OUTP_PATH");
  }
}

}  // namespace hil::cnc::decoding
