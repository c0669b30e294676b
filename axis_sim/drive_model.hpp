#pragma once
// A drive as the CNC sees it (RIG-3): position loop with gain kv and
// velocity feed-forward, the velocity loop as a first-order lag. Discretised
// exactly (zero-order hold, matrix exponential) at the cycle time.
#include <Eigen/Dense>

namespace hil::axis {

struct DriveParameters {
  double kv = 0;              // 1/s, position loop gain
  double velocity_lag_s = 0;  // s, velocity loop time constant
  double cycle_time_s = 0;    // s
};

struct DriveOutput {
  double position = 0;         // mm, actual
  double velocity = 0;         // mm/s, actual
  double acceleration = 0;     // mm/s^2, mean over the cycle
  double following_error = 0;  // mm, setpoint - actual
};

class DriveModel {
 public:
  // Throws std::invalid_argument if a parameter is not > 0.
  explicit DriveModel(const DriveParameters& parameters, double initial_position = 0);

  // Integrates one cycle under the setpoint (held over the cycle).
  DriveOutput step(double setpoint_position, double velocity_feedforward);

  const Eigen::Matrix2d& transition() const { return ad_; }

 private:
  Eigen::Matrix2d ad_;              // state: position, velocity
  Eigen::Matrix2d bd_;              // input: setpoint position, feed-forward velocity
  Eigen::Vector2d state_;
  double cycle_time_s_;
};

}  // namespace hil::axis
