#pragma once
// Acceleration overload monitoring per P-AXIS-00441 (warning) and
// P-AXIS-00442 (error), RIG-3: limits a_max * value / 1000 (docs/UNITS.md).
#include <optional>
#include <vector>

#include "event.hpp"
#include "machine_config.hpp"

namespace hil::axis {

struct AccelerationCheck {
  bool warning = false;  // |a| above the P-AXIS-00441 limit this cycle
  bool error = false;    // |a| above the P-AXIS-00442 limit this cycle
};

class AccelerationMonitor {
 public:
  explicit AccelerationMonitor(const AxisConfig& axis);

  // Checks one cycle's actual acceleration; an event is raised when a limit
  // is first exceeded (not again every cycle while it stays exceeded).
  AccelerationCheck check(double acceleration, std::vector<Event>& events);

 private:
  AxisConfig axis_;
  AccelerationCheck previous_;
};

}  // namespace hil::axis
