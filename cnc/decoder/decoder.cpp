#include "decoder.hpp"

#include <algorithm>
#include <cstdlib>
#include <regex>
#include <stdexcept>
#include <string_view>

#include "decoder_state.hpp"
#include "line_decoder.hpp"
#include "words.hpp"

namespace hil::cnc {
namespace {

using decoding::LineError;

Event line_error(const std::string& message, const std::string& line, int64_t line_nr) {
  Event error;
  error.severity = Severity::error;
  error.nc_line = line_nr;
  // The N number if the line starts with one, for the message.
  const size_t n = line.find_first_not_of(" \t");
  if (n != std::string::npos && (line[n] == 'N' || line[n] == 'n')) error.block_nr = std::atoll(line.c_str() + n + 1);
  error.message = message + " in '" + line + "'";
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

const std::regex for_line(R"(\s*(?:[Nn]\d+\s+)?\$FOR\s+[Pp](\d+)\s*=\s*([^,]+),([^,]+)(?:,([^,]+))?\s*)",
                          std::regex::icase);
const std::regex endfor_line(R"(\s*(?:[Nn]\d+\s+)?\$ENDFOR\s*)", std::regex::icase);

// The line after the $ENDFOR that closes the $FOR at `line`, or none.
std::optional<size_t> after_endfor(const std::vector<std::string_view>& lines, size_t line) {
  int depth = 0;
  for (size_t i = line; i < lines.size(); ++i) {
    if (lines[i].find('$') == std::string_view::npos) continue;
    const std::string code = decoding::strip_comments(std::string(lines[i]));
    if (std::regex_match(code, for_line)) ++depth;
    if (std::regex_match(code, endfor_line) && --depth == 0) return i + 1;
  }
  return std::nullopt;
}

// $FOR P<n> = <start>, <end> [, <step>] ... $ENDFOR: the lines between run
// while P<n> has not passed <end> (KRN-1).
class Loops {
 public:
  // The line to read after line `i` if it is a $FOR or $ENDFOR, else none.
  std::optional<size_t> control_flow(const std::vector<std::string_view>& lines, size_t i,
                                     ParameterValues& parameters) {
    if (lines[i].find('$') == std::string_view::npos) return std::nullopt;  // plain blocks spare the regexes
    const std::string code = decoding::strip_comments(std::string(lines[i]));
    std::smatch m;
    if (std::regex_match(code, m, for_line)) return begin_loop(m, lines, i, parameters);
    if (std::regex_match(code, endfor_line)) return end_of_body(i, parameters);
    return std::nullopt;
  }

 private:
  struct Loop {
    size_t first_line;  // the line after $FOR
    int parameter;
    double end;
    double step;
    bool done(double value) const { return step > 0 ? value > end + 1e-9 : value < end - 1e-9; }
  };

  size_t begin_loop(const std::smatch& m, const std::vector<std::string_view>& lines, size_t i,
                    ParameterValues& parameters) {
    auto value = [&](const std::ssub_match& part) { return evaluate_expression(part.str(), parameters); };
    Loop loop{i + 1, std::atoi(m[1].str().c_str()), value(m[3]), m[4].matched ? value(m[4]) : 1.0};
    if (loop.step == 0) throw LineError{"$FOR step must not be 0"};
    const std::optional<size_t> after = after_endfor(lines, i);
    if (!after) throw LineError{"$FOR without $ENDFOR"};
    const double first = value(m[2]);
    parameters[loop.parameter] = first;
    if (loop.done(first)) return *after;
    loops_.push_back(loop);
    return i + 1;
  }

  size_t end_of_body(size_t i, ParameterValues& parameters) {
    if (loops_.empty()) throw LineError{"$ENDFOR without $FOR"};
    const Loop& loop = loops_.back();
    const double value = parameters.at(loop.parameter) + loop.step;
    parameters[loop.parameter] = value;
    if (!loop.done(value)) return loop.first_line;
    loops_.pop_back();
    return i + 1;
  }

  std::vector<Loop> loops_;  // open, innermost last
};

constexpr int64_t max_lines_read = 10000000;  // an endless loop is an error, not a hang

}  // namespace

DecodedProgram decode_program(const std::string& text, const MachineConfig& machine,
                              const std::vector<double>& start) {
  DecodedProgram program;
  decoding::DecoderState state(machine, start);
  const std::vector<std::string_view> lines = split_lines(text);
  Loops loops;
  int64_t lines_read = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string line(lines[i]);
    const int64_t line_nr = static_cast<int64_t>(i) + 1;
    try {
      if (++lines_read > max_lines_read)
        throw LineError{"more than " + std::to_string(max_lines_read) + " lines read: endless $FOR loop?"};
      if (const std::optional<size_t> next = loops.control_flow(lines, i, state.parameters)) {
        i = *next - 1;
        continue;
      }
      if (!decoding::decode_line(line, line_nr, lines_read, state, program.blocks)) break;
    } catch (const LineError& e) {
      program.error = line_error(e.message, line, line_nr);
      break;
    } catch (const std::invalid_argument& e) {
      program.error = line_error(e.what(), line, line_nr);
      break;
    }
  }
  return program;
}

}  // namespace hil::cnc
