#pragma once
// Slope types of #SLOPE[TYPE=..] (KRN-3): how the acceleration changes.
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
};

}  // namespace hil::cnc
