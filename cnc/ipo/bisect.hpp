#pragma once
// Bisection down to adjacent doubles, for the monotone questions of the
// planners ("does this velocity still fit?").
#include <cmath>

namespace hil::cnc {

// `good` satisfies `fits`, `bad` does not (either order on the axis); the
// predicate changes once between them. Returns the last value that fits.
template <typename Fits>
double last_fitting(double good, double bad, Fits fits) {
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double mid = (good + bad) / 2;
    if (mid == good || mid == bad) break;
    (fits(mid) ? good : bad) = mid;
  }
  return good;
}

// The same question where it is "f(x) <= limit" for an f that grows
// smoothly from `good` to `bad` (f_good = f(good) <= limit < f_bad =
// f(bad)): the same answer, the last double that fits, in a few
// evaluations instead of one per bit. False position, Illinois' way (the
// end that stays twice has its value halved, so that both ends close in),
// and, where the estimate does not fall strictly between, the next double
// from the end it falls on or a bisection step in turn.
template <typename F>
double last_below(double good, double bad, double limit, double f_good, double f_bad, F f) {
  double g_good = f_good - limit, g_bad = f_bad - limit;  // <= 0, > 0
  int good_stayed = 0, bad_stayed = 0;
  bool nudge = true;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double mid = (good + bad) / 2;
    if (mid == good || mid == bad) break;
    double x = good - g_good * (bad - good) / (g_bad - g_good);
    if (!((good < bad) ? (x > good && x < bad) : (x < good && x > bad))) {
      // The estimate is on an end (a root found to the last bit, or an
      // end's value halved to nothing): the next double from that end,
      // which mostly closes the bracket; every other time a bisection.
      const bool at_good = (good < bad) ? !(x > good) : !(x < good);
      x = nudge ? (at_good ? std::nextafter(good, bad) : std::nextafter(bad, good)) : mid;
      nudge = !nudge;
    }
    const double g = f(x) - limit;
    if (g <= 0) {
      good = x;
      g_good = g;
      good_stayed = 0;
      if (++bad_stayed >= 2) g_bad /= 2;
    } else {
      bad = x;
      g_bad = g;
      bad_stayed = 0;
      if (++good_stayed >= 2) g_good /= 2;
    }
  }
  return good;
}

}  // namespace hil::cnc
