#include "parameter_expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "value_ranges.hpp"
#include "words.hpp"

namespace hil::cnc {
namespace {

// Recursive descent: expression = term {(+|-) term}; term = factor {(*|/)
// factor}; factor = [-|+] (number | P<n> | "[" expression "]"). Round
// brackets are comments in NC programs, so grouping uses square ones.
// Every intermediate result must be finite (1e300 * 1e300 is an error,
// not inf), and nesting is bounded, so a line of 100,000 '[' or '-' is an
// error rather than a stack overflow.
class Parser {
 public:
  Parser(const std::string& text, const ParameterValues& parameters, const VariableValues& variables)
      : text_(text), parameters_(parameters), variables_(variables) {}

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
  double checked(double value, char operation) const {
    if (!std::isfinite(value)) fail(std::string("result of '") + operation + "' out of range");
    return value;
  }
  size_t digits_from(size_t pos) const {
    while (pos < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos]))) ++pos;
    return pos;
  }
  double expression() {
    double value = term();
    for (;;) {
      if (take('+')) value = checked(value + term(), '+');
      else if (take('-')) value = checked(value - term(), '-');
      else return value;
    }
  }
  double term() {
    double value = factor();
    for (;;) {
      if (take('*')) {
        value = checked(value * factor(), '*');
      } else if (take('/')) {
        const double divisor = factor();
        if (divisor == 0) fail("division by zero");
        value = checked(value / divisor, '/');
      } else {
        return value;
      }
    }
  }
  double factor() {
    if (++depth_ > max_depth) fail("nested deeper than " + std::to_string(max_depth) + " levels");
    const double value = signed_factor();
    --depth_;
    return value;
  }
  double signed_factor() {
    if (take('-')) return -factor();
    if (take('+')) return factor();
    if (take('[')) {
      const double value = expression();
      if (!take(']')) fail("']' missing");
      return value;
    }
    skip_space();
    if (pos_ < text_.size() && (text_[pos_] == 'P' || text_[pos_] == 'p')) return parameter();
    if (pos_ < text_.size() && (text_[pos_] == 'V' || text_[pos_] == 'v')) return variable();
    return number();
  }
  double parameter() {
    const size_t start = ++pos_;
    pos_ = digits_from(pos_);
    if (start == pos_) fail("P needs a number");
    const std::optional<int64_t> n =
        decoding::whole_number(std::string_view(text_).substr(start, pos_ - start), decoding::max_p_parameter);
    if (!n) fail("P parameter numbers are 0.." + std::to_string(decoding::max_p_parameter));
    const auto p = parameters_.find(static_cast<int>(*n));
    if (p == parameters_.end()) fail("P" + std::to_string(*n) + " has no value yet");
    return p->second;
  }
  // V.G.<name>: letters, digits, '_' and '.' (any case).
  double variable() {
    const size_t start = pos_;
    std::string name;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' ||
                                   text_[pos_] == '.'))
      name += static_cast<char>(std::toupper(static_cast<unsigned char>(text_[pos_++])));
    const auto v = variables_.find(name);
    if (v == variables_.end()) {
      std::string known;
      for (const auto& [k, value] : variables_) known += (known.empty() ? "" : ", ") + k;
      fail("unknown variable '" + decoding::printable(text_.substr(start, pos_ - start), 40) + "'" +
           (known.empty() ? std::string() : " (known: " + known + ")"));
    }
    return v->second;
  }
  // Decimal only, [digits][.digits][e[+-]digits]: not strtod's nan, inf or 0x1p3.
  double number() {
    const size_t start = pos_;
    size_t end = digits_from(pos_);
    if (end < text_.size() && text_[end] == '.') end = digits_from(end + 1);
    if (end == start || (end == start + 1 && text_[start] == '.'))
      fail(pos_ < text_.size() ? "a number or P<n> expected" : "incomplete");
    if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
      size_t exponent = end + 1;
      if (exponent < text_.size() && (text_[exponent] == '+' || text_[exponent] == '-')) ++exponent;
      if (digits_from(exponent) > exponent) end = digits_from(exponent);
    }
    const std::string literal = text_.substr(start, end - start);
    const double value = std::strtod(literal.c_str(), nullptr);
    if (!std::isfinite(value)) fail("number '" + decoding::printable(literal, 24) + "' out of range");
    pos_ = end;
    return value;
  }

  static constexpr int max_depth = 100;

  const std::string& text_;
  const ParameterValues& parameters_;
  const VariableValues& variables_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

double evaluate_expression(const std::string& text, const ParameterValues& parameters) {
  static const VariableValues none;
  return Parser(text, parameters, none).parse();
}

double evaluate_expression(const std::string& text, const ParameterValues& parameters,
                           const VariableValues& variables) {
  return Parser(text, parameters, variables).parse();
}

}  // namespace hil::cnc
