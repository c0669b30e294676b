#include "line_decoder.hpp"

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "assignments.hpp"
#include "g_functions.hpp"
#include "technology_words.hpp"
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
  ArcWords arc;                             // I J K R
  std::optional<MotionType> motion;         // G00..G03 of this block
  bool position_preset = false;             // G92: the axis words name the current position
  std::optional<int> transition;            // G60, G61, G260, G261, G359 or G360 (KRN-6)
  std::optional<int> run;                   // G74 (homing) or G100 (measurement): this block only
  bool dwell = false;                       // G04: X is the dwell time (KRN-8)
  std::optional<double> dwell_s;            // G04 X<s> or G04 <s>
  std::optional<int> zero_offset;           // G53 (0), G54..G59 (1..6)
  std::vector<int> g_codes;                 // every G of the block, for G04's "alone"
};

// The letters TwinCAT names axes with ("Axis names": A B C U V W X Y Z Q):
// one of them that is no axis here is "not an axis of this machine"; any
// other unknown letter is no word of the dialect at all (KRN-8).
bool names_axes(char letter) {
  return letter == 'A' || letter == 'B' || letter == 'C' || (letter >= 'U' && letter <= 'Z') || letter == 'Q';
}

int axis_of(const Word& w, const DecoderState& state) {
  const int axis = state.axis_of_letter(w.letter);
  if (axis >= 0) return axis;
  if (names_axes(w.letter)) throw LineError{"'" + w.text() + "': " + w.letter + " is not an axis of this machine"};
  if (w.letter == 'E') throw LineError{"'" + w.text() + "': E (feed at block end) is not supported by this rig"};
  if (w.letter == 'L') throw LineError{"'" + w.text() + "': L (subroutine call) is not supported by this rig"};
  if (w.letter == 'P')
    throw LineError{"'" + w.text() + "': a P parameter is set by P<n> = <expression>; words do not read it yet"};
  throw LineError{"'" + w.text() + "': " + w.letter + " is not a word of the TwinCAT dialect"};
}

// Modal G codes act at once (G70 / G71 before the block's other words);
// the motion G code waits for G92's check.
void apply_g_code(const Word& w, ModalState& modal, BlockWords& programmed) {
  const int g = static_cast<int>(integer_code(w, max_g_code));
  programmed.g_codes.push_back(g);
  if (g <= 3) {
    if (programmed.motion) throw LineError{"two motion G codes in one block"};
    programmed.motion = static_cast<MotionType>(g);
  } else if (g >= 17 && g <= 19) {
    modal.plane = static_cast<Plane>(g - 17);
  } else if (g == 40) {
    // Tool radius compensation off: the rig never has it on.
  } else if (g >= 53 && g <= 59) {
    if (programmed.zero_offset) throw LineError{"two zero offsets G53..G59 in one block"};
    programmed.zero_offset = g - 53;
  } else if (g == 4 || g == 70 || g == 71 || g == 94) {
    // G04, G70 / G71: read before the other words (apply_words); G94 (feed
    // per minute) is the rig's only feed mode.
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
    throw LineError{refused_g_function_message(g), 20131};
  }
}

// F in mm/min, within [min_feed_mm_min, max_feed_mm_min].
double feed_mm_s(const Word& w, double unit) {
  if (!(w.value * unit >= min_feed_mm_min && w.value * unit <= max_feed_mm_min)) {
    std::ostringstream msg;
    msg << std::setprecision(10) << "feed '" << w.text() << "' is out of range " << min_feed_mm_min << " .. "
        << max_feed_mm_min << " mm/min";
    throw LineError{msg.str()};
  }
  return w.value * unit / 60.0;
}

void apply_word(const Word& w, bool first, DecoderState& state, BlockWords& programmed, Block& block) {
  if (w.is_axis_command()) {
    decode_axis_command(w, axis_of(w, state), state, block);
    return;
  }
  const double unit = state.modal.inch ? mm_per_inch : 1.0;
  switch (w.letter) {
    case 'N':
      if (!first) throw LineError{"'" + w.text() + "' must be the first word of the block"};
      block.block_nr = integer_code(w, max_block_nr);
      break;
    case 'G': apply_g_code(w, state.modal, programmed); break;
    case 'F': state.modal.feed = feed_mm_s(w, unit); break;
    case 'M': add_m_function(w, state, block); break;
    case 'S': case 'T': case 'D': case 'H': add_technology_word(w, state, block); break;
    case 'I': programmed.arc.i = checked_length(w.value * unit, "I"); break;
    case 'J': programmed.arc.j = checked_length(w.value * unit, "J"); break;
    case 'K': programmed.arc.k = checked_length(w.value * unit, "K"); break;
    case 'R': programmed.arc.r = checked_length(w.value * unit, "R"); break;
    default: {
      if (programmed.dwell && w.letter == 'X' && !programmed.dwell_s) {  // G04 X<s>: the first main axis' letter
        programmed.dwell_s = w.value;
        break;
      }
      const size_t axis = static_cast<size_t>(axis_of(w, state));  // axis_of throws for none
      if (programmed.axes[axis]) throw LineError{std::string("axis ") + w.letter + " programmed twice"};
      const double scale = state.machine.axes[axis].rotary() ? 1.0 : unit;
      programmed.axes[axis] = checked_length(w.value * scale, std::string_view(&w.letter, 1));
    }
  }
}

BlockWords apply_words(const std::vector<Word>& words, DecoderState& state, Block& block) {
  BlockWords programmed(state.buffers.axis_words);
  programmed.axes.assign(state.machine.axes.size(), std::nullopt);
  // G70 / G71 act on the block's own words, wherever they stand in it;
  // G04 makes its X the time.
  for (const Word& w : words) {
    if (w.letter != 'G' || w.is_axis_command()) continue;
    if (w.value == 70 || w.value == 71) state.modal.inch = w.value == 70;
    if (w.value == 4) programmed.dwell = true;
  }
  for (size_t k = 0; k < words.size(); ++k) {
    try {
      apply_word(words[k], k == 0, state, programmed, block);
    } catch (LineError& e) {
      if (e.word.empty()) e.word = words[k].letter + std::string(words[k].written);  // where it stands (KRN-8)
      throw;
    }
  }
  return programmed;
}

// G92: the reference point offset, an additive zero offset (TF5200 "G92"):
// G90 sets it, G91 adds to it; nothing moves. After G92 X10, X0 is X10.
void preset_position(const BlockWords& programmed, DecoderState& state) {
  if (programmed.motion || programmed.run || programmed.arc.any())
    throw LineError{"G92 must not be combined with motion"};
  if (state.cs) throw LineError{"G92 while a #CS is active is not supported yet"};
  for (size_t a = 0; a < programmed.axes.size(); ++a) {
    if (!programmed.axes[a]) continue;
    state.reference_point_offset[a] = checked_length(
        (state.modal.absolute ? 0.0 : state.reference_point_offset[a]) + *programmed.axes[a], "G92 offset");
  }
  state.update_offset();
}

// G04 X<s> / G04 <s>: a dwell, alone in its block but for the N number
// (TF5200 "Dwell time"; errors 20685, 20013).
void decode_dwell(const BlockWords& programmed, const std::vector<Word>& words, Block& block) {
  if (!programmed.dwell_s) throw LineError{"G04 needs the dwell time: G04 X<s> or G04 <s>", 20685};
  const bool alone = std::all_of(words.begin(), words.end(), [](const Word& w) {
    return w.letter == 'N' || w.letter == 'X' || (w.letter == 'G' && w.value == 4);
  });
  if (!alone) throw LineError{"G04 must stand alone in its block (after the N number)", 20685};
  if (!(*programmed.dwell_s > 0 && *programmed.dwell_s <= max_dwell_s))
    throw LineError{"G04 needs a dwell time > 0 and <= " + std::to_string(static_cast<int64_t>(max_dwell_s)) + " s"};
  block.dwell_s = *programmed.dwell_s;
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
  if (programmed.arc.any()) throw LineError{"I J K R are only allowed with G02/G03"};
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
  if (programmed.arc.any() && !is_arc) throw LineError{"I J K R are only allowed with G02/G03"};
  const bool full_circle = is_arc && programmed.arc.any();  // end = start (R: refused there)
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
  // KRN-9: G00 and exact stops switch HSC off where AUTO_OFF_G00 /
  // AUTO_OFF_G60 say so; otherwise a G00 block is not smoothed and an exact
  // stop ends the spline where it stands (hsc_spline.hpp).
  if (modal.hsc.on && ((m.type == MotionType::rapid && modal.hsc.auto_off_g00) ||
                       (block.transition == BlockTransition::exact_stop && modal.hsc.auto_off_g60)))
    modal.hsc.on = false;
  block.hsc = modal.hsc;
  if (m.type != MotionType::rapid && !(modal.feed > 0)) throw LineError{"no feed F programmed for G01/G02/G03"};
  m.feed = modal.feed;  // G00 too: a short cut to its end runs at it (DDTG-2)
  if (is_arc) set_arc_centre(m, programmed.arc, state);
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

// Block skip (TF5200 "Skipping of NC blocks"): /1 .. /10 at the start of a
// line name skip levels 1 .. 10 (bits 0x001 .. 0x200); a bare / is level
// 1. The line is left out while the PLC's program_block_ignore has its
// level's bit; `first` moves past the mark either way.
bool skipped(std::string_view code, size_t& first, uint32_t block_ignore) {
  size_t i = first + 1;
  int level = 0;
  while (i < code.size() && code[i] >= '0' && code[i] <= '9' && level <= max_skip_level) level = level * 10 + (code[i++] - '0');
  if (i == first + 1) level = 1;
  if (level < 1 || level > max_skip_level)
    throw LineError{"block skip '/" + std::string(code.substr(first + 1, i - first - 1)) + "': the skip levels are /1 .. /" +
                    std::to_string(max_skip_level)};
  first = i;
  return (block_ignore >> (level - 1)) & 1u;
}

// G04 <s> (TF5200 "Dwell time"): the time without an address, written as
// G04 X<s> into `storage` for the words; empty if the line has no such form.
const std::string& with_dwell_address(std::string_view code, std::string& storage) {
  storage.clear();
  LineCursor cursor(code);
  cursor.skip_block_nr();
  if (!(cursor.take_keyword("G04") || cursor.take_keyword("G4"))) return storage;
  cursor.skip_blanks();
  const std::string_view rest = cursor.rest();
  if (rest.empty() || !(std::isdigit(static_cast<unsigned char>(rest[0])) || rest[0] == '.')) return storage;
  storage.assign(code.substr(0, code.size() - rest.size()));
  storage += 'X';
  storage += rest;
  return storage;
}

}  // namespace

bool decode_line(std::string_view line, int64_t line_nr, int64_t lines_read, DecoderState& state,
                 std::vector<Block>& out) {
  std::string_view code = without_comments(line, state.buffers.code);
  size_t first = code.find_first_not_of(" \t\r");
  if (first == std::string::npos || code[first] == '%') return true;  // empty, or the program name
  if (code[first] == '/') {
    if (skipped(code, first, state.block_ignore)) return true;
    first = code.find_first_not_of(" \t\r", first);
    if (first == std::string::npos) return true;
  }
  code = code.substr(first);
  const std::string& bare_dwell = with_dwell_address(code, state.buffers.dwell);
  if (!bare_dwell.empty()) code = bare_dwell;
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
    if (programmed.zero_offset) {
      // G53..G59 act from this block on (TF5200 "Zero offsets").
      state.zero_offset = *programmed.zero_offset;
      state.update_offset();
    }
    // G92's M functions (and M30) are the block's, as with any other block.
    if (programmed.dwell) decode_dwell(programmed, words, block);
    else if (programmed.position_preset) preset_position(programmed, state);
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
