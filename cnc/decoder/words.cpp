#include "words.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>

#include "short_decimal.hpp"

namespace hil::cnc::decoding {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }
// The "C" locale's classes, inline: the <cctype> calls were a fifth of
// the time per word.
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }
bool is_control(char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }

// "0x00" of a control character.
std::string hex_code(char c) {
  char code[8];
  std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
  return code;
}

// The ']' that closes the '[' at code[open] (expressions nest them), or npos.
size_t closing_bracket(std::string_view code, size_t open) {
  int depth = 0;
  for (size_t i = open; i < code.size(); ++i) {
    if (code[i] == '[') ++depth;
    else if (code[i] == ']' && --depth == 0) return i;
  }
  return std::string::npos;
}

// Z[LIFT_START ...] names a command; Z[P1 + 2] or Z[-5] is an expression,
// which axis words do not take yet: an address without a number.
bool names_command(const std::string& content) {
  if (content.empty() || !std::isalpha(static_cast<unsigned char>(content[0]))) return false;
  return !(content[0] == 'P' && content.size() > 1 && std::isdigit(static_cast<unsigned char>(content[1])));
}

// Z[LIFT_START POS=40]: the word from its letter at code[i] to the ']'
// closing the '[' at code[open]; none if the brackets hold no command.
std::optional<Word> axis_command_word(std::string_view code, char letter, size_t i, size_t open, size_t& end) {
  const size_t close = closing_bracket(code, open);
  const std::string content =
      upper_words(code.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1));
  if (!names_command(content)) return std::nullopt;
  if (close == std::string::npos)
    throw LineError{std::string("axis command '") + letter + "[" + command_keyword(content) + "' has no closing ']'"};
  end = close + 1;
  return Word{letter, 0.0, code.substr(i, end - i), content};
}

// The value of the number of `letter` that starts at code[j]; `end` after
// it. std::from_chars where read_decimal_digits has none: no locale, no
// allocation (strtod was a third of the decoder's time).
double number_value(std::string_view code, char letter, size_t j, size_t& end) {
  const size_t number_start = j;
  if (j < code.size() && (code[j] == '+' || code[j] == '-')) ++j;
  const size_t digits_start = j;
  const DecimalDigits read = read_decimal_digits(code.data() + j, code.data() + code.size());
  j = static_cast<size_t>(read.end - code.data());
  const std::string_view number(code.data() + number_start, j - number_start);
  if (!read.has_digit) throw LineError{std::string("address '") + letter + "' needs a number"};
  // X1e5 would read as X1 and an address E: say what is wrong instead.
  if (j + 1 < code.size() && (code[j] == 'e' || code[j] == 'E') &&
      (is_digit(code[j + 1]) || code[j + 1] == '+' || code[j + 1] == '-'))
    throw LineError{std::string("'") + letter + printable(number, 24) + code[j] +
                    "..': words take decimal numbers, no exponent"};
  // from_chars takes no '+'; the sign is applied after.
  const std::string_view unsigned_number(code.data() + digits_start, j - digits_start);
  double value = 0;
  if (read.value) {
    value = *read.value;
  } else {
    const char* const last = code.data() + j;
    const std::from_chars_result parsed = std::from_chars(code.data() + digits_start, last, value);
    if (parsed.ptr != last || (parsed.ec != std::errc() && parsed.ec != std::errc::result_out_of_range))
      throw LineError{std::string("malformed number '") + printable(number, 24) + "' after '" + letter + "'"};
    if (parsed.ec == std::errc::result_out_of_range) {
      // Beyond a double either way: as strtod has it (too large: infinite,
      // below the smallest: 0 or a denormal), rare enough to copy for.
      value = std::strtod(std::string(unsigned_number).c_str(), nullptr);
    }
  }
  if (code[number_start] == '-') value = -value;
  if (!std::isfinite(value))
    throw LineError{std::string("number '") + printable(number, 24) + "' after '" + letter + "' is out of range"};
  end = j;
  return value;
}

// The word starting at code[i], an address letter, onto `words`; `i`
// moves past it.
void read_word(std::string_view code, size_t& i, std::vector<Word>& words) {
  const char letter = upper(code[i]);
  size_t j = i + 1;
  while (j < code.size() && is_blank(code[j])) ++j;
  size_t end = j;
  if (j < code.size() && code[j] == '[') {
    if (std::optional<Word> word = axis_command_word(code, letter, i, j, end)) {
      i = end;
      words.push_back(std::move(*word));
      return;
    }
  }
  const double value = number_value(code, letter, j, end);
  Word& word = words.emplace_back();  // in place: most words are numbers
  word.letter = letter;
  word.value = value;
  word.written = code.substr(j, end - j);
  i = end;
}

}  // namespace

std::string Word::text() const {
  if (is_axis_command()) return printable(written, 60);
  // Digits, '.' and a sign: only a long number needs printable.
  if (written.size() <= 24) return letter + std::string(written);
  return letter + printable(written, 24);
}

namespace {
// Whether `line` may hold a control character, 8 bytes at a time (every
// line comes here): false means it has none; true also for a tab or a CR.
bool may_have_control(std::string_view line) {
  constexpr uint64_t ones = 0x0101010101010101, highs = 0x8080808080808080;
  auto has_below = [&](uint64_t x, uint64_t n) { return ((x - ones * n) & ~x & highs) != 0; };  // a byte < n (n <= 128)
  auto has_byte = [&](uint64_t x, uint64_t b) { return has_below(x ^ (ones * b), 1); };
  auto bad = [&](size_t i) {
    uint64_t x;
    std::memcpy(&x, line.data() + i, 8);
    return has_below(x, 0x20) || has_byte(x, 0x7f);
  };
  if (line.size() < 8) return std::any_of(line.begin(), line.end(), [](char c) { return is_control(c); });
  for (size_t i = 0; i + 8 <= line.size(); i += 8)
    if (bad(i)) return true;
  return bad(line.size() - 8);  // the last 8 bytes: the rest, overlapping
}
}  // namespace

void check_characters(std::string_view line) {
  if (!may_have_control(line)) return;
  const auto bad = std::find_if(line.begin(), line.end(), [](char c) { return is_control(c) && c != '\t' && c != '\r'; });
  if (bad == line.end()) return;
  throw LineError{"control character " + hex_code(*bad) + " in column " + std::to_string(bad - line.begin() + 1) +
                  ": an NC program is text"};
}

std::string printable(std::string_view text, size_t max_bytes) {
  // Every word's text comes here: most need no change.
  if (text.size() <= max_bytes && std::none_of(text.begin(), text.end(), [](char c) { return is_control(c); }))
    return std::string(text);
  size_t cut = std::min(text.size(), max_bytes);
  // Whole UTF-8 characters: not cut before a continuation byte.
  while (cut < text.size() && cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  std::string out;
  out.reserve(cut + 3);
  for (const char c : text.substr(0, cut)) {
    if (is_control(c) && c != '\t') out += "\\x" + hex_code(c).substr(2);
    else out += c;
  }
  if (cut < text.size()) out += "...";
  return out;
}

std::string command_keyword(const std::string& command) { return command.substr(0, command.find_first_of(" =")); }

namespace {
// Two memchr (vectorised) over the line; find_first_of calls memchr per character.
bool has_comment(std::string_view line) {
  return line.find(';') != std::string_view::npos || line.find('(') != std::string_view::npos;
}
}  // namespace

std::string_view without_comments(std::string_view line, std::string& storage) {
  if (!has_comment(line)) return line;
  storage = strip_comments(line);
  return storage;
}

std::string strip_comments(std::string_view line) {
  // Most lines have no comment.
  if (!has_comment(line)) return std::string(line);
  std::string out;
  bool in_paren = false;
  for (char c : line) {
    if (in_paren) {
      if (c == ')') in_paren = false;
      continue;
    }
    if (c == ';') break;
    if (c == '(') {
      in_paren = true;
      continue;
    }
    out += c;
  }
  if (in_paren) throw LineError{"comment '(' is not closed on this line"};
  return out;
}

LineError unsupported_command(std::string_view code, size_t i) {
  const size_t end = code.find_first_of(" \t[", i);
  return LineError{"command '" + std::string(code.substr(i, end == std::string_view::npos ? end : end - i)) +
                   "' is not supported yet"};
}

std::vector<Word> split_words(std::string_view code) {
  std::vector<Word> words;
  words.reserve(8);
  split_words(code, words);
  return words;
}

void split_words(std::string_view code, std::vector<Word>& words) {
  words.clear();
  size_t i = 0;
  while (i < code.size()) {
    const unsigned char c = static_cast<unsigned char>(code[i]);
    if (is_space(static_cast<char>(c))) {
      ++i;
      continue;
    }
    if (c == '#' || c == '$') throw unsupported_command(code, i);
    if (!is_letter(static_cast<char>(c))) throw LineError{std::string("unexpected character '") + code[i] + "'"};
    read_word(code, i, words);
  }
}

int64_t integer_code(const Word& w, int64_t max) {
  // Compared as doubles: the cast of a number beyond int64_t is undefined.
  if (w.value != std::floor(w.value) || w.value < 0 || w.value > static_cast<double>(max))
    throw LineError{"'" + w.text() + "' needs a whole number 0.." + std::to_string(max)};
  return static_cast<int64_t>(w.value);
}

std::string upper_words(std::string_view text) {
  std::istringstream in{std::string(text)};
  std::string word, out;
  while (in >> word) {
    for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}

size_t find_assignment(std::string_view code) {
  if (code.find('=') == std::string_view::npos) return std::string::npos;  // memchr: most lines
  for (size_t i = 0; i < code.size(); ++i) {
    if (code[i] == '=') return i;
    if (code[i] == '[') {
      i = closing_bracket(code, i);
      if (i == std::string::npos) break;
    }
  }
  return std::string::npos;
}

}  // namespace hil::cnc::decoding
