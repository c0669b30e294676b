#include "value_ranges.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "words.hpp"

namespace hil::cnc::decoding {

double checked_length(double value, std::string_view what) {
  if (std::isfinite(value) && std::abs(value) <= max_length_mm) return value;
  std::ostringstream msg;
  msg << std::setprecision(15) << what << " " << value << " mm is out of range (|value| <= " << max_length_mm
      << " mm)";
  throw LineError{msg.str()};
}

void check_position(const AxisValues& position, const MachineConfig& machine, std::string_view what) {
  for (size_t a = 0; a < position.size(); ++a)  // the name only for the message: this runs for every block
    if (!(std::abs(position[a]) <= max_length_mm))
      checked_length(position[a], std::string(what) + " " + machine.axes[a].name);
}

std::optional<int64_t> whole_number(std::string_view digits, int64_t max) {
  if (digits.empty()) return std::nullopt;
  int64_t value = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    // value * 10 + digit > max, without overflow (and right for a max below 10).
    if (value > max / 10 || value * 10 > max - (c - '0')) return std::nullopt;
    value = value * 10 + (c - '0');
  }
  return value;
}

}  // namespace hil::cnc::decoding
