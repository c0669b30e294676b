#include "words.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

namespace hil::cnc::decoding {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// The ']' that closes the '[' at code[open] (expressions nest them), or npos.
size_t closing_bracket(const std::string& code, size_t open) {
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
std::optional<Word> axis_command_word(const std::string& code, char letter, size_t i, size_t open, size_t& end) {
  const size_t close = closing_bracket(code, open);
  const std::string content =
      upper_words(code.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1));
  if (!names_command(content)) return std::nullopt;
  if (close == std::string::npos)
    throw LineError{std::string("axis command '") + letter + "[" + command_keyword(content) + "' has no closing ']'"};
  end = close + 1;
  return Word{letter, 0.0, code.substr(i, end - i), content};
}

// The word of `letter` whose number starts at code[j].
Word number_word(const std::string& code, char letter, size_t j, size_t& end) {
  const size_t number_start = j;
  if (j < code.size() && (code[j] == '+' || code[j] == '-')) ++j;
  bool digits = false;
  while (j < code.size() && (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.')) {
    digits = digits || code[j] != '.';
    ++j;
  }
  const std::string number = code.substr(number_start, j - number_start);
  if (!digits) throw LineError{std::string("address '") + letter + "' needs a number"};
  char* parse_end = nullptr;
  const double value = std::strtod(number.c_str(), &parse_end);
  if (parse_end != number.c_str() + number.size() || !std::isfinite(value))
    throw LineError{std::string("malformed number '") + number + "' after '" + letter + "'"};
  end = j;
  return Word{letter, value, std::string(1, letter) + number, std::string()};
}

// The word starting at code[i], an address letter; `i` moves past it.
Word read_word(const std::string& code, size_t& i) {
  const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(code[i])));
  size_t j = i + 1;
  while (j < code.size() && is_blank(code[j])) ++j;
  size_t end = j;
  if (j < code.size() && code[j] == '[') {
    if (std::optional<Word> word = axis_command_word(code, letter, i, j, end)) {
      i = end;
      return *word;
    }
  }
  Word word = number_word(code, letter, j, end);
  i = end;
  return word;
}

}  // namespace

std::string command_keyword(const std::string& command) { return command.substr(0, command.find_first_of(" =")); }

std::string strip_comments(const std::string& line) {
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

LineError unsupported_command(const std::string& code, size_t i) {
  const size_t end = code.find_first_of(" \t[", i);
  return LineError{"command '" + code.substr(i, end - i) + "' is not supported yet"};
}

std::vector<Word> split_words(const std::string& code) {
  std::vector<Word> words;
  size_t i = 0;
  while (i < code.size()) {
    const unsigned char c = static_cast<unsigned char>(code[i]);
    if (std::isspace(c)) {
      ++i;
      continue;
    }
    if (c == '#' || c == '$') throw unsupported_command(code, i);
    if (!std::isalpha(c)) throw LineError{std::string("unexpected character '") + code[i] + "'"};
    words.push_back(read_word(code, i));
  }
  return words;
}

int integer_code(const Word& w) {
  if (w.value != std::floor(w.value) || w.value < 0)
    throw LineError{"'" + w.text + "' needs a whole non-negative number"};
  return static_cast<int>(w.value);
}

std::string upper_words(const std::string& text) {
  std::istringstream in(text);
  std::string word, out;
  while (in >> word) {
    for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}

size_t find_assignment(const std::string& code) {
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
