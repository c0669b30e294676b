// The decoder as it was before programs were streamed (issue 17, commit
// 1aff34d): the whole text split into lines, $FOR loops over the line
// list, M function pre-output over the whole block list. Kept here, frozen,
// as the reference the streamed decoder must match block for block.
#include "reference_decoder.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "decoder_state.hpp"
#include "lift_commands.hpp"
#include "line_cursor.hpp"
#include "line_decoder.hpp"
#include "motion_parts.hpp"
#include "path_segment.hpp"
#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc::reference {
namespace decoding_old {
using namespace hil::cnc::decoding;

class WholeForLoops {
 public:
  std::optional<size_t> control_flow(const std::vector<std::string_view>& lines, size_t i,
                                     ParameterValues& parameters);

 private:
  struct Loop {
    size_t first_line;
    int parameter;
    double end;
    double step;
    bool done(double value) const { return step > 0 ? value > end + 1e-9 : value < end - 1e-9; }
  };
  size_t begin_loop(const std::string& code, const std::vector<std::string_view>& lines, size_t i,
                    ParameterValues& parameters);
  size_t end_of_body(size_t i, ParameterValues& parameters);
  std::vector<Loop> loops_;
};

namespace {

enum class LoopKeyword { none, for_loop, endfor };

// The loop keyword that starts the code of `line` (after an N number), the
// cursor after it. A line whose comment is not closed is none here: that
// error is the line's own, when it is decoded.
LoopKeyword loop_keyword(std::string_view line, std::string& code, LineCursor& after) {
  if (line.find('$') == std::string_view::npos) return LoopKeyword::none;  // plain blocks spare the work
  try {
    code = strip_comments(line);
  } catch (const LineError&) {
    return LoopKeyword::none;
  }
  after = LineCursor(code);
  after.skip_block_nr();
  if (after.take_keyword("$FOR")) return LoopKeyword::for_loop;
  if (after.take_keyword("$ENDFOR")) return LoopKeyword::endfor;
  return LoopKeyword::none;
}

// The line after the $ENDFOR that closes the $FOR at `line`, or none.
std::optional<size_t> after_endfor(const std::vector<std::string_view>& lines, size_t line) {
  int depth = 0;
  std::string code;
  LineCursor cursor{std::string_view()};
  for (size_t i = line; i < lines.size(); ++i) {
    const LoopKeyword keyword = loop_keyword(lines[i], code, cursor);
    if (keyword == LoopKeyword::for_loop) ++depth;
    if (keyword == LoopKeyword::endfor && --depth == 0) return i + 1;
  }
  return std::nullopt;
}

// <start>, <end> [, <step>] after the '='.
std::vector<std::string> loop_bounds(std::string_view text) {
  std::vector<std::string> parts;
  for (size_t begin = 0;;) {
    const size_t comma = text.find(',', begin);
    parts.emplace_back(text.substr(begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin));
    if (comma == std::string_view::npos) return parts;
    begin = comma + 1;
  }
}

const LineError syntax{"$FOR needs P<n> = <start>, <end> [, <step>]"};

// Each loop entered looks for its $ENDFOR through the lines after it: with
// nesting unbounded, 100,000 nested loops took 10^10 steps.
constexpr size_t max_depth = 100;

}  // namespace

std::optional<size_t> WholeForLoops::control_flow(const std::vector<std::string_view>& lines, size_t i,
                                             ParameterValues& parameters) {
  std::string code;
  LineCursor after{std::string_view()};
  switch (loop_keyword(lines[i], code, after)) {
    case LoopKeyword::for_loop: return begin_loop(code, lines, i, parameters);
    case LoopKeyword::endfor:
      if (!after.at_end()) throw LineError{"$ENDFOR must stand alone in its block"};
      return end_of_body(i, parameters);
    case LoopKeyword::none: break;
  }
  return std::nullopt;
}

size_t WholeForLoops::begin_loop(const std::string& code, const std::vector<std::string_view>& lines, size_t i,
                            ParameterValues& parameters) {
  if (loops_.size() == max_depth) throw LineError{"$FOR nested deeper than " + std::to_string(max_depth) + " levels"};
  LineCursor cursor(code);
  cursor.skip_block_nr();
  cursor.take_keyword("$FOR");
  if (!cursor.take('P')) throw syntax;
  const std::optional<int64_t> parameter = whole_number(cursor.take_digits(), max_p_parameter);
  if (!parameter) throw LineError{"$FOR: the P parameter number must be 0.." + std::to_string(max_p_parameter)};
  if (!cursor.take('=')) throw syntax;
  const std::vector<std::string> bounds = loop_bounds(cursor.rest());
  if (bounds.size() < 2 || bounds.size() > 3) throw syntax;
  auto value = [&](const std::string& text) { return evaluate_expression(text, parameters); };
  Loop loop{i + 1, static_cast<int>(*parameter), value(bounds[1]), bounds.size() == 3 ? value(bounds[2]) : 1.0};
  if (loop.step == 0) throw LineError{"$FOR step must not be 0"};
  const std::optional<size_t> after = after_endfor(lines, i);
  if (!after) throw LineError{"$FOR without $ENDFOR"};
  const double first = value(bounds[0]);
  parameters[loop.parameter] = first;
  if (loop.done(first)) return *after;
  loops_.push_back(loop);
  return i + 1;
}

size_t WholeForLoops::end_of_body(size_t i, ParameterValues& parameters) {
  if (loops_.empty()) throw LineError{"$ENDFOR without $FOR"};
  const Loop& loop = loops_.back();
  const double previous = parameters.at(loop.parameter);
  const double value = previous + loop.step;
  // Past the largest double, or a step below its resolution: the loop
  // would never end (or end with P<n> = inf).
  if (!std::isfinite(value) || value == previous) {
    std::ostringstream msg;
    msg << "$FOR: P" << loop.parameter << " = " << previous << " + step " << loop.step << " is "
        << (value == previous ? "no step" : "out of range");
    throw LineError{msg.str()};
  }
  parameters[loop.parameter] = value;
  if (!loop.done(value)) return loop.first_line;
  loops_.pop_back();
  return i + 1;
}


}  // namespace decoding_old

using decoding_old::WholeForLoops;

namespace {

using decoding::LineError;

Event line_error(const std::string& message, const std::string& line, int64_t line_nr) {
  Event error;
  error.severity = Severity::error;
  error.nc_line = line_nr;
  // The N number if the line starts with one (and it is in range), for the message.
  using decoding::max_block_nr, decoding::whole_number;
  decoding::LineCursor cursor(line);
  if (cursor.take('N')) error.block_nr = whole_number(cursor.take_digits(), max_block_nr).value_or(0);
  error.message = decoding::printable(message) + " in '" + decoding::printable(line) + "'";
  return error;
}

// Views into `text`: $FOR loops read lines again.
std::vector<std::string_view> split_lines(const std::string& text) {
  std::vector<std::string_view> lines;
  for (size_t begin = 0; begin < text.size();) {
    const size_t end = std::min(text.find('\n', begin), text.size());
    lines.emplace_back(text.data() + begin, end - begin);
    begin = end + 1;
  }
  return lines;
}

// The axis positions decoding starts from are the first block's start.
std::optional<Event> check_start(const MachineConfig& machine, const std::vector<double>& start) {
  Event error;
  error.severity = Severity::error;  // nc_line 0: not from the program
  try {
    if (start.size() != machine.axes.size())
      throw LineError{std::to_string(start.size()) + " start positions for " + std::to_string(machine.axes.size()) +
                      " axes"};
    decoding::check_position(start, machine, "start position");
  } catch (const LineError& e) {
    error.message = "decoder: " + e.message;
    return error;
  }
  return std::nullopt;
}

constexpr int64_t default_max_lines_read = 10000000;  // an endless loop is an error, not a hang

}  // namespace

DecodedProgram whole_decode_program(const std::string& text, const MachineConfig& machine,
                              const std::vector<double>& start) {
  return whole_decode_program(text, machine, start, default_max_lines_read);
}

DecodedProgram whole_decode_program(const std::string& text, const MachineConfig& machine, const std::vector<double>& start,
                              int64_t max_lines_read) {
  DecodedProgram program;
  if ((program.error = check_start(machine, start))) return program;
  decoding::DecoderState state(machine, start);
  const std::vector<std::string_view> lines = split_lines(text);
  WholeForLoops loops;
  int64_t lines_read = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string line(lines[i]);
    const int64_t line_nr = static_cast<int64_t>(i) + 1;
    try {
      if (++lines_read > max_lines_read)
        throw LineError{"more than " + std::to_string(max_lines_read) + " lines read: endless $FOR loop?"};
      decoding::check_characters(line);
      if (const std::optional<size_t> next = loops.control_flow(lines, i, state.parameters)) {
        i = *next - 1;
        continue;
      }
      if (!decoding::decode_line(line, line_nr, lines_read, state, program.blocks)) break;
    } catch (const LineError& e) {
      program.error = line_error(e.message, line, line_nr);
      program.error->id = e.id;
      break;
    } catch (const std::invalid_argument& e) {
      program.error = line_error(e.what(), line, line_nr);
      break;
    } catch (const std::exception& e) {  // a decoder bug: still an error of this line, not a crashed CNC
      program.error = line_error(std::string("decoder fault: ") + e.what(), line, line_nr);
      break;
    }
  }
  if (program.error) decoding::park_lift_at_error(state, program.blocks);  // LIFT-5 special case 2
  return program;
}


namespace pre_output {

constexpr int pre_output_lookahead_blocks = 10;  // P-CHAN-00603 default
// No part shorter than this (10 nm) is split off: a shorter arc could not be
// told from a full circle.
constexpr double shortest_part_mm = 1e-5;

// Puts `m` `distance` mm before the end of `out`'s path: between two parts
// of the motion block there, or before the earliest block searched.
// False if the path before it was shorter than the pre-output path.
bool insert_pre_output(std::vector<Block>& out, const MFunction& m, const Block& owner, const MachineConfig& machine) {
  double distance = m.pre_output_mm;
  bool reached = false;
  size_t insert_at = out.size();
  int searched = 0;
  for (size_t i = out.size(); i-- > 0 && searched < pre_output_lookahead_blocks;) {
    if (!out[i].has_motion) continue;
    ++searched;
    insert_at = i;
    const PathSegment segment(out[i].motion, machine);
    if (distance >= segment.length() - shortest_part_mm) {  // lies before this block
      distance -= segment.length();
      reached = distance <= shortest_part_mm;
      if (reached) break;
      continue;
    }
    reached = true;
    if (distance <= shortest_part_mm) {  // at its end
      insert_at = i + 1;
      break;
    }
    Block second = out[i];
    const std::vector<double> split = segment.position(segment.length() - distance);
    out[i].motion = motion_until(out[i].motion, split);
    out[i].program_end = false;  // M30 ends the second part
    out[i].lift_end = false;     // a lift range begins with the first part, ends with the second (LIFT-1)
    second.motion = motion_from(second.motion, split);
    second.continues_block = true;
    second.m_functions.clear();  // the line's own M functions went out before its first part
    second.dwell_s = 0;
    second.lift_start.reset();
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(i) + 1, std::move(second));
    insert_at = i + 1;
    break;
  }
  // The M function stands as a block without motion of the line it goes out in.
  const Block& at = insert_at < out.size() ? out[insert_at] : owner;
  Block carrier;
  carrier.nc_line = at.nc_line;
  carrier.block_count = at.block_count;
  carrier.block_nr = at.block_nr;
  carrier.m_functions.push_back({m.nr, 0});
  out.insert(out.begin() + static_cast<std::ptrdiff_t>(insert_at), std::move(carrier));
  return reached;
}

}  // namespace pre_output
using namespace pre_output;

std::vector<Block> whole_m_pre_output(std::vector<Block> blocks, const MachineConfig& machine,
                                      std::vector<Event>& warnings) {
  const bool any = std::any_of(blocks.begin(), blocks.end(), [](const Block& b) {
    return std::any_of(b.m_functions.begin(), b.m_functions.end(), [](const MFunction& m) { return m.pre_output_mm > 0; });
  });
  if (!any) return blocks;
  std::vector<Block> out;
  out.reserve(blocks.size() + 16);
  for (Block& block : blocks) {
    std::vector<MFunction> stay;
    for (const MFunction& m : block.m_functions) {
      if (m.pre_output_mm <= 0) {
        stay.push_back(m);
      } else if (!insert_pre_output(out, m, block, machine)) {
        Event short_path;
        short_path.severity = Severity::warning;
        short_path.parameter = "P-CHAN-00070";
        short_path.nc_line = block.nc_line;
        short_path.block_nr = block.block_nr;
        short_path.value = m.pre_output_mm;
        short_path.message = "M" + std::to_string(m.nr) + ": pre-output path " + std::to_string(m.pre_output_mm) +
                             " mm reaches past the program start or the " +
                             std::to_string(pre_output_lookahead_blocks) +
                             " motion blocks searched (P-CHAN-00603); output as early as they allow";
        warnings.push_back(short_path);
      }
    }
    block.m_functions = std::move(stay);
    if (block.has_motion || block.has_command()) out.push_back(std::move(block));
  }
  return out;
}


}  // namespace hil::cnc::reference
