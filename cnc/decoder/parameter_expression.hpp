#pragma once
// Arithmetic of P parameters as the decoder evaluates it (KRN-1): numbers,
// P<n>, + - * /, unary minus and square brackets, e.g. "P1 * [2 + P3] / 4"
// (round brackets are comments in NC programs), and V.G. variables
// (P1 = V.G.LIFT_ACTIVE * 2).
// P parameters are decoder variables: they take their values while the
// program is decoded, ahead of the interpolator.
#include <functional>
#include <map>
#include <string>

namespace hil::cnc {

using ParameterValues = std::map<int, double>;
// V.G. variables readable in expressions (V.G.LIFT_ACTIVE), by upper-case name.
using VariableValues = std::map<std::string, double, std::less<>>;

// Throws std::invalid_argument naming what is wrong (unknown parameter,
// division by zero, a stray character).
double evaluate_expression(const std::string& text, const ParameterValues& parameters);
// The same with V.G.<name> variables (any case; an unknown one is an error).
double evaluate_expression(const std::string& text, const ParameterValues& parameters,
                           const VariableValues& variables);

}  // namespace hil::cnc
