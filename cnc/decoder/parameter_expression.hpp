#pragma once
// Arithmetic of P parameters as the decoder evaluates it (KRN-1): numbers,
// P<n>, + - * /, unary minus and square brackets, e.g. "P1 * [2 + P3] / 4"
// (round brackets are comments in NC programs).
// P parameters are decoder variables: they take their values while the
// program is decoded, ahead of the interpolator.
#include <map>
#include <string>

namespace hil::cnc {

using ParameterValues = std::map<int, double>;

// Throws std::invalid_argument naming what is wrong (unknown parameter,
// division by zero, a stray character).
double evaluate_expression(const std::string& text, const ParameterValues& parameters);

}  // namespace hil::cnc
