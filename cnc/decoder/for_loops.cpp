#include "for_loops.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "line_cursor.hpp"
#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {
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
std::optional<size_t> after_endfor(LineStore& lines, size_t line) {
  int depth = 0;
  std::string code;
  LineCursor cursor{std::string_view()};
  for (size_t i = line; lines.has(i); ++i) {
    if (i - line > ForLoops::max_body_lines)
      throw LineError{"$FOR without $ENDFOR within " + std::to_string(ForLoops::max_body_lines) +
                      " lines (a loop's body is held while it runs)"};
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

std::optional<size_t> ForLoops::control_flow(LineStore& lines, size_t i, ParameterValues& parameters) {
  if (lines[i].find('$') == std::string_view::npos) return std::nullopt;  // plain blocks: before any set-up
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

size_t ForLoops::begin_loop(const std::string& code, LineStore& lines, size_t i, ParameterValues& parameters) {
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

size_t ForLoops::end_of_body(size_t i, ParameterValues& parameters) {
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

}  // namespace hil::cnc::decoding
