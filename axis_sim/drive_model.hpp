#pragma once
// A drive as the CNC sees it (RIG-3): position loop with gain kv and
// velocity feed-forward, the velocity loop as a first- or second-order lag,
// the torque limit as an acceleration limit (saturation), Coulomb and
// viscous friction. The linear part is discretised exactly (matrix
// exponential, setpoints held over the cycle); saturation and Coulomb
// friction switch the linear mode at 1/10 of the cycle.
#include <Eigen/Dense>

#include <limits>

#include "machine_config.hpp"

namespace hil::axis {

struct DriveParameters {
  double kv = 0;                 // 1/s, position loop gain (P-AXIS-00099 style); 0 opens the loop
  double velocity_lag_s = 0;     // s: T of the first-order lag, 1/omega of the second-order one
  double cycle_time_s = 0;       // s
  int velocity_loop_order = 1;   // 1: v' = (v_cmd - v) / T; 2: damped second-order response
  double velocity_damping = 1;   // zeta of the second-order velocity loop
  double feedforward = 1;        // velocity feed-forward factor
  double acceleration_limit = std::numeric_limits<double>::infinity();  // mm/s^2, torque limit / inertia
  double coulomb_friction = 0;   // mm/s^2, friction force / inertia
  double viscous_friction = 0;   // 1/s, deceleration per unit of velocity
};

struct DriveOutput {
  double position = 0;         // mm, actual
  double velocity = 0;         // mm/s, actual
  double acceleration = 0;     // mm/s^2, mean over the cycle
  double following_error = 0;  // mm, setpoint - actual
};

class DriveModel {
 public:
  // Throws std::invalid_argument naming the parameter if one is out of
  // range or the closed loop is unstable (second order: kv < 2 zeta omega).
  explicit DriveModel(const DriveParameters& parameters, double initial_position = 0);

  // Integrates one cycle under the setpoint (held over the cycle). A
  // setpoint that is not finite is not taken: the drive holds the last
  // valid one, without feed-forward (the monitor reports it as an error).
  DriveOutput step(double setpoint_position, double velocity_feedforward);

  // One cycle's state transition of the linear (unsaturated) loop, over the
  // states in use: position, velocity (and drive acceleration, second order).
  Eigen::MatrixXd cycle_transition() const;
  int states() const { return p_.velocity_loop_order == 1 ? 2 : 3; }

 private:
  // z' = A z + B w over a step, exactly: z+ = ad z + bd w, with the inputs
  // w = (setpoint, feed-forward velocity, constant acceleration).
  struct Discrete {
    Eigen::Matrix3d ad;
    Eigen::Matrix3d bd;
  };
  static Discrete discretise(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, double h);
  void substep(double setpoint, double feedforward);

  DriveParameters p_;
  Discrete unsaturated_, saturated_;
  int substeps_ = 1;
  double h_ = 0;                  // substep, s
  Eigen::Vector3d state_;         // position, velocity, drive acceleration (second order only)
  double last_valid_setpoint_;    // mm
};

// The model of a configured axis at the cycle time.
DriveParameters drive_parameters(const AxisConfig& axis, double cycle_time_s);

}  // namespace hil::axis
