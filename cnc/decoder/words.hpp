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
  int32_t id = 0;    // TF5200 error ID where the texts give one
  std::string word = {};  // the refused word as written ("G41"), for its column; empty if none
};

// X10, G01, or an axis command in square brackets, Z[LIFT_START POS=40]:
// then `command` is what stands between the brackets (upper case, single
// blanks) and `value` is 0.
struct Word {
  char letter;  // upper case
  double value;
  // A view into the line, valid while it is decoded: the number as written,
  // or the whole axis command from its letter to the ']'. Only a message
  // needs it as a string (text()), and few lines have one.
  std::string_view written;
  std::string command;  // empty for a number
  bool is_axis_command() const { return !command.empty(); }
  // The word for messages: X10 (a long number shortened), Z[LIFT_END].
  std::string text() const;
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
// The same without a copy for a line that has none (most): `line` itself,
// else `storage` filled.
std::string_view without_comments(std::string_view line, std::string& storage);

std::vector<Word> split_words(std::string_view code);
// The same into `words` (cleared first), whose capacity is kept from line to
// line. The words view `code`.
void split_words(std::string_view code, std::vector<Word>& words);

// The number of an N, G or M word: whole, 0..max (value_ranges.hpp).
int64_t integer_code(const Word& w, int64_t max);

// Upper case, blanks between words reduced to one: how '#' commands and
// axis commands are matched against their keywords.
std::string upper_words(std::string_view text);

// A '#' or '$' command the decoder does not know, starting at code[i].
LineError unsupported_command(std::string_view code, size_t i);

// The '=' of an assignment (P1 = 2): the first one outside square brackets,
// since inside them it belongs to an axis command (Z[LIFT_START POS=40]).
// std::string::npos if there is none.
size_t find_assignment(std::string_view code);

}  // namespace hil::cnc::decoding
