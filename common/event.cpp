#include "event.hpp"

#include <sstream>

namespace hil {

const char* to_string(Severity severity) {
  switch (severity) {
    case Severity::info: return "info";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
  }
  return "?";
}

std::string describe(const Event& event) {
  std::ostringstream out;
  out << to_string(event.severity);
  if (event.id != 0) out << ' ' << event.id;
  if (!event.parameter.empty()) out << " (" << event.parameter << ')';
  if (!event.axis.empty()) out << " axis " << event.axis;
  if (event.nc_line > 0) out << " line " << event.nc_line;
  if (event.block_nr > 0) out << " N" << event.block_nr;
  out << ": " << event.message;
  return out.str();
}

}  // namespace hil
