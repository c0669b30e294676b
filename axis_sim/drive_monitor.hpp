#pragma once
// The drive's monitoring of one axis (RIG-3), each limit with its TF5200
// parameter: acceleration P-AXIS-00441/00442, velocity P-AXIS-00439/00440,
// following error P-AXIS-00168/00169 (P-AXIS-00172 type 4), software limit
// switches P-AXIS-00177/00178 (+ P-AXIS-00179). Limits in docs/UNITS.md.
// A setpoint that is not a finite number is an error of its own.
#include <cstdint>
#include <vector>

#include "event.hpp"
#include "machine_config.hpp"

namespace hil::axis {

// Bits of MonitorState::warnings / errors; the same values as the
// MONITOR_* constants of axis_state_t.
namespace monitor {
constexpr int32_t acceleration = 0x1;
constexpr int32_t velocity = 0x2;
constexpr int32_t following_error = 0x4;
constexpr int32_t software_limit = 0x8;
constexpr int32_t not_finite = 0x10;  // a setpoint (or actual value) that is not a finite number
}  // namespace monitor

struct MonitorState {
  int32_t warnings = 0;  // monitor:: bits above a warning limit this cycle
  int32_t errors = 0;    // monitor:: bits above an error limit this cycle
};

// One cycle of the drive as the monitors see it.
struct DriveSample {
  double setpoint_position = 0;  // mm
  double setpoint_velocity = 0;  // mm/s
  double position = 0;           // mm, actual
  double velocity = 0;           // mm/s, actual
  double acceleration = 0;       // mm/s², actual
  double following_error = 0;    // mm
};

class DriveMonitor {
 public:
  explicit DriveMonitor(const AxisConfig& axis);

  // Checks one cycle; raises an event when a limit is first exceeded (not
  // again every cycle while it stays exceeded).
  MonitorState check(const DriveSample& sample, std::vector<Event>& events);

 private:
  AxisConfig axis_;
  MonitorState previous_;
};

}  // namespace hil::axis
