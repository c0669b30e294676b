#include "decoder.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>

#include "decoder_state.hpp"
#include "for_loops.hpp"
#include "lift_commands.hpp"
#include "line_cursor.hpp"
#include "line_decoder.hpp"
#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc {
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

DecodedProgram decode_program(const std::string& text, const MachineConfig& machine,
                              const std::vector<double>& start) {
  return decode_program(text, machine, start, default_max_lines_read);
}

DecodedProgram decode_program(const std::string& text, const MachineConfig& machine, const std::vector<double>& start,
                              int64_t max_lines_read) {
  DecodedProgram program;
  if ((program.error = check_start(machine, start))) return program;
  decoding::DecoderState state(machine, start);
  const std::vector<std::string_view> lines = split_lines(text);
  decoding::ForLoops loops;
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

}  // namespace hil::cnc
