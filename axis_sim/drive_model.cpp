#include "drive_model.hpp"

#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

namespace hil::axis {

DriveModel::DriveModel(const DriveParameters& p, double initial_position)
    : state_(initial_position, 0.0), cycle_time_s_(p.cycle_time_s) {
  if (!(p.kv > 0) || !(p.velocity_lag_s > 0) || !(p.cycle_time_s > 0))
    throw std::invalid_argument("drive model: kv, velocity_lag_s and cycle time must be > 0");
  // x' = v;  v' = (v_ff + kv (x_set - x) - v) / T
  Eigen::Matrix<double, 4, 4> augmented = Eigen::Matrix<double, 4, 4>::Zero();
  const double t = p.velocity_lag_s;
  augmented(0, 1) = 1;
  augmented(1, 0) = -p.kv / t;
  augmented(1, 1) = -1 / t;
  augmented(1, 2) = p.kv / t;
  augmented(1, 3) = 1 / t;
  const Eigen::Matrix<double, 4, 4> discrete = (augmented * p.cycle_time_s).exp();
  ad_ = discrete.block<2, 2>(0, 0);
  bd_ = discrete.block<2, 2>(0, 2);
}

DriveOutput DriveModel::step(double setpoint_position, double velocity_feedforward) {
  const double previous_velocity = state_(1);
  state_ = ad_ * state_ + bd_ * Eigen::Vector2d(setpoint_position, velocity_feedforward);
  DriveOutput out;
  out.position = state_(0);
  out.velocity = state_(1);
  out.acceleration = (state_(1) - previous_velocity) / cycle_time_s_;
  out.following_error = setpoint_position - state_(0);
  return out;
}

}  // namespace hil::axis
