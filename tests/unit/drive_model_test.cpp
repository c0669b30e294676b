// RIG-3: the drive model against its analytic step response, and the
// acceleration monitoring per P-AXIS-00441 / P-AXIS-00442.
#include <catch2/catch.hpp>

#include <cmath>

#include "acceleration_monitor.hpp"
#include "drive_model.hpp"
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

TEST_CASE("RIG-3 acceleration monitor: P-AXIS-00441 warning and P-AXIS-00442 error at a_max * value / 1000",
          "[drive]") {
  AxisConfig axis = test::xyz_machine().axes[0];  // a_max 2000, 1500 / 2000
  REQUIRE(axis.accel_warning_limit() == 3000);
  REQUIRE(axis.accel_error_limit() == 4000);
  AccelerationMonitor monitor(axis);
  std::vector<Event> events;
  CHECK_FALSE(monitor.check(2999, events).warning);
  CHECK(events.empty());
  AccelerationCheck c = monitor.check(-3001, events);
  CHECK(c.warning);
  CHECK_FALSE(c.error);
  REQUIRE(events.size() == 1);
  CHECK(events[0].severity == Severity::warning);
  CHECK(events[0].parameter == "P-AXIS-00441");
  CHECK(events[0].value == -3001);
  CHECK(events[0].limit == 3000);
  monitor.check(3500, events);  // still above: no second warning
  CHECK(events.size() == 1);
  c = monitor.check(4001, events);
  CHECK(c.error);
  REQUIRE(events.size() == 2);
  CHECK(events[1].severity == Severity::error);
  CHECK(events[1].parameter == "P-AXIS-00442");
  CHECK(events[1].axis == "X");
  monitor.check(0, events);
  monitor.check(4500, events);  // a new excursion past both: warning and error again
  REQUIRE(events.size() == 4);
  CHECK(events[2].parameter == "P-AXIS-00441");
  CHECK(events[3].parameter == "P-AXIS-00442");
}
