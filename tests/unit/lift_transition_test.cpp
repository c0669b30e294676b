// The lift function's transitions through the channel (LIFT-2, LIFT-3,
// KRN-6): contouring curves into and out of a lift range, and the lift
// axis' jerk in every transition of both methods.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lift_rig.hpp"

using namespace hil;
using namespace hil::cnc;
using namespace hil::test;

TEST_CASE("LIFT-2 KRN-6 G261: the path passes the corners into and out of an Advanced Lifting range without "
          "stopping where the lift axis stands still beside it, and stops where it moves",
          "[lift][channel]") {
  auto slowest_near = [](const std::string& program, LiftMethod method, double corner_x) {
    MachineConfig m = test::xyz_lift_machine();
    m.lift_method = method;
    LiftRig rig(program, m);
    rig.start();
    double slowest = 1e9;
    while (!rig.done() && rig.k < 200000) {
      rig.step();
      if (std::abs(rig.axis(X) - corner_x) < 1) slowest = std::min(slowest, rig.hli().path_velocity);
    }
    REQUIRE(rig.hli().channel_state == ChannelState::program_end);
    rig.require_within_limits();
    return slowest;
  };
  auto program = [](const std::string& before, double pos, const std::string& after) {
    return "N05 G01 X0 Y0 Z10 F3000\n#CONTOUR MODE [DEV PATH_DEV=0.5]\nN10 G261 X20 Y10" + before + "\nN15 Z[LIFT_START POS=" + std::to_string(pos) +
           " POS_LIMIT=30]\nN20 X40 Y0\nN30 X60 Y10\nN40 X80 Y0\nN45 Z[LIFT_END]\nN50 X100 Y10" + after +
           "\nN60 M30\n";
  };
  const std::string still = program("", 10, " Z10");
  const std::string moving = program(" Z11", 11, " Z14");
  const std::string higher = program("", 12, "");
  SECTION("Advanced Lifting") {
    const LiftMethod method = LiftMethod::time_based;
    CHECK(slowest_near(still, method, 20) > 5);  // into the range: contoured
    CHECK(slowest_near(still, method, 80) > 5);  // out of it
    CHECK(slowest_near(moving, method, 20) < 0.01);  // the corner stops
    CHECK(slowest_near(moving, method, 80) < 0.01);
    // Landing higher than it started: the path's lift axis steps at the
    // range's end (the lift bridges it), so that corner stops.
    CHECK(slowest_near(higher, method, 20) > 5);
    CHECK(slowest_near(higher, method, 80) < 0.01);
  }
  SECTION("Lifting: coupled to the covered distance, the 1st case at both ends") {
    const LiftMethod method = LiftMethod::path_based;
    CHECK(slowest_near(still, method, 20) < 0.01);
    CHECK(slowest_near(still, method, 80) < 0.01);
  }
}


// Found by the channel fuzz (lift kind, seed 2672): G61 into a range of
// 0.015 mm. The curve's half in the range covers more programmed distance
// than its length; had its velocity counted length, the path would have
// left the range before the lift axis landed (an error at program end).
TEST_CASE("LIFT-2 KRN-6 a contouring curve into a short Advanced Lifting range: the lift axis lands before the path "
          "leaves it",
          "[lift][channel]") {
  LiftRig rig(
      "N10 G90 G01 X0 Y0 Z10 F9619\n"
      "N30 G01 X-11.714287135 Y3.157297805\n"
      "N40 G01 X-12.012035992 Y3.31777443 G61\n"
      "N50 Z[LIFT_START POS=15.593347017 POS_LIMIT=20]\n"
      "N60 G01 X-11.997920195 Y3.313315158\n"
      "N80 Z[LIFT_END]\n"
      "N110 M30\n",
      test::xyz_lift_machine());
  rig.start();
  rig.run_to_end();
  CHECK(rig.hli().channel_state == ChannelState::program_end);
  CHECK(rig.axis(Z) == Approx(15.593347017).margin(1e-9));
  rig.require_within_limits();
}

namespace {

// The largest |third difference| of the lift axis' setpoints over a run:
// a third difference never exceeds the true peak jerk, so one above j_max
// proves the limit broken (issue 32's measure).
double largest_z_jerk(const std::vector<double>& z, double dt) {
  double j = 0;
  for (size_t i = 3; i < z.size(); ++i)
    j = std::max(j, std::abs(z[i] - 3 * z[i - 1] + 3 * z[i - 2] - z[i - 3]) / (dt * dt * dt));
  return j;
}

}  // namespace

TEST_CASE("LIFT-2 LIFT-3 the lift axis' jerk stays within j_max in every cycle of every transition, both methods",
          "[lift][channel]") {
  // From rest at program start (the range first), after a block that moved
  // Z, with the path accelerating and decelerating inside the range (F
  // changes, corners), feed hold and override changes while lifting, and
  // the landing; on the machines of both methods and the stiff Advanced one.
  const std::string program =
      "N10 Z[LIFT_START POS=5 POS_LIMIT=40]\n"
      "N20 G01 X30 F3000\n"
      "N30 Z[LIFT_END]\n"
      "N40 G01 X35 Z12 F6000\n"
      "N50 Z[LIFT_START POS=10 POS_LIMIT=60]\n"
      "N60 G01 X60 Y10 F2000\n"
      "N70 G01 X100 Y0 F9000\n"
      "N80 G02 X120 Y20 I0 J20 F4000\n"
      "N90 G01 X160 Y20 F9000\n"
      "N100 Z[LIFT_END]\n"
      "N110 X170\n"
      "N120 M30\n";
  struct Case {
    const char* name;
    MachineConfig machine;
  };
  const Case cases[] = {{"Advanced Lifting", test::xyz_lift_machine()},
                        {"Lifting", test::xyz_lifting_machine()},
                        {"Advanced Lifting, stiff Z", test::xyz_lift_stiff_machine()}};
  for (const Case& c : cases) {
    for (int plc = 0; plc < 3; ++plc) {  // 0: no PLC action; 1: feed hold; 2: override changes
      INFO(c.name << ", PLC " << plc);
      LiftRig rig(program, c.machine);
      rig.start();
      while (!rig.done() && rig.k < 60000) {
        if (plc == 1) rig.control.feedhold.command_w = rig.k % 700 > 600;
        if (plc == 2) rig.control.override.command_w = rig.k % 500 < 250 ? 1000 : 300 + rig.k % 250;
        rig.step();
      }
      REQUIRE(rig.hli().channel_state == ChannelState::program_end);
      const double j_max = c.machine.axes[Z].j_max;
      CHECK(largest_z_jerk(rig.z, c.machine.cycle_time_s()) <= j_max * (1 + 1e-6));
      CHECK(rig.z_peak > 30);  // it did lift
      CHECK(rig.axis(Z) == Approx(10));
      rig.require_within_limits();
    }
  }
}
