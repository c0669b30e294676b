#pragma once
// $FOR P<n> = <start>, <end> [, <step>] ... $ENDFOR (KRN-1): the lines
// between run while P<n> has not passed <end>; loops nest.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "parameter_expression.hpp"

namespace hil::cnc::decoding {

class ForLoops {
 public:
  // The line to read after line `i` if it is a $FOR or $ENDFOR, else none.
  // Throws LineError, or std::invalid_argument from an expression.
  std::optional<size_t> control_flow(const std::vector<std::string_view>& lines, size_t i,
                                     ParameterValues& parameters);

 private:
  struct Loop {
    size_t first_line;  // the line after $FOR
    int parameter;
    double end;
    double step;
    bool done(double value) const { return step > 0 ? value > end + 1e-9 : value < end - 1e-9; }
  };

  size_t begin_loop(const std::string& code, const std::vector<std::string_view>& lines, size_t i,
                    ParameterValues& parameters);
  size_t end_of_body(size_t i, ParameterValues& parameters);

  std::vector<Loop> loops_;  // open, innermost last
};

}  // namespace hil::cnc::decoding
