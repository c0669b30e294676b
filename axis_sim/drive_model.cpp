#include "drive_model.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

namespace hil::axis {
namespace {

double sign(double x) { return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0); }

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("drive model: " + what);
}

}  // namespace

DriveParameters drive_parameters(const AxisConfig& axis, double cycle_time_s) {
  DriveParameters p{axis.kv, axis.velocity_lag_s, cycle_time_s};
  p.velocity_loop_order = axis.velocity_loop_order;
  p.velocity_damping = axis.velocity_damping;
  p.feedforward = axis.velocity_feedforward;
  if (axis.drive_acceleration_limit > 0) p.acceleration_limit = axis.drive_acceleration_limit;
  p.coulomb_friction = axis.friction_coulomb;
  p.viscous_friction = axis.friction_viscous;
  return p;
}

DriveModel::Discrete DriveModel::discretise(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, double h) {
  Eigen::Matrix<double, 6, 6> augmented = Eigen::Matrix<double, 6, 6>::Zero();
  augmented.block<3, 3>(0, 0) = a;
  augmented.block<3, 3>(0, 3) = b;
  const Eigen::Matrix<double, 6, 6> discrete = (augmented * h).exp();
  return {discrete.block<3, 3>(0, 0), discrete.block<3, 3>(0, 3)};
}

DriveModel::DriveModel(const DriveParameters& p, double initial_position)
    : p_(p), state_(initial_position, 0.0, 0.0), last_valid_setpoint_(initial_position) {
  require(p.kv >= 0 && std::isfinite(p.kv), "kv must be >= 0");
  require(p.velocity_lag_s > 0 && std::isfinite(p.velocity_lag_s), "velocity_lag_s must be > 0");
  require(p.cycle_time_s > 0 && std::isfinite(p.cycle_time_s), "the cycle time must be > 0");
  require(p.velocity_loop_order == 1 || p.velocity_loop_order == 2, "velocity_loop_order must be 1 or 2");
  require(p.velocity_damping > 0 && std::isfinite(p.velocity_damping), "velocity_damping must be > 0");
  require(p.feedforward >= 0 && p.feedforward <= 1, "velocity feed-forward must be within 0 .. 1");
  require(p.acceleration_limit > 0, "the drive's acceleration limit must be > 0");
  require(p.coulomb_friction >= 0 && std::isfinite(p.coulomb_friction), "Coulomb friction must be >= 0");
  require(p.viscous_friction >= 0 && std::isfinite(p.viscous_friction), "viscous friction must be >= 0");

  const double b = p.viscous_friction;
  Eigen::Matrix3d a_lin = Eigen::Matrix3d::Zero(), b_lin = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d a_sat = Eigen::Matrix3d::Zero(), b_sat = Eigen::Matrix3d::Zero();
  // x' = v in every mode; the constant acceleration input (friction, the
  // saturated torque) acts on v.
  a_lin(0, 1) = a_sat(0, 1) = 1;
  b_lin(1, 2) = b_sat(1, 2) = 1;
  a_sat(1, 1) = -b;
  if (p.velocity_loop_order == 1) {
    // v' = (ff v_ff + kv (x_set - x) - v) / T - b v + d
    const double t = p.velocity_lag_s;
    a_lin(1, 0) = -p.kv / t;
    a_lin(1, 1) = -1 / t - b;
    b_lin(1, 0) = p.kv / t;
    b_lin(1, 1) = p.feedforward / t;
  } else {
    // v' = a - b v + d;  a' = w² (ff v_ff + kv (x_set - x) - v) - 2 zeta w a
    const double w = 1 / p.velocity_lag_s, zeta = p.velocity_damping;
    require(p.kv < 2 * zeta * w,
            "the position loop is unstable with a second-order velocity loop unless kv < 2 velocity_damping / "
            "velocity_lag_s (kv " + std::to_string(p.kv) + " >= " + std::to_string(2 * zeta * w) + ")");
    a_lin(1, 1) = -b;
    a_lin(1, 2) = 1;
    a_lin(2, 0) = -w * w * p.kv;
    a_lin(2, 1) = -w * w;
    a_lin(2, 2) = -2 * zeta * w;
    b_lin(2, 0) = w * w * p.kv;
    b_lin(2, 1) = w * w * p.feedforward;
    a_sat(1, 2) = 1;  // the drive acceleration stays at the limit
  }
  // The continuous loop must be stable (the position integrator of an open
  // loop, kv = 0, aside); the exact discretisation keeps it so at any cycle.
  const int n = states();
  const Eigen::VectorXcd poles = Eigen::MatrixXd(a_lin.topLeftCorner(n, n)).eigenvalues();
  for (int i = 0; i < n; ++i)
    require(poles(i).real() < 0 || (p.kv == 0 && std::abs(poles(i)) < 1e-12),
            "the closed loop is unstable (pole at " + std::to_string(poles(i).real()) + " 1/s)");
  const bool nonlinear = std::isfinite(p.acceleration_limit) || p.coulomb_friction > 0;
  substeps_ = nonlinear ? 10 : 1;
  h_ = p.cycle_time_s / substeps_;
  unsaturated_ = discretise(a_lin, b_lin, h_);
  saturated_ = discretise(a_sat, b_sat, h_);
}

void DriveModel::substep(double setpoint, double feedforward) {
  const double x = state_(0), v = state_(1);
  const double v_cmd = p_.feedforward * feedforward + p_.kv * (setpoint - x);
  // The drive's torque as acceleration, and whether it is at the limit.
  double torque = 0;
  bool saturated = false;
  if (p_.velocity_loop_order == 1) {
    const double demand = (v_cmd - v) / p_.velocity_lag_s;
    saturated = std::abs(demand) > p_.acceleration_limit;
    torque = saturated ? sign(demand) * p_.acceleration_limit : demand;
  } else {
    const double w = 1 / p_.velocity_lag_s;
    const double rising = w * w * (v_cmd - v) - 2 * p_.velocity_damping * w * state_(2);
    saturated = std::abs(state_(2)) >= p_.acceleration_limit && sign(rising) == sign(state_(2));
    if (saturated) state_(2) = sign(state_(2)) * p_.acceleration_limit;
    torque = state_(2);
  }
  // Coulomb friction opposes the motion; at rest it holds the axis until
  // the torque exceeds it (stiction).
  double d = 0;
  bool stuck = false;
  if (p_.coulomb_friction > 0) {
    const double at_rest = p_.coulomb_friction * h_;  // friction stops this much velocity within a substep
    stuck = std::abs(v) <= at_rest && std::abs(torque - p_.viscous_friction * v) <= p_.coulomb_friction;
    if (stuck) {
      d = -torque;
    } else {
      d = -p_.coulomb_friction * (std::abs(v) > at_rest ? sign(v) : sign(torque));
    }
  }
  if (saturated && p_.velocity_loop_order == 1) d += torque;
  const Discrete& mode = saturated ? saturated_ : unsaturated_;
  state_ = mode.ad * state_ + mode.bd * Eigen::Vector3d(setpoint, feedforward, d);
  if (stuck) {  // held by friction: only the drive's own acceleration state moves on
    state_(0) = x;
    state_(1) = 0;
  }
  if (p_.velocity_loop_order == 2 && std::abs(state_(2)) > p_.acceleration_limit)
    state_(2) = sign(state_(2)) * p_.acceleration_limit;
}

Eigen::MatrixXd DriveModel::cycle_transition() const {
  Eigen::MatrixXd ad = unsaturated_.ad.topLeftCorner(states(), states());
  Eigen::MatrixXd out = Eigen::MatrixXd::Identity(states(), states());
  for (int i = 0; i < substeps_; ++i) out = ad * out;
  return out;
}

DriveOutput DriveModel::step(double setpoint_position, double velocity_feedforward) {
  if (std::isfinite(setpoint_position) && std::isfinite(velocity_feedforward)) {
    last_valid_setpoint_ = setpoint_position;
  } else {
    setpoint_position = last_valid_setpoint_;
    velocity_feedforward = 0;
  }
  const double previous_velocity = state_(1);
  for (int i = 0; i < substeps_; ++i) substep(setpoint_position, velocity_feedforward);
  DriveOutput out;
  out.position = state_(0);
  out.velocity = state_(1);
  out.acceleration = (state_(1) - previous_velocity) / p_.cycle_time_s;
  out.following_error = setpoint_position - state_(0);
  return out;
}

}  // namespace hil::axis
