#include "acceleration_monitor.hpp"

#include <cmath>
#include <sstream>

namespace hil::axis {

AccelerationMonitor::AccelerationMonitor(const AxisConfig& axis) : axis_(axis) {}

AccelerationCheck AccelerationMonitor::check(double acceleration, std::vector<Event>& events) {
  AccelerationCheck now;
  const double magnitude = std::abs(acceleration);
  now.warning = magnitude > axis_.accel_warning_limit();
  now.error = magnitude > axis_.accel_error_limit();
  auto raise = [&](Severity severity, const char* parameter, int32_t value, double limit) {
    Event e;
    e.severity = severity;
    e.parameter = parameter;
    e.axis = axis_.name;
    e.value = acceleration;
    e.limit = limit;
    std::ostringstream msg;
    msg << "acceleration " << acceleration << " mm/s^2 exceeds " << limit << " mm/s^2 (a_max "
        << axis_.a_max << " * " << parameter << " " << value << " / 1000)";
    e.message = msg.str();
    events.push_back(e);
  };
  // Each threshold reports its own rising excursion: a jump past both in one
  // cycle gives the warning and the error.
  if (now.warning && !previous_.warning)
    raise(Severity::warning, "P-AXIS-00441", axis_.dyn_monitoring_a_warn, axis_.accel_warning_limit());
  if (now.error && !previous_.error)
    raise(Severity::error, "P-AXIS-00442", axis_.dyn_monitoring_a_err, axis_.accel_error_limit());
  previous_ = now;
  return now;
}

}  // namespace hil::axis
