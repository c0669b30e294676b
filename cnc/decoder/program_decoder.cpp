#include "program_decoder.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>
#include <string_view>

#include "lift_commands.hpp"
#include "line_cursor.hpp"
#include "line_decoder.hpp"
#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc {
namespace {

using decoding::LineError;

Event line_error(const std::string& message, std::string_view line, int64_t line_nr) {
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

// The 1-based column of `word` in `line` (any case), 0 if it is not there
// as written (blanks inside it, or none given).
int64_t column_of(const std::string& word, std::string_view line) {
  if (word.empty() || word.size() > line.size()) return 0;
  const auto upper = [](char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; };
  for (size_t i = 0; i + word.size() <= line.size(); ++i) {
    size_t k = 0;
    while (k < word.size() && upper(line[i + k]) == upper(word[k])) ++k;
    // Not the start of a longer number: G4 is not the G4 of G41.
    const bool whole = i + k == line.size() || !(std::isdigit(static_cast<unsigned char>(line[i + k])) || line[i + k] == '.');
    if (k == word.size() && whole) return static_cast<int64_t>(i) + 1;
  }
  return 0;
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

// Handed-out blocks are dropped in batches (the vector's front).
constexpr size_t drop_batch = 256;

}  // namespace

ProgramDecoder::ProgramDecoder(std::unique_ptr<LineSource> text, const MachineConfig& machine,
                               const std::vector<double>& start, int64_t max_lines_read)
    : text_(std::move(text)), lines_(*text_), state_(machine, start), max_lines_read_(max_lines_read) {
  if ((error_ = check_start(machine, start))) finished_ = true;
}

size_t ProgramDecoder::releasable() const {
  if (finished_ || !state_.lift) return out_.size();
  return state_.lift->block_index;
}

bool ProgramDecoder::next(Block& block) {
  while (head_ >= releasable()) {
    if (finished_) return false;
    decode_next_line();
  }
  block = std::move(out_[head_++]);
  if (head_ == out_.size()) {
    out_.clear();
    head_ = 0;
  } else if (head_ >= drop_batch && head_ >= out_.size() / 2) {  // a lift range open: keep its blocks
    out_.erase(out_.begin(), out_.begin() + static_cast<std::ptrdiff_t>(head_));
    if (state_.lift) state_.lift->block_index -= head_;
    head_ = 0;
  }
  return true;
}

void ProgramDecoder::decode_next_line() {
  if (!lines_.has(line_)) {
    finish();
    return;
  }
  const int64_t line_nr = static_cast<int64_t>(line_) + 1;
  try {
    // Lines read again by $FOR loops are counted, not the program's own:
    // a program may be of any length, an endless loop is still an error.
    furthest_ = std::max(furthest_, static_cast<int64_t>(line_) + 1);
    if (++lines_read_ - furthest_ > max_lines_read_)
      throw LineError{"more than " + std::to_string(max_lines_read_) + " lines read again by $FOR loops: endless $FOR loop?"};
    decoding::check_characters(lines_[line_]);
    if (const std::optional<size_t> next = loops_.control_flow(lines_, line_, state_.parameters)) {
      line_ = *next;
    } else if (decoding::decode_line(lines_[line_], line_nr, lines_read_, state_, out_)) {
      ++line_;
    } else {
      finish();  // M30
    }
  } catch (const LineError& e) {
    error_ = line_error(e.message, lines_[line_], line_nr);
    error_->id = e.id;
    error_->column = column_of(e.word, lines_[line_]);
  } catch (const std::invalid_argument& e) {
    error_ = line_error(e.what(), lines_[line_], line_nr);
  } catch (const std::exception& e) {  // a decoder bug: still an error of this line, not a crashed CNC
    error_ = line_error(std::string("decoder fault: ") + e.what(), lines_[line_], line_nr);
  }
  if (error_) {
    decoding::park_lift_at_error(state_, out_);  // LIFT-5 special case 2
    finish();
    return;
  }
  const std::optional<size_t> loop = loops_.oldest_needed();
  lines_.forget_before(loop && *loop < line_ ? *loop : line_);
}

void ProgramDecoder::finish() {
  finished_ = true;
  state_.lift.reset();
}

}  // namespace hil::cnc
