#include "lift_commands.hpp"

#include <stdexcept>

#include "command_parameters.hpp"
#include "motion_target.hpp"
#include "value_ranges.hpp"

namespace hil::cnc::decoding {
namespace {

std::string axis_name(const DecoderState& state, int axis) { return state.machine.axes[static_cast<size_t>(axis)].name; }

// "Z[LIFT_START]" for messages.
std::string command_name(const DecoderState& state, int axis, const char* keyword) {
  return axis_name(state, axis) + "[" + keyword + "]";
}

std::string open_range(const DecoderState& state) {
  return "the lift range of " + axis_name(state, state.lift->start.axis) + " (LIFT_START in line " +
         std::to_string(state.lift->nc_line) + ")";
}

void check_enabled(const DecoderState& state, const std::string& name) {
  if (state.machine.lift_method == LiftMethod::none)
    throw LineError{name +
                    ": the lift function is not enabled on this machine (FCT_LIFT_UP or FCT_LIFT_UP_TIME in "
                    "P-STUP-00060 path_preparation_function, P-CHAN-00345 enable_time_based_lift)"};
}

void check_one_per_block(const Block& block, const std::string& name) {
  if (block.lift_start || block.lift_end) throw LineError{name + ": one lift command per block"};
}

// Z[LIFT_START ..] / Z[LIFT ..]: the range's LiftStart, positions absolute.
LiftStart lift_start_of(int axis, const std::string& arguments, const DecoderState& state, const std::string& name) {
  check_enabled(state, name);
  if (state.lift) throw LineError{name + " inside " + open_range(state) + ": Z[LIFT_END] first"};
  const AxisConfig& config = state.machine.axes[static_cast<size_t>(axis)];
  if (config.modulo) throw LineError{name + ": a modulo axis cannot be a lift axis"};
  bool down = false, relative = false, dimension = false;
  std::optional<double> pos, pos_limit;
  for (const CommandParameter& item : read_parameter_items(name, arguments)) {
    const std::string& key = item.key;
    if (key == "DOWN" || key == "G90" || key == "G91") {
      if (item.value) throw LineError{name + ": " + key + " takes no value"};
      if (key == "DOWN") {
        if (down) throw LineError{name + ": DOWN given twice"};
        down = true;
      } else {
        if (dimension) throw LineError{name + ": one of G90 / G91"};
        dimension = true;
        relative = key == "G91";
      }
    } else if (key == "POS" || key == "POS_LIMIT") {
      std::optional<double>& target = key == "POS" ? pos : pos_limit;
      if (target) throw LineError{name + ": " + key + " given twice"};
      if (!item.value || item.value->empty()) throw LineError{name + ": " + key + " needs =<value>"};
      try {
        target = checked_length(state.evaluate(*item.value), key);
      } catch (const std::invalid_argument& e) {
        throw LineError{name + ": " + key + "=" + *item.value + " is not a number (" + e.what() + ")"};
      }
    } else if (key == "LIFT_START" || key == "LIFT" || key == "LIFT_END") {
      throw LineError{name + ": " + key + " must be the first keyword, and only one"};
    } else {
      throw LineError{name + ": unknown keyword '" + key + "' (DOWN, G90, G91, POS=, POS_LIMIT=)"};
    }
  }
  if (!pos_limit) throw LineError{name + " needs POS_LIMIT=.."};
  // LIFT-3: Lifting (path-based) has no DOWN.
  if (down && state.machine.lift_method != LiftMethod::time_based)
    throw LineError{name + ": DOWN is only available with Advanced Lifting (FCT_LIFT_UP_TIME, P-CHAN-00345 = 1)"};
  // LIFT-6: only a rotation about the lift axis may be active (2.3).
  const size_t main = std::string("XYZ").find(config.name);
  if (state.cs && main != std::string::npos && !state.cs->keeps_axis(static_cast<int>(main)))
    throw LineError{name + ": the active #CS rotates the lift axis " + config.name +
                        " (only a rotation about it is permitted)",
                    21071};
  // Through G92 and #CS as the axis' words are; G91 from where it stands.
  std::vector<std::optional<double>> words(state.machine.axes.size());
  auto machine_position = [&](double value) {
    words[static_cast<size_t>(axis)] = value;
    return checked_length(programmed_target(words, state, !relative)[static_cast<size_t>(axis)], name + " position");
  };
  LiftStart start;
  start.axis = axis;
  start.down = down;
  start.pos = pos ? machine_position(*pos) : state.position[static_cast<size_t>(axis)];
  start.pos_limit = machine_position(*pos_limit);
  return start;
}

bool has_lift(const Block& block) { return block.lift_start || block.lift_end; }

}  // namespace

void decode_lift_start(int axis, const std::string& arguments, DecoderState& state, Block& block) {
  const std::string name = command_name(state, axis, "LIFT_START");
  check_one_per_block(block, name);
  block.lift_start = lift_start_of(axis, arguments, state, name);
}

void decode_lift(int axis, const std::string& arguments, DecoderState& state, Block& block) {
  const std::string name = command_name(state, axis, "LIFT");
  check_one_per_block(block, name);
  block.lift_start = lift_start_of(axis, arguments, state, name);
  block.lift_end = true;
}

void decode_lift_end(int axis, const std::string& arguments, DecoderState& state, Block& block) {
  const std::string name = command_name(state, axis, "LIFT_END");
  check_one_per_block(block, name);
  check_enabled(state, name);
  if (!arguments.empty()) throw LineError{name + " takes no parameters, not '" + arguments + "'"};
  if (!state.lift) throw LineError{name + " without an open lift range (Z[LIFT_START ..])"};
  if (state.lift->start.axis != axis) throw LineError{name + ": the open range is " + open_range(state)};
  block.lift_end = true;
}

void decode_flush(const std::string& arguments, DecoderState& state, Block& block) {
  if (!arguments.empty()) throw LineError{"#FLUSH takes nothing but WAIT, not '" + arguments + "'"};
  if (!state.lift) return;
  block.lift_end = true;
  block.lift_start = state.lift->start;  // the range goes on with its own POS and POS_LIMIT
  block.short_cut_restriction = ShortCutRestriction::not_skippable;  // DDTG-8
}

void refuse_rotation(const std::string& keyword, const DecoderState& state) {
  if (state.lift)
    throw LineError{keyword + " inside " + open_range(state) + " is not permitted (and " + keyword +
                        " is not supported by this rig; #CS is its coordinate rotation)",
                    120606};
  throw LineError{"command '" + keyword + "' is not supported by this rig (#CS is its coordinate rotation)"};
}

void finish_lift_block(const std::vector<Word>& words, const std::vector<std::optional<double>>& axis_words,
                       bool position_preset, const DecoderState& state, Block& block) {
  const std::optional<int> axis = state.lift           ? std::optional<int>(state.lift->start.axis)
                                  : block.lift_start ? std::optional<int>(block.lift_start->axis)
                                                     : std::nullopt;
  if (!axis) return;
  if (axis_words[static_cast<size_t>(*axis)])
    throw LineError{"axis " + axis_name(state, *axis) + " is programmed inside " +
                    (state.lift ? open_range(state) : "its lift range") +
                    ": the lift function moves it until Z[LIFT_END]"};
  if (has_lift(block) && position_preset) throw LineError{"a lift command cannot be combined with G92"};
  for (const Word& w : words)
    if (w.is_axis_command() && command_keyword(w.command) == "LIFT" && !block.has_motion)
      throw LineError{command_name(state, *axis, "LIFT") + " needs a motion in its block (else Z[LIFT_START ..])"};
  if (block.program_end) block.lift_end = true;  // M30 acts as LIFT_END (2.4)
  if (has_lift(block)) block.short_cut_restriction = ShortCutRestriction::not_skippable;  // DDTG-8: error 51016
}

void record_lift_block(DecoderState& state, std::vector<Block>& blocks) {
  const Block& block = blocks.back();
  const bool ends_open = block.lift_end && state.lift;
  if (ends_open) {
    LiftStart& first = *blocks[state.lift->block_index].lift_start;
    if (block.lift_start) first.pos = first.pos_limit;  // #FLUSH: LIFT_END at the highest lift, then LIFT_START
    state.position[static_cast<size_t>(first.axis)] = first.pos;
    state.lift.reset();
  }
  if (!block.lift_start) return;
  state.lift = LiftRange{*block.lift_start, blocks.size() - 1, block.nc_line};
  if (block.lift_end && !ends_open) {  // Z[LIFT ..], or LIFT_START with M30: the range is this block
    state.position[static_cast<size_t>(block.lift_start->axis)] = block.lift_start->pos;
    state.lift.reset();
  }
}

void park_lift_at_error(const DecoderState& state, std::vector<Block>& blocks) {
  if (!state.lift || state.lift->block_index >= blocks.size()) return;
  LiftStart& start = *blocks[state.lift->block_index].lift_start;
  start.pos = start.pos_limit;
}

}  // namespace hil::cnc::decoding
