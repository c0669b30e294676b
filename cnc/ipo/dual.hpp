#pragma once
// A value with its derivative along one parameter (forward-mode automatic
// differentiation): the position planner's switch search evaluates the
// overshoot with it to take Newton steps (issue 36 item 3). Only the
// operations the closed-form velocity change uses.
#include <cmath>

namespace hil::cnc {

struct Dual {
  double x = 0;  // the value
  double d = 0;  // its derivative
};

inline double value_of(double x) { return x; }
inline double value_of(const Dual& x) { return x.x; }

inline Dual operator+(Dual a, Dual b) { return {a.x + b.x, a.d + b.d}; }
inline Dual operator-(Dual a, Dual b) { return {a.x - b.x, a.d - b.d}; }
inline Dual operator-(Dual a) { return {-a.x, -a.d}; }
inline Dual operator*(Dual a, Dual b) { return {a.x * b.x, a.d * b.x + a.x * b.d}; }
// Divisions by a reciprocal: the search's evaluations are latency-bound on
// them, and their values may differ from double's by an ulp.
inline Dual operator/(Dual a, Dual b) {
  const double r = 1 / b.x, x = a.x * r;
  return {x, (a.d - x * b.d) * r};
}
inline Dual operator+(Dual a, double b) { return {a.x + b, a.d}; }
inline Dual operator+(double a, Dual b) { return {a + b.x, b.d}; }
inline Dual operator-(Dual a, double b) { return {a.x - b, a.d}; }
inline Dual operator-(double a, Dual b) { return {a - b.x, -b.d}; }
inline Dual operator*(Dual a, double b) { return {a.x * b, a.d * b}; }
inline Dual operator*(double a, Dual b) { return {a * b.x, a * b.d}; }
inline Dual operator/(Dual a, double b) {
  const double r = 1 / b;
  return {a.x * r, a.d * r};
}
inline Dual operator/(double a, Dual b) { return {a / b.x, -a * b.d / (b.x * b.x)}; }

// At 0 the root's derivative is infinite: taken as 0 (the planners meet it
// only where a plateau vanishes, and Newton falls back on its bracket).
inline Dual sqrt(Dual a) {
  const double r = std::sqrt(a.x);
  return {r, r > 0 ? a.d / (2 * r) : 0.0};
}

}  // namespace hil::cnc
