// RIG-4: the offline checker names each violation with time, axis, value
// and limit, and reports per-axis maxima.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::logger;

TEST_CASE("RIG-4 limit check: a motion within the limits passes and reports its maxima", "[check]") {
  const MachineConfig m = test::xyz_machine();
  LimitChecker checker(m);
  // x = 1 - cos(w t): v = w sin, a = w^2 cos, j = w^3 sin, with w = 10 rad/s.
  const double w = 10, dt = m.cycle_time_s();
  for (int64_t k = 0; k < 2000; ++k) checker.add_setpoint(0, k, 1 - std::cos(w * k * dt));
  const CheckReport r = checker.finish();
  CHECK(r.passed());
  CHECK(r.axes[0].cmd_v == Approx(w).epsilon(1e-3));
  CHECK(r.axes[0].cmd_a == Approx(w * w).epsilon(1e-3));
  CHECK(r.axes[0].cmd_j == Approx(w * w * w).epsilon(1e-2));
  CHECK(r.axes[0].setpoints == 2000);
}

TEST_CASE("RIG-4 limit check: violations name time, axis, quantity, value and limit", "[check]") {
  const MachineConfig m = test::xyz_machine();  // Y: v_max 250, a_max 2000
  LimitChecker checker(m);
  // A velocity step of Y at cycle 10: 300 mm/s from there on.
  for (int64_t k = 0; k < 20; ++k) checker.add_setpoint(1, k, k < 10 ? 0.0 : 0.3 * (k - 9));
  checker.add_actual(2, 7, 0, 0, 3500, 0.6);  // Z: 00442 limit 3000, FE limit 0.5
  const CheckReport r = checker.finish();
  REQUIRE_FALSE(r.passed());
  bool velocity = false, acceleration = false, jerk = false, actual = false, fe = false;
  for (const Violation& v : r.violations) {
    if (v.quantity == "commanded velocity") {
      velocity = true;
      CHECK(v.axis == "Y");
      CHECK(v.value == Approx(300));
      CHECK(v.limit == 250);
      CHECK(v.time_s >= 0.010 - 1e-12);
    }
    if (v.quantity == "commanded acceleration") {
      acceleration = true;
      CHECK(v.time_s == Approx(0.010));
      CHECK(v.value == Approx(300000));
    }
    jerk = jerk || v.quantity == "commanded jerk";
    if (v.quantity == "actual acceleration (P-AXIS-00442 limit)") {
      actual = true;
      CHECK(v.axis == "Z");
      CHECK(v.limit == 3000);
      CHECK(v.time_s == Approx(0.007));
    }
    fe = fe || (v.quantity == "following error" && v.limit == 0.5);
  }
  CHECK(velocity);
  CHECK(acceleration);
  CHECK(jerk);
  CHECK(actual);
  CHECK(fe);
}

TEST_CASE("RIG-4 limit check: a gap in the cycles restarts the differences", "[check]") {
  LimitChecker checker(test::xyz_machine());
  checker.add_setpoint(0, 0, 0.0);
  checker.add_setpoint(0, 1, 0.0);
  checker.add_setpoint(0, 100, 5.0);  // 5 mm later, but 99 cycles apart: no jump
  checker.add_setpoint(0, 101, 5.0);
  CHECK(checker.finish().passed());
}

TEST_CASE("RIG-4 limit check: consecutive violating cycles are one episode with its worst value", "[check]") {
  const MachineConfig m = test::xyz_machine();  // X: P-AXIS-00442 limit 4000
  LimitChecker checker(m);
  const double overload[] = {0, 4100, 4300, -4200, 0, 0, 4050, 0};  // two episodes
  for (int64_t k = 0; k < 8; ++k) checker.add_actual(0, k, 0, 0, overload[k], 0);
  const CheckReport r = checker.finish();
  REQUIRE(r.violations.size() == 2);
  CHECK(r.violations[0].cycles == 3);
  CHECK(r.violations[0].time_s == Approx(0.001));
  CHECK(r.violations[0].end_time_s == Approx(0.003));
  CHECK(r.violations[0].value == 4300);
  CHECK(r.violations[0].worst_time_s == Approx(0.002));
  CHECK(r.violations[1].cycles == 1);
  CHECK(r.violations[1].value == 4050);
}

TEST_CASE("RIG-4 limit check: actual velocity (P-AXIS-00440) and software limit switches (P-AXIS-00177/00178)",
          "[check]") {
  MachineConfig m = test::xyz_machine();  // X: v_max 250, P-AXIS-00440 1090 -> 272.5
  m.axes[0].software_limits = true;
  m.axes[0].swe_neg = -1;
  m.axes[0].swe_pos = 10;
  m.axes[0].swe_toleranz = 0.1;
  LimitChecker checker(m);
  for (int64_t k = 0; k < 30; ++k) checker.add_setpoint(0, k, 0.5 * k);  // beyond 10 from cycle 21 on
  checker.add_actual(0, 3, 0, 273, 0, 0);
  checker.add_actual(0, 4, 10.05, 0, 0, 0);  // within swe_pos + swe_toleranz
  checker.add_actual(0, 5, -1.2, 0, 0, 0);
  const CheckReport r = checker.finish();
  std::map<std::string, Violation> found;
  for (const Violation& v : r.violations) found[v.quantity] = v;
  REQUIRE(found.count("actual velocity (P-AXIS-00440 limit)"));
  CHECK(found["actual velocity (P-AXIS-00440 limit)"].limit == Approx(272.5));
  REQUIRE(found.count("commanded position (P-AXIS-00178 swe_pos)"));
  CHECK(found["commanded position (P-AXIS-00178 swe_pos)"].time_s == Approx(0.021));
  CHECK(found["commanded position (P-AXIS-00178 swe_pos)"].cycles == 9);
  REQUIRE(found.count("actual position (P-AXIS-00177 swe_neg - P-AXIS-00179)"));
  CHECK(found["actual position (P-AXIS-00177 swe_neg - P-AXIS-00179)"].limit == Approx(-1.1));
  CHECK_FALSE(found.count("actual position (P-AXIS-00178 swe_pos + P-AXIS-00179)"));
}

TEST_CASE("RIG-4 limit check: a position, velocity or acceleration that is not finite is a violation", "[check]") {
  const MachineConfig m = test::xyz_machine();
  LimitChecker checker(m);
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  for (int64_t k = 0; k < 20; ++k) checker.add_setpoint(0, k, k == 10 ? nan : 0.0);
  for (int64_t k = 0; k < 20; ++k) checker.add_setpoint(1, k, k >= 15 ? inf : 0.0);
  checker.add_actual(2, 3, 0, nan, 0, 0);
  checker.add_actual(2, 4, inf, 0, 0, 0);
  const CheckReport r = checker.finish();
  REQUIRE_FALSE(r.passed());
  std::map<std::string, int> seen;
  for (const Violation& v : r.violations) seen[v.axis + " " + v.quantity] += v.cycles;
  CHECK(seen["X commanded position (not finite)"] == 1);
  CHECK(seen["Y commanded position (not finite)"] == 5);
  CHECK(seen["Z actual velocity (P-AXIS-00440 limit)"] == 1);
  CHECK(seen["Z actual position (not finite)"] == 1);
  // The finite samples around the NaN stay clean: no velocity or jerk spike from it.
  CHECK(seen.count("X commanded velocity") == 0);
  CHECK(r.axes[0].cmd_v == 0);
}

namespace {

// Z (a_max 1500, P-AXIS-00442 2000: 3000 mm/s^2) rest to rest in 200 cycles
// with a = a0 sin(w t) from cycle 50 on (|j| up to a0 w = 0.0209 a0 / ms);
// lift_active (LIFT-7) in `lift_from` .. `lift_to`. v_max 250 for the test;
// the machine lifts by `method`, with `j_max`; the path velocity on the HLI
// is constant or, with `feed_changes`, changes every cycle.
struct LiftMotion {
  double a0 = 0;
  int64_t lift_from = -1, lift_to = -1;
  bool by_hli_state = false;
  LiftMethod method = LiftMethod::time_based;
  double j_max = 100000;
  bool feed_changes = false;
};

CheckReport lift_motion(const LiftMotion& c) {
  MachineConfig m = test::xyz_machine();
  m.lift_method = c.method;
  m.axes[2].v_max = 250;
  m.axes[2].j_max = c.j_max;
  LimitChecker checker(m);
  const double dt = m.cycle_time_s(), w = 2 * M_PI / (200 * dt);
  for (int64_t k = 0; k < 400; ++k) {
    const double t = std::clamp<double>(static_cast<double>(k - 50), 0, 200) * dt;
    checker.add_setpoint(2, k, c.a0 / w * (t - std::sin(w * t) / w));
    const double path_velocity = c.feed_changes ? 100 + 0.1 * k : 100;
    const bool lifting = k >= c.lift_from && k <= c.lift_to;
    if (!c.by_hli_state) {
      checker.add_path_velocity(k, path_velocity);
      if (lifting) checker.add_lift_active(2, k);
      continue;
    }
    HliState s;  // the HLI names the axes: order does not matter
    s.cycle = k;
    s.path_velocity = path_velocity;
    s.axis_name = {"Z", "X", "Y"};
    s.lift_active = {lifting, false, false};
    checker.add_hli_state(s);
  }
  return checker.finish();
}

std::map<std::string, Violation> by_quantity(const CheckReport& r) {
  std::map<std::string, Violation> found;
  for (const Violation& v : r.violations) found[v.axis + " " + v.quantity] = v;
  return found;
}

}  // namespace

TEST_CASE("LIFT-2 RIG-4 limit check: an Advanced Lifting axis may use the overload range up to P-AXIS-00442",
          "[check][lift]") {
  // 1.5 a_max while the HLI shows lift_active: within a_max * 2000 / 1000;
  // |j| 70,700 within j_max 80,000.
  const CheckReport r = lift_motion({1.5 * 1500, 50, 250, true, LiftMethod::time_based, 80000});
  CHECK(r.passed());
  CHECK(r.axes[2].cmd_a_lift == Approx(2250).epsilon(1e-3));
  CHECK(r.axes[2].cmd_j_lift == Approx(2250 * 2 * M_PI / 0.2).epsilon(1e-2));
  CHECK(r.axes[2].a_err_limit == Approx(3000));
  CHECK(r.axes[2].cmd_a == 0);  // no commanded acceleration outside the lift
  CHECK(r.axes[2].lift_cycles == 201);
  CHECK(r.axes[0].lift_cycles == 0);
  CHECK(r.axes[0].cmd_a_lift == 0);
}

TEST_CASE("LIFT-2 LIFT-3 RIG-4 limit check: a lift-active axis keeps j_max; the overload factor is the "
          "acceleration's only",
          "[check][lift]") {
  // |j| 70,700 against j_max 60,000: the rule before (j_max * P-AXIS-00442 /
  // 1000 = 120,000 while lifting) passed it.
  for (const LiftMethod method : {LiftMethod::time_based, LiftMethod::path_based}) {
    const CheckReport r = lift_motion({1.5 * 1500, 50, 250, true, method, 60000, true});
    auto found = by_quantity(r);
    REQUIRE(found.count("Z commanded jerk (lift, j_max)"));
    CHECK(found["Z commanded jerk (lift, j_max)"].limit == 60000);
    CHECK(std::abs(found["Z commanded jerk (lift, j_max)"].value) == Approx(2250 * 2 * M_PI / 0.2).epsilon(1e-2));
    CHECK_FALSE(found.count("Z commanded acceleration (lift overload range, P-AXIS-00442)"));
    CHECK(r.axes[2].cmd_j_lift > 60000);
  }
}

TEST_CASE("LIFT-3 RIG-4 limit check: Lifting goes beyond a_max only while the path velocity changes",
          "[check][lift]") {
  // The text: at constant path velocity the lift axis moves "at its maximum
  // acceleration"; a feed rate change may take it into the overload range.
  const CheckReport steady = lift_motion({1.5 * 1500, 50, 250, false, LiftMethod::path_based});
  auto found = by_quantity(steady);
  REQUIRE(found.count("Z commanded acceleration (Lifting at constant path velocity, a_max)"));
  CHECK(found["Z commanded acceleration (Lifting at constant path velocity, a_max)"].limit == 1500);
  CHECK(lift_motion({1.5 * 1500, 50, 250, false, LiftMethod::path_based, 100000, true}).passed());
  // Advanced Lifting plans the overload range at any path velocity.
  CHECK(lift_motion({1.5 * 1500, 50, 250, false, LiftMethod::time_based}).passed());
}

TEST_CASE("LIFT-2 RIG-4 limit check: beyond P-AXIS-00442 a lift-active axis is a violation of the overload range",
          "[check][lift]") {
  const CheckReport r = lift_motion({2.1 * 1500, 50, 250});
  REQUIRE_FALSE(r.passed());
  auto found = by_quantity(r);
  REQUIRE(found.count("Z commanded acceleration (lift overload range, P-AXIS-00442)"));
  const Violation& v = found["Z commanded acceleration (lift overload range, P-AXIS-00442)"];
  CHECK(v.limit == Approx(3000));
  CHECK(std::abs(v.value) == Approx(3150).epsilon(1e-3));
  CHECK(r.violations.size() == 2);  // the two episodes near a's peaks, nothing else
  CHECK_FALSE(found.count("Z commanded acceleration"));
  CHECK_FALSE(found.count("Z commanded velocity"));
}

TEST_CASE("LIFT-2 RIG-4 limit check: without lift_active the plain a_max and j_max hold", "[check][lift]") {
  auto found = by_quantity(lift_motion({1.5 * 1500, -1, -1}));
  REQUIRE(found.count("Z commanded acceleration"));
  CHECK(found["Z commanded acceleration"].limit == 1500);
  CHECK_FALSE(found.count("Z commanded acceleration (lift overload range, P-AXIS-00442)"));
  // lift_active on another stretch of the run excuses nothing here.
  found = by_quantity(lift_motion({1.5 * 1500, 300, 399}));
  CHECK(found.count("Z commanded acceleration"));
}

TEST_CASE("LIFT-2 RIG-4 limit check: the lift's overload range leaves v_max as it is", "[check][lift]") {
  MachineConfig m = test::xyz_machine();
  LimitChecker checker(m);
  for (int64_t k = 0; k < 100; ++k) {
    checker.add_setpoint(2, k, 0.2 * k);  // 200 mm/s, Z v_max 150
    checker.add_lift_active(2, k);
  }
  auto found = by_quantity(checker.finish());
  REQUIRE(found.count("Z commanded velocity"));
  CHECK(found["Z commanded velocity"].limit == 150);
}
