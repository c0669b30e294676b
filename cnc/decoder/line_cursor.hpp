#pragma once
// Reads an NC line from left to right, white space skipped before each
// token, without backtracking: the fixed forms $FOR P<n> = .., P<n> = ..
// and V.G.M_FCT[<m>].PRE_OUTP_PATH = .. are read with it rather than with
// std::regex, whose recursion overflowed the stack on lines of ~100,000
// characters (KRN-1: bad input never crashes).
#include <cctype>
#include <string_view>

namespace hil::cnc::decoding {

class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  // `c` next; a letter in either case.
  bool take(char c) {
    skip_blanks();
    if (pos_ == text_.size() || std::toupper(static_cast<unsigned char>(text_[pos_])) != c) return false;
    ++pos_;
    return true;
  }
  // `keyword` (upper case) next, in any case, not continued by a letter,
  // digit or '_' ($FORX is not $FOR).
  bool take_keyword(std::string_view keyword) {
    skip_blanks();
    if (text_.size() - pos_ < keyword.size()) return false;
    for (size_t k = 0; k < keyword.size(); ++k)
      if (std::toupper(static_cast<unsigned char>(text_[pos_ + k])) != keyword[k]) return false;
    const size_t end = pos_ + keyword.size();
    if (end < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '_')) return false;
    pos_ = end;
    return true;
  }
  // The decimal digits right here, no blank before them (none: empty).
  std::string_view take_digits() {
    const size_t begin = pos_;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(begin, pos_ - begin);
  }
  // An N number and the blank after it, if the block starts with them.
  void skip_block_nr() {
    const size_t begin = pos_;
    if (take('N') && !take_digits().empty() && pos_ < text_.size() && is_blank(text_[pos_])) return;
    pos_ = begin;
  }
  bool at_end() {
    skip_blanks();
    return pos_ == text_.size();
  }
  std::string_view rest() const { return text_.substr(pos_); }
  void skip_blanks() {
    while (pos_ < text_.size() && is_blank(text_[pos_])) ++pos_;
  }

 private:
  static bool is_blank(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

  std::string_view text_;
  size_t pos_ = 0;
};

}  // namespace hil::cnc::decoding
