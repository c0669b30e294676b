#include "slope.hpp"

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

}  // namespace hil::cnc
