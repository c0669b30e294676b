#pragma once
// Bisection down to adjacent doubles, for the monotone questions of the
// planners ("does this velocity still fit?").
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

}  // namespace hil::cnc
