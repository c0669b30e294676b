#include "slope.hpp"

#include <cmath>
#include <limits>

namespace hil::cnc {

const char* to_string(SlopeType type) {
  switch (type) {
    case SlopeType::step: return "STEP";
    case SlopeType::trapez: return "TRAPEZ";
    case SlopeType::sin2: return "SIN2";
  }
  return "?";
}

std::optional<SlopeType> parse_slope_type(const std::string& name) {
  if (name == "STEP") return SlopeType::step;
  if (name == "TRAPEZ") return SlopeType::trapez;
  if (name == "SIN2") return SlopeType::sin2;
  return std::nullopt;
}

double ramp_rate(const Limits& lim, SlopeType slope) {
  switch (slope) {
    case SlopeType::step: return std::numeric_limits<double>::infinity();
    case SlopeType::trapez: return lim.j;
    case SlopeType::sin2: return lim.j / 2;  // a sin² pulse of peak j averages j/2
  }
  return lim.j;
}

double unwind_rate(const Limits& lim, SlopeType slope) {
  return slope == SlopeType::step ? std::numeric_limits<double>::infinity() : lim.j;
}

double velocity_after_ramp_to_zero(double v, double a, const Limits& lim, SlopeType slope) {
  return v + a * std::abs(a) / (2 * unwind_rate(lim, slope));
}

}  // namespace hil::cnc
