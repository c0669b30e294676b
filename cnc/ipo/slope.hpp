#pragma once
// Slope types of #SLOPE[TYPE=..] (KRN-3): how the acceleration changes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace hil::cnc {

enum class SlopeType {
  step,    // STEP: acceleration jumps; only velocity and acceleration limited
  trapez,  // TRAPEZ: acceleration ramps at constant jerk j_max
  sin2,    // SIN2: acceleration ramps with a sin² jerk pulse of peak j_max
};

const char* to_string(SlopeType type);
std::optional<SlopeType> parse_slope_type(const std::string& name);  // "STEP", "TRAPEZ", "SIN2"

// Limits of one motion; all > 0 (j is not used by STEP).
struct Limits {
  double v = 0;
  double a = 0;
  double j = 0;

  // No limit at all: what a cap is where there is none.
  static constexpr Limits none() {
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
  }
};

// The lower of each (a limit under a cap: the lift function's, LIFT-2).
inline Limits capped(const Limits& lim, const Limits& cap) {
  return {std::min(lim.v, cap.v), std::min(lim.a, cap.a), std::min(lim.j, cap.j)};
}

// Mean jerk over a ramp of the slope type (infinite for STEP): a ramp of da
// takes |da| / rate and changes the velocity by (a_from + a_to) |da| / (2 rate).
inline double ramp_rate(const Limits& lim, SlopeType slope) {
  switch (slope) {
    case SlopeType::step: return std::numeric_limits<double>::infinity();
    case SlopeType::trapez: return lim.j;
    case SlopeType::sin2: return lim.j / 2;  // a sin² pulse of peak j averages j/2
  }
  return lim.j;
}

// Jerk with which a start acceleration is brought back towards 0: full
// jerk for every slope type (infinite for STEP). A SIN2 state met in the
// middle of a ramp (replanning at a block transition, feed hold) must not
// wait for a fresh sin² pulse: that would carry |v| past the velocity the
// interrupted ramp was heading for.
inline double unwind_rate(const Limits& lim, SlopeType slope) {
  return slope == SlopeType::step ? std::numeric_limits<double>::infinity() : lim.j;
}

// The velocity reached when the start acceleration a is brought straight
// back to 0 (at unwind_rate).
inline double velocity_after_ramp_to_zero(double v, double a, const Limits& lim, SlopeType slope) {
  return v + a * std::abs(a) / (2 * unwind_rate(lim, slope));
}

}  // namespace hil::cnc
