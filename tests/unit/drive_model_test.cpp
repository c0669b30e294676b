// RIG-3: the drive model against its analytic step response, and the
// drive monitoring: acceleration P-AXIS-00441/00442, velocity
// P-AXIS-00439/00440, following error P-AXIS-00168/00169 (P-AXIS-00172),
// software limit switches P-AXIS-00177/00178/00179.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "drive_model.hpp"
#include "drive_monitor.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::axis;

TEST_CASE("RIG-3 drive model: position step response equals the analytic solution", "[drive]") {
  const double kv = 40, T = 0.002, dt = 0.001;
  DriveModel drive({kv, T, dt});
  // x'' + x'/T + kv/T x = kv/T: real roots for these values.
  const double disc = std::sqrt(1 / (T * T) - 4 * kv / T);
  const double r1 = (-1 / T + disc) / 2, r2 = (-1 / T - disc) / 2;
  const double c1 = r2 / (r1 - r2), c2 = -1 - c1;  // x(0) = 0, x'(0) = 0
  for (int k = 1; k <= 500; ++k) {
    const DriveOutput out = drive.step(1.0, 0.0);
    const double t = k * dt;
    INFO("t = " << t);
    CHECK(out.position == Approx(1 + c1 * std::exp(r1 * t) + c2 * std::exp(r2 * t)).margin(1e-12));
    CHECK(out.velocity == Approx(c1 * r1 * std::exp(r1 * t) + c2 * r2 * std::exp(r2 * t)).margin(1e-9));
    CHECK(out.following_error == Approx(1 - out.position).margin(1e-15));
  }
}

TEST_CASE("RIG-3 drive model: with velocity feed-forward a ramp is followed without lag", "[drive]") {
  const double v = 100, dt = 0.001;
  DriveModel drive({40, 0.002, dt});
  DriveOutput out, previous;
  for (int k = 1; k <= 3000; ++k) {
    previous = out;
    out = drive.step(v * k * dt, v);
  }
  // Left: the half-cycle of the zero-order hold, v*dt/2 at most.
  CHECK(std::abs(out.following_error) < v * dt / 2 + 1e-9);
  // Within a cycle the held setpoint makes the velocity ripple; its mean is v.
  CHECK((out.position - previous.position) / dt == Approx(v).epsilon(1e-9));
  CHECK(out.velocity == Approx(v).epsilon(0.01));
}

namespace {

// Velocity feed-forward only (kv = 0): the velocity loop's own response.
DriveParameters velocity_loop(double lag_s) {
  DriveParameters p{0, lag_s, 0.001};
  return p;
}

}  // namespace

TEST_CASE("RIG-3 drive model: second-order velocity loop step equals the analytic response", "[drive]") {
  DriveParameters p = velocity_loop(0.002);  // omega = 500 rad/s
  p.velocity_loop_order = 2;
  p.velocity_damping = 0.5;
  DriveModel drive(p);
  const double w = 500, zeta = 0.5, wd = w * std::sqrt(1 - zeta * zeta), v0 = 100;
  double overshoot = 0;
  for (int k = 1; k <= 100; ++k) {
    const double t = k * 0.001;
    const double v = v0 * (1 - std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) *
                                                                               std::sin(wd * t)));
    const DriveOutput out = drive.step(0, v0);
    INFO("t = " << t);
    CHECK(out.velocity == Approx(v).margin(1e-9));
    overshoot = std::max(overshoot, out.velocity - v0);
  }
  CHECK(overshoot == Approx(v0 * std::exp(-zeta * M_PI / std::sqrt(1 - zeta * zeta))).epsilon(0.05));  // 16 %
}

TEST_CASE("RIG-3 drive model: the torque limit caps the acceleration (saturation), then the lag goes on",
          "[drive]") {
  DriveParameters p = velocity_loop(0.01);
  p.acceleration_limit = 2000;
  DriveModel drive(p);
  // Demand (100 - v) / T exceeds 2000 until v = 80, at t = 40 ms.
  for (int k = 1; k <= 200; ++k) {
    const double t = k * 0.001;
    const DriveOutput out = drive.step(0, 100);
    INFO("t = " << t);
    if (k <= 40) {
      CHECK(out.velocity == Approx(2000 * t).margin(1e-9));
      CHECK(out.acceleration == Approx(2000).margin(1e-6));
    } else {
      CHECK(out.velocity == Approx(100 - 20 * std::exp(-(t - 0.04) / 0.01)).margin(1e-6));
    }
  }
}

TEST_CASE("RIG-3 drive model: viscous and Coulomb friction against the analytic responses; stiction",
          "[drive]") {
  SECTION("viscous: v' = (v_ff - v) / T - b v") {
    DriveParameters p = velocity_loop(0.01);
    p.viscous_friction = 50;
    DriveModel drive(p);
    const double v_end = 100 / (1 + 50 * 0.01), rate = 1 / 0.01 + 50;
    for (int k = 1; k <= 100; ++k)
      CHECK(drive.step(0, 100).velocity == Approx(v_end * (1 - std::exp(-rate * k * 0.001))).margin(1e-9));
  }
  SECTION("Coulomb: v' = (v_ff - v) / T - c while moving") {
    DriveParameters p = velocity_loop(0.01);
    p.coulomb_friction = 1000;
    DriveModel drive(p);
    for (int k = 1; k <= 100; ++k)
      CHECK(drive.step(0, 100).velocity == Approx(90 * (1 - std::exp(-k * 0.001 / 0.01))).margin(1e-9));
  }
  SECTION("stiction: a torque below the Coulomb friction does not move the axis") {
    DriveParameters p = velocity_loop(0.01);
    p.coulomb_friction = 1000;
    DriveModel drive(p);
    for (int k = 1; k <= 100; ++k) {
      const DriveOutput out = drive.step(0, 5);  // torque 500 < 1000
      CHECK(out.position == 0);
      CHECK(out.velocity == 0);
    }
  }
  SECTION("a position loop with Coulomb friction stops within its dead band c T / kv") {
    DriveParameters p{40, 0.002, 0.001};
    p.coulomb_friction = 100;
    DriveModel drive(p);
    DriveOutput out;
    for (int k = 1; k <= 2000; ++k) out = drive.step(1, 0);
    CHECK(std::abs(out.following_error) <= 100 * 0.002 / 40 + 1e-12);
    CHECK(out.velocity == 0);
  }
}

TEST_CASE("RIG-3 drive model: the discrete system is stable; bad parameters are refused", "[drive]") {
  for (double dt : {0.0001, 0.001, 0.01, 0.1}) {
    for (int order : {1, 2}) {
      DriveParameters p{40, 0.002, dt};
      p.velocity_loop_order = order;
      p.velocity_damping = 0.7;
      p.viscous_friction = 5;
      DriveModel drive(p);
      const Eigen::VectorXcd eig = drive.cycle_transition().eigenvalues();
      REQUIRE(eig.size() == order + 1);
      for (int i = 0; i < eig.size(); ++i) CHECK(std::abs(eig(i)) < 1);
    }
  }
  CHECK_THROWS_AS(DriveModel({-1, 0.002, 0.001}), std::invalid_argument);
  CHECK_THROWS_AS(DriveModel({40, -1, 0.001}), std::invalid_argument);
  CHECK_THROWS_AS(DriveModel({40, 0.002, 0}), std::invalid_argument);
  DriveParameters second{40, 0.02, 0.001};
  second.velocity_loop_order = 2;
  second.velocity_damping = 0.3;  // 2 zeta / T = 30 < kv: the position loop oscillates up
  CHECK_THROWS_WITH(DriveModel(second), Catch::Contains("kv < 2 velocity_damping / velocity_lag_s"));
  second.velocity_loop_order = 3;
  CHECK_THROWS_WITH(DriveModel(second), Catch::Contains("velocity_loop_order"));
  DriveParameters friction{40, 0.002, 0.001};
  friction.coulomb_friction = -1;
  CHECK_THROWS_WITH(DriveModel(friction), Catch::Contains("Coulomb"));
}

namespace {

// A sample at rest on the setpoint but for the quantity a test sets.
DriveSample at_rest() { return {}; }

DriveSample with_acceleration(double a) {
  DriveSample s = at_rest();
  s.acceleration = a;
  return s;
}

}  // namespace

TEST_CASE("RIG-3 acceleration monitor: P-AXIS-00441 warning and P-AXIS-00442 error at a_max * value / 1000",
          "[drive]") {
  AxisConfig axis = test::xyz_machine().axes[0];  // a_max 2000, 1500 / 2000
  REQUIRE(axis.accel_warning_limit() == 3000);
  REQUIRE(axis.accel_error_limit() == 4000);
  DriveMonitor monitor(axis);
  std::vector<Event> events;
  CHECK(monitor.check(with_acceleration(2999), events).warnings == 0);
  CHECK(events.empty());
  MonitorState c = monitor.check(with_acceleration(-3001), events);
  CHECK(c.warnings == monitor::acceleration);
  CHECK(c.errors == 0);
  REQUIRE(events.size() == 1);
  CHECK(events[0].severity == Severity::warning);
  CHECK(events[0].parameter == "P-AXIS-00441");
  CHECK(events[0].value == -3001);
  CHECK(events[0].limit == 3000);
  monitor.check(with_acceleration(3500), events);  // still above: no second warning
  CHECK(events.size() == 1);
  c = monitor.check(with_acceleration(4001), events);
  CHECK(c.errors == monitor::acceleration);
  REQUIRE(events.size() == 2);
  CHECK(events[1].severity == Severity::error);
  CHECK(events[1].parameter == "P-AXIS-00442");
  CHECK(events[1].axis == "X");
  monitor.check(at_rest(), events);
  monitor.check(with_acceleration(4500), events);  // a new excursion past both: warning and error again
  REQUIRE(events.size() == 4);
  CHECK(events[2].parameter == "P-AXIS-00441");
  CHECK(events[3].parameter == "P-AXIS-00442");
}

TEST_CASE("RIG-3 velocity monitor: P-AXIS-00439 warning and P-AXIS-00440 error at v_max * value / 1000",
          "[drive]") {
  AxisConfig axis = test::xyz_machine().axes[0];  // v_max 250, defaults 1050 / 1090
  REQUIRE(axis.velocity_warning_limit() == Approx(262.5));
  REQUIRE(axis.velocity_error_limit() == Approx(272.5));
  DriveMonitor monitor(axis);
  std::vector<Event> events;
  DriveSample s = at_rest();
  s.setpoint_velocity = s.velocity = 262;
  CHECK(monitor.check(s, events).warnings == 0);
  s.velocity = -263;
  CHECK(monitor.check(s, events).warnings == monitor::velocity);
  s.velocity = 273;
  const MonitorState c = monitor.check(s, events);
  CHECK(c.errors == monitor::velocity);
  REQUIRE(events.size() == 2);
  CHECK(events[0].parameter == "P-AXIS-00439");
  CHECK(events[1].parameter == "P-AXIS-00440");
  CHECK(events[1].severity == Severity::error);
  CHECK(events[1].limit == Approx(272.5));
}

TEST_CASE("RIG-3 following error monitor: P-AXIS-00168 slep_max moving, P-AXIS-00169 slep_min at standstill",
          "[drive]") {
  AxisConfig axis = test::xyz_machine().axes[0];
  REQUIRE(axis.following_error_monitoring == 4);  // set by slep_max in the machine file
  axis.slep_max = 0.5;
  axis.slep_min = 0.05;
  DriveMonitor monitor(axis);
  std::vector<Event> events;
  DriveSample s = at_rest();
  s.setpoint_velocity = 100;
  s.following_error = 0.4;
  CHECK(monitor.check(s, events).errors == 0);  // moving: 0.4 <= slep_max
  s.setpoint_velocity = 0;
  s.following_error = -0.06;
  CHECK(monitor.check(s, events).errors == monitor::following_error);  // at standstill: > slep_min
  REQUIRE(events.size() == 1);
  CHECK(events[0].parameter == "P-AXIS-00169");
  CHECK(events[0].limit == 0.05);
  s.following_error = 0;
  monitor.check(s, events);
  s.setpoint_velocity = 100;
  s.following_error = 0.51;
  monitor.check(s, events);
  REQUIRE(events.size() == 2);
  CHECK(events[1].parameter == "P-AXIS-00168");
  CHECK(events[1].value == 0.51);
  axis.following_error_monitoring = 0;  // off
  DriveMonitor off(axis);
  CHECK(off.check(s, events).errors == 0);
}

TEST_CASE("RIG-3 software limit switches: setpoint on P-AXIS-00177/00178, actual widened by P-AXIS-00179",
          "[drive]") {
  AxisConfig axis = test::xyz_machine().axes[0];
  axis.software_limits = true;
  axis.swe_neg = -10;
  axis.swe_pos = 300;
  axis.swe_toleranz = 0.1;
  DriveMonitor monitor(axis);
  std::vector<Event> events;
  DriveSample s = at_rest();
  s.setpoint_position = 300;
  s.position = 300.1;  // within the tolerance
  CHECK(monitor.check(s, events).errors == 0);
  s.position = 300.11;
  CHECK(monitor.check(s, events).errors == monitor::software_limit);
  REQUIRE(events.size() == 1);
  CHECK(events[0].parameter == "P-AXIS-00178");
  CHECK(events[0].limit == Approx(300.1));
  monitor.check(at_rest(), events);  // back inside: the excursion ends
  s.setpoint_position = s.position = -10.001;  // the setpoint is checked without tolerance
  monitor.check(s, events);
  REQUIRE(events.size() == 2);
  CHECK(events[1].parameter == "P-AXIS-00177");
  CHECK(events[1].limit == -10);
  CHECK_THAT(events[1].message, Catch::Contains("setpoint"));
}

TEST_CASE("RIG-3 drive model: built from the machine file's axis", "[drive]") {
  AxisConfig axis = test::xyz_machine().axes[2];  // Z: kv 35, velocity_lag_s 0.0025
  axis.velocity_loop_order = 2;
  axis.velocity_damping = 0.8;
  axis.velocity_feedforward = 0.9;
  axis.drive_acceleration_limit = 5000;
  axis.friction_coulomb = 20;
  axis.friction_viscous = 1;
  const DriveParameters p = drive_parameters(axis, 0.001);
  CHECK(p.kv == 35);
  CHECK(p.velocity_lag_s == 0.0025);
  CHECK(p.velocity_loop_order == 2);
  CHECK(p.velocity_damping == 0.8);
  CHECK(p.feedforward == 0.9);
  CHECK(p.acceleration_limit == 5000);
  CHECK(p.coulomb_friction == 20);
  CHECK(p.viscous_friction == 1);
  CHECK(std::isinf(drive_parameters(test::xyz_machine().axes[0], 0.001).acceleration_limit));  // none configured
}

TEST_CASE("RIG-3 a setpoint that is not finite is an error; the drive holds its last valid setpoint", "[drive]") {
  const AxisConfig axis = test::xyz_machine().axes[0];
  DriveModel drive(drive_parameters(axis, 0.001));
  DriveMonitor monitor(axis);
  std::vector<Event> events;
  DriveOutput out;
  for (int k = 0; k < 200; ++k) out = drive.step(0.5, 0);
  CHECK(monitor.check({0.5, 0, out.position, out.velocity, out.acceleration, out.following_error}, events).errors == 0);
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    for (int k = 0; k < 500; ++k) out = drive.step(bad, 0);
    CHECK(std::isfinite(out.position));
    CHECK(out.position == Approx(0.5).margin(1e-3));  // held, settled on the last valid setpoint
    const MonitorState m = monitor.check({bad, 0, out.position, out.velocity, out.acceleration, 0}, events);
    CHECK(m.errors == monitor::not_finite);
  }
  REQUIRE(events.size() == 1);  // one excursion: both bad setpoints in a row
  CHECK(events[0].severity == Severity::error);
  CHECK_THAT(events[0].message, Catch::Contains("not a finite number"));
  out = drive.step(0.5, 0);
  CHECK(monitor.check({0.5, 0, out.position, out.velocity, out.acceleration, out.following_error}, events).errors == 0);
}
