#pragma once
// $FOR P<n> = <start>, <end> [, <step>] ... $ENDFOR (KRN-1): the lines
// between run while P<n> has not passed <end>; loops nest. The lines of
// the open loops are held (LineStore) from the outermost loop's first body
// line on: a loop's body is read ahead to its $ENDFOR when it begins, at
// most max_body_lines lines.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "line_source.hpp"
#include "parameter_expression.hpp"
#include "tolerances.hpp"

namespace hil::cnc::decoding {

class ForLoops {
 public:
  // The line to read after line `i` if it is a $FOR or $ENDFOR, else none.
  // Throws LineError, or std::invalid_argument from an expression.
  std::optional<size_t> control_flow(LineStore& lines, size_t i, ParameterValues& parameters);
  // The first line an open loop may read again; none with no loop open.
  std::optional<size_t> oldest_needed() const {
    if (loops_.empty()) return std::nullopt;
    return loops_.front().first_line;
  }
  // A $FOR's $ENDFOR is looked for this far at most: the body is held.
  static constexpr size_t max_body_lines = 1000000;

 private:
  struct Loop {
    size_t first_line;  // the line after $FOR
    int parameter;
    double end;
    double step;
    bool done(double value) const { return step > 0 ? value > end + tolerance::length_mm : value < end - tolerance::length_mm; }
  };

  size_t begin_loop(const std::string& code, LineStore& lines, size_t i, ParameterValues& parameters);
  size_t end_of_body(size_t i, ParameterValues& parameters);

  std::vector<Loop> loops_;  // open, innermost last
};

}  // namespace hil::cnc::decoding
