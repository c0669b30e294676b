#include "parameter_expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace hil::cnc {
namespace {

// Recursive descent: expression = term {(+|-) term}; term = factor {(*|/)
// factor}; factor = [-|+] (number | P<n> | "[" expression "]"). Round
// brackets are comments in NC programs, so grouping uses square ones.
class Parser {
 public:
  Parser(const std::string& text, const ParameterValues& parameters) : text_(text), parameters_(parameters) {}

  double parse() {
    const double value = expression();
    skip_space();
    if (pos_ != text_.size()) fail(std::string("unexpected '") + text_[pos_] + "'");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument(what + " in expression '" + text_ + "'");
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool take(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  double expression() {
    double value = term();
    for (;;) {
      if (take('+')) value += term();
      else if (take('-')) value -= term();
      else return value;
    }
  }
  double term() {
    double value = factor();
    for (;;) {
      if (take('*')) {
        value *= factor();
      } else if (take('/')) {
        const double divisor = factor();
        if (divisor == 0) fail("division by zero");
        value /= divisor;
      } else {
        return value;
      }
    }
  }
  double factor() {
    if (take('-')) return -factor();
    if (take('+')) return factor();
    if (take('[')) {
      const double value = expression();
      if (!take(']')) fail("']' missing");
      return value;
    }
    skip_space();
    if (pos_ < text_.size() && (text_[pos_] == 'P' || text_[pos_] == 'p')) {
      ++pos_;
      const size_t start = pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      if (start == pos_) fail("P needs a number");
      const int n = std::atoi(text_.substr(start, pos_ - start).c_str());
      const auto p = parameters_.find(n);
      if (p == parameters_.end()) fail("P" + std::to_string(n) + " has no value yet");
      return p->second;
    }
    const char* begin = text_.c_str() + pos_;
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || !std::isfinite(value)) fail(pos_ < text_.size() ? "a number or P<n> expected" : "incomplete");
    pos_ += static_cast<size_t>(end - begin);
    return value;
  }

  const std::string& text_;
  const ParameterValues& parameters_;
  size_t pos_ = 0;
};

}  // namespace

double evaluate_expression(const std::string& text, const ParameterValues& parameters) {
  return Parser(text, parameters).parse();
}

}  // namespace hil::cnc
