#include "line_decoder.hpp"

#include <cstdlib>
#include <optional>
#include <regex>
#include <stdexcept>

#include "motion_target.hpp"
#include "nc_commands.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {
namespace {

// What the words of a block program: G92 and the motion act only once all
// of them are read.
struct BlockWords {
  std::vector<std::optional<double>> axes;  // per machine axis
  std::optional<double> i, j;               // arc centre
  std::optional<MotionType> motion;         // G00..G03 of this block
  bool position_preset = false;             // G92: the axis words name the current position
};

int axis_of(const Word& w, const MachineConfig& machine) {
  const int axis = machine.axis_index(std::string(1, w.letter));
  if (axis < 0) throw LineError{"'" + w.text + "': " + w.letter + " is not an axis of this machine"};
  return axis;
}

// Modal G codes act at once; the motion G code waits for G92's check.
void apply_g_code(const Word& w, ModalState& modal, BlockWords& programmed) {
  const int g = integer_code(w);
  if (g <= 3) {
    if (programmed.motion) throw LineError{"two motion G codes in one block"};
    programmed.motion = static_cast<MotionType>(g);
  } else if (g == 90 || g == 91) {
    modal.absolute = g == 90;
  } else if (g == 92) {
    programmed.position_preset = true;
  } else if (g == 161 || g == 162) {
    modal.centre_absolute = g == 161;
  } else if (g == 164 || g == 165) {
    modal.centre_correction = g == 165;
  } else {
    throw LineError{"G code '" + w.text + "' is not supported yet"};
  }
}

void add_m_function(const Word& w, const DecoderState& state, Block& block) {
  const int m = integer_code(w);
  if (m == 30) {
    block.program_end = true;
    return;
  }
  const auto pre_output = state.pre_output_mm.find(m);
  block.m_functions.push_back({m, pre_output == state.pre_output_mm.end() ? 0.0 : pre_output->second});
}

void apply_word(const Word& w, bool first, DecoderState& state, BlockWords& programmed, Block& block) {
  if (w.is_axis_command()) {
    decode_axis_command(w, axis_of(w, state.machine), state, block);
    return;
  }
  switch (w.letter) {
    case 'N':
      if (!first) throw LineError{"'" + w.text + "' must be the first word of the block"};
      block.block_nr = integer_code(w);
      break;
    case 'G': apply_g_code(w, state.modal, programmed); break;
    case 'F':
      if (!(w.value > 0)) throw LineError{"feed '" + w.text + "' must be > 0"};
      state.modal.feed = w.value / 60.0;  // F is mm/min
      break;
    case 'M': add_m_function(w, state, block); break;
    case 'I': programmed.i = w.value; break;
    case 'J': programmed.j = w.value; break;
    default: {
      const int axis = axis_of(w, state.machine);
      if (programmed.axes[axis]) throw LineError{std::string("axis ") + w.letter + " programmed twice"};
      programmed.axes[axis] = w.value;
    }
  }
}

BlockWords apply_words(const std::vector<Word>& words, DecoderState& state, Block& block) {
  BlockWords programmed;
  programmed.axes.resize(state.machine.axes.size());
  for (size_t k = 0; k < words.size(); ++k) apply_word(words[k], k == 0, state, programmed, block);
  return programmed;
}

// G92: the current position gets the programmed coordinates; nothing moves.
void preset_position(const BlockWords& programmed, DecoderState& state) {
  if (programmed.motion || programmed.i || programmed.j) throw LineError{"G92 must not be combined with motion"};
  if (state.cs) throw LineError{"G92 while a #CS is active is not supported yet"};
  for (size_t a = 0; a < programmed.axes.size(); ++a)
    if (programmed.axes[a]) state.offset[a] = state.position[a] - *programmed.axes[a];
}

// A block whose axes do not move is no motion block.
void decode_motion(const BlockWords& programmed, DecoderState& state, Block& block) {
  ModalState& modal = state.modal;
  if (programmed.motion) modal.motion = *programmed.motion;
  const std::vector<double> target = programmed_target(programmed.axes, state);
  const bool is_arc = modal.motion == MotionType::arc_cw || modal.motion == MotionType::arc_ccw;
  const bool has_centre = programmed.i || programmed.j;
  if (has_centre && !is_arc) throw LineError{"I/J are only allowed with G02/G03"};
  const bool full_circle = is_arc && has_centre;  // end = start
  if (target == state.position && !full_circle) return;
  block.has_motion = true;
  Motion& m = block.motion;
  m.type = modal.motion;
  m.start = state.position;
  m.end = target;
  block.slope = modal.slope;
  if (m.type != MotionType::rapid) {
    if (!(modal.feed > 0)) throw LineError{"no feed F programmed for G01/G02/G03"};
    m.feed = modal.feed;
  }
  if (is_arc) set_arc_centre(m, programmed.i, programmed.j, state);
  state.position = target;
}

// A '#' command is the whole block, after an optional N number.
void decode_command_block(const std::string& code, size_t hash, DecoderState& state, Block& block) {
  const std::vector<Word> before = split_words(code.substr(0, hash));
  const bool n_only =
      before.empty() || (before.size() == 1 && before[0].letter == 'N' && !before[0].is_axis_command());
  if (!n_only) throw LineError{"a '#' command must stand alone in its block (after the N number)"};
  if (!before.empty()) block.block_nr = integer_code(before[0]);
  decode_nc_command(upper_words(code.substr(hash)), state, block);
}

// P<n> = <expression> (a decoder variable) or
// V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm> (P-CHAN-00070 for M<m> from here
// on), after an optional N number. Decoder work: no block.
void assign_parameter(const std::string& code, size_t equals, DecoderState& state) {
  static const std::regex assignment(
      R"(\s*(?:[Nn]\d+\s+)?(?:[Pp](\d+)|V\.G\.M_FCT\[\s*(\d+)\s*\]\.PRE_OUTP_PATH)\s*)", std::regex::icase);
  std::smatch match;
  const std::string left = code.substr(0, equals);
  if (!std::regex_match(left, match, assignment))
    throw LineError{"'=' is only allowed in P<n> = <expression> and V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm>"};
  double value = 0;
  try {
    value = evaluate_expression(code.substr(equals + 1), state.parameters);
  } catch (const std::invalid_argument& e) {
    throw LineError{e.what()};
  }
  if (match[1].matched) {
    state.parameters[std::atoi(match[1].str().c_str())] = value;
  } else {
    if (value < 0) throw LineError{"PRE_OUTP_PATH must be >= 0 mm"};
    state.pre_output_mm[std::atoi(match[2].str().c_str())] = value;
  }
}

}  // namespace

bool decode_line(const std::string& line, int64_t line_nr, int64_t lines_read, DecoderState& state,
                 std::vector<Block>& out) {
  const std::string code = strip_comments(line);
  const size_t first = code.find_first_not_of(" \t\r");
  if (first == std::string::npos || code[first] == '%') return true;  // empty, or the program name
  Block block;
  block.nc_line = line_nr;
  block.block_count = lines_read;
  if (const size_t hash = code.find('#'); hash != std::string::npos) {
    decode_command_block(code, hash, state, block);
    if (block.has_command()) out.push_back(block);
    return true;
  }
  if (const size_t dollar = code.find('$'); dollar != std::string::npos) throw unsupported_command(code, dollar);
  if (const size_t equals = find_assignment(code); equals != std::string::npos) {
    assign_parameter(code, equals, state);
    return true;
  }
  const BlockWords programmed = apply_words(split_words(code), state, block);
  if (programmed.position_preset) {
    preset_position(programmed, state);
    return true;
  }
  decode_motion(programmed, state, block);
  if (block.has_motion || block.has_command()) out.push_back(block);
  return !block.program_end;
}

}  // namespace hil::cnc::decoding
