#pragma once
// The lexical level of one NC line (KRN-1): comments, words (an address
// letter and its number), and the error of a line.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hil::cnc::decoding {

// Thrown while one line is decoded; decode_program turns it into the Event
// of that line (NC line and N number are added there).
struct LineError {
  std::string message;
  int32_t id = 0;  // TF5200 error ID where the texts give one
};

// X10, G01, or an axis command in square brackets, Z[LIFT_START POS=40]:
// then `command` is what stands between the brackets (upper case, single
// blanks) and `value` is 0.
struct Word {
  char letter;
  double value;
  std::string text;     // as written, for messages (a long number shortened)
  std::string command;  // empty for a number
  bool is_axis_command() const { return !command.empty(); }
};

// The keyword of an axis command: LIFT_START of LIFT_START POS=40.
std::string command_keyword(const std::string& command);

// An NC line is text: a control character other than tab and CR (a NUL
// byte, binary data) is a LineError naming it and its column.
void check_characters(std::string_view line);

// `text` to quote in a message: control characters as \xNN, at most
// `max_bytes` (then "...").
std::string printable(std::string_view text, size_t max_bytes = 200);

// `line` without its `;` and `( )` comments.
std::string strip_comments(std::string_view line);

std::vector<Word> split_words(const std::string& code);

// The number of an N, G or M word: whole, 0..max (value_ranges.hpp).
int64_t integer_code(const Word& w, int64_t max);

// Upper case, blanks between words reduced to one: how '#' commands and
// axis commands are matched against their keywords.
std::string upper_words(const std::string& text);

// A '#' or '$' command the decoder does not know, starting at code[i].
LineError unsupported_command(const std::string& code, size_t i);

// The '=' of an assignment (P1 = 2): the first one outside square brackets,
// since inside them it belongs to an axis command (Z[LIFT_START POS=40]).
// std::string::npos if there is none.
size_t find_assignment(const std::string& code);

}  // namespace hil::cnc::decoding
