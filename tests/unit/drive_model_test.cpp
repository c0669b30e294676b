// RIG-3: the drive model against its analytic step response, and the
// drive monitoring: acceleration P-AXIS-00441/00442, velocity
// P-AXIS-00439/00440, following error P-AXIS-00168/00169 (P-AXIS-00172),
// software limit switches P-AXIS-00177/00178/00179.
#include <catch2/catch.hpp>

#include <cmath>

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

TEST_CASE("RIG-3 drive model: the discrete system is stable; bad parameters are refused", "[drive]") {
  for (double dt : {0.0001, 0.001, 0.01, 0.1}) {
    DriveModel drive({40, 0.002, dt});
    const auto eig = drive.transition().eigenvalues();
    for (int i = 0; i < 2; ++i) CHECK(std::abs(eig(i)) < 1);
  }
  CHECK_THROWS_AS(DriveModel({0, 0.002, 0.001}), std::invalid_argument);
  CHECK_THROWS_AS(DriveModel({40, -1, 0.001}), std::invalid_argument);
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
