#include "line_decoder.hpp"

#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "lift_commands.hpp"
#include "line_cursor.hpp"
#include "motion_target.hpp"
#include "nc_commands.hpp"
#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {
namespace {

// What the words of a block program: G92 and the motion act only once all
// of them are read.
struct BlockWords {
  explicit BlockWords(std::vector<std::optional<double>>& axis_words) : axes(axis_words) {}
  std::vector<std::optional<double>>& axes;  // per machine axis (DecoderState::buffers, refilled)
  std::optional<double> i, j;               // arc centre
  std::optional<MotionType> motion;         // G00..G03 of this block
  bool position_preset = false;             // G92: the axis words name the current position
  std::optional<int> transition;            // G60, G61, G260, G261, G359 or G360 (KRN-6)
  std::optional<int> run;                   // G74 (homing) or G100 (measurement): this block only
};

int axis_of(const Word& w, const DecoderState& state) {
  const int axis = state.axis_of_letter(w.letter);
  if (axis < 0) throw LineError{"'" + w.text() + "': " + w.letter + " is not an axis of this machine"};
  return axis;
}

// Modal G codes act at once; the motion G code waits for G92's check.
void apply_g_code(const Word& w, ModalState& modal, BlockWords& programmed) {
  const int g = static_cast<int>(integer_code(w, max_g_code));
  if (g <= 3) {
    if (programmed.motion) throw LineError{"two motion G codes in one block"};
    programmed.motion = static_cast<MotionType>(g);
  } else if (g == 90 || g == 91) {
    modal.absolute = g == 90;
  } else if (g == 92) {
    programmed.position_preset = true;
  } else if (g == 74 || g == 100) {
    if (programmed.run) throw LineError{"two of G74 / G100 in one block"};
    programmed.run = g;
  } else if (g == 161 || g == 162) {
    modal.centre_absolute = g == 161;
  } else if (g == 164 || g == 165) {
    modal.centre_correction = g == 165;
  } else if (g == 60 || g == 61 || g == 260 || g == 261 || g == 359 || g == 360) {
    if (programmed.transition)
      throw LineError{"G" + std::to_string(*programmed.transition) + " and '" + w.text() +
                          "': two block transition G functions in one block",
                      20117};
    programmed.transition = g;
    if (g == 261) modal.transition = BlockTransition::contour;
    if (g == 360) modal.transition = BlockTransition::exact_stop;
    if (g == 260 && modal.transition == BlockTransition::contour) modal.transition = BlockTransition::standard;
    if (g == 359 && modal.transition == BlockTransition::exact_stop) modal.transition = BlockTransition::standard;
  } else {
    throw LineError{"G code '" + w.text() + "' is not supported yet"};
  }
}

void add_m_function(const Word& w, const DecoderState& state, Block& block) {
  const int m = static_cast<int>(integer_code(w, max_m_function));
  if (m == 30) {
    block.program_end = true;
    return;
  }
  if (m == 0 || m == 1) {  // M00 / M01: the channel's own stop (ISC-5), not output to the PLC
    if (block.programmed_stop) throw LineError{"two of M00 / M01 in one block"};
    block.programmed_stop = m;
    return;
  }
  const auto pre_output = state.pre_output_mm.find(m);
  block.m_functions.push_back({m, pre_output == state.pre_output_mm.end() ? 0.0 : pre_output->second});
}

// F in mm/min, within [min_feed_mm_min, max_feed_mm_min].
double feed_mm_s(const Word& w) {
  if (!(w.value >= min_feed_mm_min && w.value <= max_feed_mm_min)) {
    std::ostringstream msg;
    msg << std::setprecision(10) << "feed '" << w.text() << "' is out of range " << min_feed_mm_min << " .. "
        << max_feed_mm_min << " mm/min";
    throw LineError{msg.str()};
  }
  return w.value / 60.0;
}

void apply_word(const Word& w, bool first, DecoderState& state, BlockWords& programmed, Block& block) {
  if (w.is_axis_command()) {
    decode_axis_command(w, axis_of(w, state), state, block);
    return;
  }
  switch (w.letter) {
    case 'N':
      if (!first) throw LineError{"'" + w.text() + "' must be the first word of the block"};
      block.block_nr = integer_code(w, max_block_nr);
      break;
    case 'G': apply_g_code(w, state.modal, programmed); break;
    case 'F': state.modal.feed = feed_mm_s(w); break;
    case 'M': add_m_function(w, state, block); break;
    case 'I': programmed.i = checked_length(w.value, "I"); break;
    case 'J': programmed.j = checked_length(w.value, "J"); break;
    default: {
      const int axis = axis_of(w, state);
      if (programmed.axes[axis]) throw LineError{std::string("axis ") + w.letter + " programmed twice"};
      programmed.axes[axis] = checked_length(w.value, std::string_view(&w.letter, 1));
    }
  }
}

BlockWords apply_words(const std::vector<Word>& words, DecoderState& state, Block& block) {
  BlockWords programmed(state.buffers.axis_words);
  programmed.axes.assign(state.machine.axes.size(), std::nullopt);
  for (size_t k = 0; k < words.size(); ++k) apply_word(words[k], k == 0, state, programmed, block);
  return programmed;
}

// G92: the current position gets the programmed coordinates; nothing moves.
void preset_position(const BlockWords& programmed, DecoderState& state) {
  if (programmed.motion || programmed.run || programmed.i || programmed.j)
    throw LineError{"G92 must not be combined with motion"};
  if (state.cs) throw LineError{"G92 while a #CS is active is not supported yet"};
  for (size_t a = 0; a < programmed.axes.size(); ++a)
    if (programmed.axes[a]) state.offset[a] = state.position[a] - *programmed.axes[a];
}

// G74 homing run and G100 measurement run: motions ended by an external
// signal (DPS-3), non-modal, ending at standstill. The rig simulates the
// signal: G74 moves the named axes together as a rapid to their reference
// points (machine file `reference_position`; the words' values, TwinCAT's
// homing order, are not used), G100 moves linearly at F to the programmed
// point (no probe input: the run ends there). Block search by distance
// cannot simulate them: not_searchable. Both need channel initialisation
// (TF5200_delete_distance_to_go.txt 2.5, DDTG-8): the path stands still
// before them, and a short cut's search for its end marker ends there.
void decode_run(const BlockWords& programmed, DecoderState& state, Block& block) {
  const std::string name = "G" + std::to_string(*programmed.run);
  if (programmed.motion) throw LineError{name + " cannot be combined with G00 / G01 / G02 / G03"};
  if (programmed.i || programmed.j) throw LineError{"I/J are only allowed with G02/G03"};
  block.not_searchable = name;
  block.short_cut_restriction = ShortCutRestriction::channel_initialisation;
  const bool homing = *programmed.run == 74;
  AxisValues target = state.position;
  if (homing) {
    bool named = false;
    for (size_t a = 0; a < programmed.axes.size(); ++a) {
      if (!programmed.axes[a]) continue;
      target[a] = state.machine.axes[a].reference_position;
      named = true;
    }
    if (!named) throw LineError{"G74 needs the axes to home, e.g. G74 X1 Y2"};
  } else {
    target = programmed_target(programmed.axes, state);
  }
  check_position(target, state.machine, "end point");
  if (!homing && !(state.modal.feed > 0)) throw LineError{"no feed F programmed for G100"};
  if (target == state.position) return;  // the signal comes where the axes stand
  block.has_motion = true;
  Motion& m = block.motion;
  m.type = homing ? MotionType::rapid : MotionType::linear;
  m.start = state.position;
  m.end = target;
  m.feed = state.modal.feed;
  block.slope = state.modal.slope;
  block.transition = BlockTransition::exact_stop;
  block.contour = state.modal.contour;
  state.position = target;
}

// A block whose axes do not move is no motion block.
void decode_motion(const BlockWords& programmed, DecoderState& state, Block& block) {
  if (programmed.run) return decode_run(programmed, state, block);
  ModalState& modal = state.modal;
  if (programmed.motion) modal.motion = *programmed.motion;
  AxisValues target = programmed_target(programmed.axes, state);
  check_position(target, state.machine, "end point");  // after G91, G92 and #CS: each word may be in range, the sum not
  const bool is_arc = modal.motion == MotionType::arc_cw || modal.motion == MotionType::arc_ccw;
  const bool has_centre = programmed.i || programmed.j;
  if (has_centre && !is_arc) throw LineError{"I/J are only allowed with G02/G03"};
  const bool full_circle = is_arc && has_centre;  // end = start
  if (target == state.position && !full_circle) return;
  block.has_motion = true;
  Motion& m = block.motion;
  m.type = modal.motion;
  m.start = state.position;
  m.end = std::move(target);
  block.slope = modal.slope;
  // G60 / G61 act on this block's end only (KRN-6).
  block.transition = programmed.transition == 60   ? BlockTransition::exact_stop
                     : programmed.transition == 61 ? BlockTransition::contour
                                                   : modal.transition;
  block.contour = modal.contour;
  if (m.type != MotionType::rapid && !(modal.feed > 0)) throw LineError{"no feed F programmed for G01/G02/G03"};
  m.feed = modal.feed;  // G00 too: a short cut to its end runs at it (DDTG-2)
  if (is_arc) set_arc_centre(m, programmed.i, programmed.j, state);
  state.position = m.end;
}

// A '#' command is the whole block, after an optional N number.
void decode_command_block(std::string_view code, size_t hash, DecoderState& state, Block& block) {
  const std::vector<Word> before = split_words(code.substr(0, hash));
  const bool n_only =
      before.empty() || (before.size() == 1 && before[0].letter == 'N' && !before[0].is_axis_command());
  if (!n_only) throw LineError{"a '#' command must stand alone in its block (after the N number)"};
  if (!before.empty()) block.block_nr = integer_code(before[0], max_block_nr);
  decode_nc_command(upper_words(code.substr(hash)), state, block);
}

// What the left side of an assignment names: P<n>, or the pre-output
// path of M<m>.
struct AssignmentTarget {
  std::optional<int64_t> parameter, m_function;
};

// P<n> or V.G.M_FCT[<m>].PRE_OUTP_PATH after an optional N number, and
// nothing else; either number out of range is none.
AssignmentTarget assignment_target(std::string_view left) {
  LineCursor cursor(left);
  cursor.skip_block_nr();
  AssignmentTarget target;
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

// P<n> = <expression> (a decoder variable) or
// V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm> (P-CHAN-00070 for M<m> from here
// on), after an optional N number. Decoder work: no block.
void assign_parameter(std::string_view code, size_t equals, DecoderState& state) {
  const AssignmentTarget target = assignment_target(code.substr(0, equals));
  if (!target.parameter && !target.m_function)
    throw LineError{"'=' is only allowed in P<n> = <expression> (n 0.." + std::to_string(max_p_parameter) +
                    ") and V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm>"};
  double value = 0;
  try {
    value = state.evaluate(std::string(code.substr(equals + 1)));
  } catch (const std::invalid_argument& e) {
    throw LineError{e.what()};
  }
  if (target.parameter) {
    state.parameters[static_cast<int>(*target.parameter)] = value;
  } else {
    if (value < 0) throw LineError{"PRE_OUTP_PATH must be >= 0 mm"};
    state.pre_output_mm[static_cast<int>(*target.m_function)] = checked_length(value, "PRE_OUTP_PATH");
  }
}

}  // namespace

bool decode_line(std::string_view line, int64_t line_nr, int64_t lines_read, DecoderState& state,
                 std::vector<Block>& out) {
  const std::string_view code = without_comments(line, state.buffers.code);
  const size_t first = code.find_first_not_of(" \t\r");
  if (first == std::string::npos || code[first] == '%') return true;  // empty, or the program name
  if (const size_t hash = code.find('#'); hash != std::string::npos) {
    Block block;
    block.nc_line = line_nr;
    block.block_count = lines_read;
    decode_command_block(code, hash, state, block);
    const bool lift = block.lift_start || block.lift_end;
    if (block.has_command()) out.push_back(std::move(block));
    if (lift) record_lift_block(state, out);
    return true;
  }
  if (const size_t dollar = code.find('$'); dollar != std::string::npos) throw unsupported_command(code, dollar);
  if (const size_t equals = find_assignment(code); equals != std::string::npos) {
    assign_parameter(code, equals, state);
    return true;
  }
  split_words(code, state.buffers.words);
  const std::vector<Word>& words = state.buffers.words;
  // Made in place (a Block is large to move), taken back if the line turns
  // out to command nothing or to be in error.
  Block& block = out.emplace_back();
  block.nc_line = line_nr;
  block.block_count = lines_read;
  try {
    const BlockWords programmed = apply_words(words, state, block);
    // G92's M functions (and M30) are the block's, as with any other block.
    if (programmed.position_preset) preset_position(programmed, state);
    else decode_motion(programmed, state, block);
    finish_lift_block(words, programmed.axes, programmed.position_preset, state, block);
  } catch (...) {
    out.pop_back();
    throw;
  }
  const bool lift = block.lift_start || block.lift_end, end = block.program_end;
  if (!block.has_motion && !block.has_command()) out.pop_back();
  if (lift) record_lift_block(state, out);
  return !end;
}

}  // namespace hil::cnc::decoding
