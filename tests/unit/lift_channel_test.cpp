// The lift function through the channel, cycle by cycle
// (TF5200_lift_function.txt, LIFT-1 .. LIFT-8): the text's programs and
// special cases on both methods; every run also passes the offline limit
// check, with the lift axis' overload range where lift_active says so.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lift_rig.hpp"

using namespace hil;
using namespace hil::cnc;
using namespace hil::test;

namespace {

// The text's cross-block example: laser off, lift over 100 mm of XY
// positioning, land at 12.
const std::string cross_block =
    "N10 G01 X0 Y0 Z10 F6000\n"
    "N20 Z[LIFT_START POS=12 POS_LIMIT=30]\n"
    "N30 X40\n"
    "N40 X60 Y10\n"
    "N50 X100 Y0\n"
    "N60 Z[LIFT_END]\n"
    "N70 X110\n"
    "N80 M30\n";

double run_peak(const std::string& program, const MachineConfig& machine) {
  LiftRig rig(program, machine);
  rig.start();
  rig.run_to_end();
  REQUIRE(rig.hli().channel_state == ChannelState::program_end);
  rig.require_within_limits();
  return rig.z_peak;
}

}  // namespace

TEST_CASE("LIFT-2 Advanced Lifting: the lift axis rises towards POS_LIMIT and lands on POS at LIFT_END, in the "
          "overload range",
          "[lift][channel]") {
  const MachineConfig m = test::xyz_lift_machine();
  LiftRig rig(cross_block, m);
  rig.start();
  rig.run_until([&] { return rig.hli().block_nr_r == 70; });
  CHECK(rig.axis(Z) == Approx(12).margin(1e-9));  // landed when the path reached N70
  rig.run_to_end();
  REQUIRE(rig.hli().channel_state == ChannelState::program_end);
  CHECK(rig.z_peak == Approx(30).margin(1e-6));
  CHECK(rig.axis(Z) == Approx(12));
  CHECK(rig.axis(X) == Approx(110));
  const AxisConfig& z = m.axes[Z];
  CHECK(rig.largest_z_acceleration() > z.a_max);  // the overload range is used
  CHECK(rig.largest_z_acceleration() <= z.accel_error_limit() * (1 + 1e-6));
  rig.require_within_limits();
}

TEST_CASE("LIFT-2 LIFT-3: on the same program Advanced Lifting lifts higher than Lifting (Fig. 9)", "[lift][channel]") {
  // 40 mm of positioning at 100 mm/s: 0.4 s, too short for either to reach 100.
  const std::string program =
      "N10 G01 X0 Y0 Z10 F6000\n"
      "N20 Z[LIFT_START POS=12 POS_LIMIT=100]\n"
      "N30 X20\n"
      "N40 X40\n"
      "N50 Z[LIFT_END]\n"
      "N60 M30\n";
  const double advanced = run_peak(program, test::xyz_lift_machine());
  const double lifting = run_peak(program, test::xyz_lifting_machine());
  INFO("Advanced Lifting " << advanced << " mm, Lifting " << lifting << " mm");
  CHECK(advanced > lifting + 1);
  CHECK(lifting > 12);
}

TEST_CASE("LIFT-3 Lifting: the lift follows the path parameter; feed hold stops it with the path", "[lift][channel]") {
  LiftRig rig(cross_block, test::xyz_lifting_machine());
  rig.start();
  rig.run_until([&] { return rig.hli().block_nr_r == 40; });
  const double z_before = rig.axis(Z);
  CHECK(z_before > 10);
  rig.control.feedhold.command_w = true;
  rig.control.feedhold.enable_w = true;
  rig.run_until([&] { return rig.hli().path_velocity == 0; });
  const double z_held = rig.axis(Z);
  for (int i = 0; i < 500; ++i) rig.step();
  CHECK(rig.axis(Z) == z_held);  // stands with the path
  rig.control.feedhold.command_w = false;
  rig.run_to_end();
  REQUIRE(rig.hli().channel_state == ChannelState::program_end);
  CHECK(rig.axis(Z) == Approx(12));
  // The feed hold's braking adds to the lift's own acceleration: beyond
  // a_max perhaps, never beyond the P-AXIS-00442 limit.
  rig.require_within_limits();
}

TEST_CASE("LIFT-2 Advanced Lifting: under feed hold the lift axis goes on to its height", "[lift][channel]") {
  LiftRig rig(cross_block, test::xyz_lift_machine());
  rig.start();
  rig.run_until([&] { return rig.hli().block_nr_r == 30 && rig.axis(Z) > 11; });
  rig.control.feedhold.command_w = true;
  rig.run_until([&] { return rig.hli().path_velocity == 0; });
  const double x_held = rig.axis(X);
  for (int i = 0; i < 3000; ++i) rig.step();
  CHECK(rig.axis(X) == x_held);
  CHECK(rig.z_peak == Approx(30).margin(1e-6));  // it rose on while the path stood
  rig.control.feedhold.command_w = false;
  rig.run_to_end();
  REQUIRE(rig.hli().channel_state == ChannelState::program_end);
  CHECK(rig.axis(Z) == Approx(12));
  rig.require_within_limits();
}

TEST_CASE("LIFT-2 a range without path motion: the path waits while the lift axis positions", "[lift][channel]") {
  for (const MachineConfig& m : {test::xyz_lift_machine(), test::xyz_lifting_machine()}) {
    LiftRig rig("N10 G01 X10 Y0 Z10 F6000\nN20 Z[LIFT_START POS=40 POS_LIMIT=50]\nN30 Z[LIFT_END]\nN40 X20\nN50 M30\n",
                m);
    rig.start();
    bool waited = false;
    rig.run_until([&] {
      waited = waited || (rig.hli().stop_conditions_r & stop_condition::wait_for_axes);
      return rig.axis(X) > 10 + 1e-9;
    });
    CHECK(waited);
    CHECK(rig.axis(Z) == Approx(40));  // the path moved on only after the lift axis got there
    rig.run_to_end();
    CHECK(rig.hli().channel_state == ChannelState::program_end);
    CHECK(rig.z_peak == Approx(40));
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-5 POS beyond POS_LIMIT: the limit has no effect, the target is reached at the start", "[lift][channel]") {
  const std::string program =
      "N10 G01 X0 Y0 Z10 F3000\nN20 Z[LIFT_START POS=40 POS_LIMIT=30]\nN30 X10\nN40 X20\nN50 X35\nN60 Z[LIFT_END]\n"
      "N70 X45\nN80 M30\n";
  for (const MachineConfig& m : {test::xyz_lift_machine(), test::xyz_lifting_machine()}) {
    LiftRig rig(program, m);
    rig.start();
    rig.run_until([&] { return rig.hli().block_nr_r == 50; });
    CHECK(rig.axis(Z) == Approx(40).margin(1e-6));  // there before the range's last block
    rig.run_to_end();
    CHECK(rig.z_peak == Approx(40));
    CHECK(rig.axis(Z) == Approx(40));
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-5 a syntax error in the range: the path runs to the last good block, the lift axis parks at POS_LIMIT",
          "[lift][channel]") {
  const std::string program =
      "N10 G01 X0 Y0 Z10 F6000\nN20 Z[LIFT_START POS_LIMIT=30]\nN30 X10\nN40 X20\nN50 X35\nN100 G01 X=?\n"
      "N560 X50\nN600 Z[LIFT_END]\nN610 M30\n";
  for (const MachineConfig& m : {test::xyz_lift_machine(), test::xyz_lifting_machine()}) {
    LiftRig rig(program, m);
    rig.start();
    rig.run_to_end();
    CHECK(rig.hli().channel_state == ChannelState::error);
    CHECK(rig.axis(X) == Approx(35));
    CHECK(rig.axis(Z) == Approx(30));
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-5 #FLUSH acts as LIFT_END and LIFT_START: the text's equivalent programs give the same trace",
          "[lift][channel]") {
  const std::string flush =
      "N20 G01 X40 Z2 F3000\nN30 Z[LIFT_START POS=12 POS_LIMIT=40]\nN40 X50\nN50 X40\nN60 #FLUSH\nN70 X30\nN80 X20\n"
      "N90 Z[LIFT_END]\nN100 M30\n";
  const std::string equivalent =
      "N20 G01 X40 Z2 F3000\nN30 Z[LIFT_START POS=40 POS_LIMIT=40]\nN40 X50\nN50 X40\nN60 Z[LIFT_END]\n"
      "N60 Z[LIFT_START POS=12 POS_LIMIT=40]\nN70 X30\nN80 X20\nN90 Z[LIFT_END]\nN100 M30\n";
  for (const MachineConfig& m : {test::xyz_lift_machine(), test::xyz_lifting_machine()}) {
    LiftRig a(flush, m), b(equivalent, m);
    a.start();
    b.start();
    a.run_to_end();
    b.run_to_end();
    CHECK(a.hli().channel_state == ChannelState::program_end);
    REQUIRE(a.z.size() == b.z.size());
    CHECK(a.z == b.z);
    CHECK(a.x == b.x);
    CHECK(a.axis(Z) == Approx(12));
    a.require_within_limits();
  }
}

TEST_CASE("LIFT-5 program end without LIFT_END acts as LIFT_END", "[lift][channel]") {
  for (const MachineConfig& m : {test::xyz_lift_machine(), test::xyz_lifting_machine()}) {
    LiftRig rig("N10 G01 X0 Z10 F6000\nN20 Z[LIFT_START POS=12 POS_LIMIT=30]\nN30 X50\nN40 M30\n", m);
    rig.start();
    rig.run_to_end();
    CHECK(rig.hli().channel_state == ChannelState::program_end);
    CHECK(rig.axis(Z) == Approx(12));
    CHECK(rig.z_peak > 12);
    CHECK_FALSE(rig.hli().lift_active[Z]);
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-4 LIFT-7 P-CHAN-00244: a shorter path suppresses the lift, the axis goes straight to POS",
          "[lift][channel]") {
  const std::string program = "N10 G01 X0 Z10 F6000\nN20 Z[LIFT_START POS=14 POS_LIMIT=30]\nN30 X5\nN40 Z[LIFT_END]\nN50 M30\n";
  SECTION("Advanced Lifting: active and suppressed at once (POS is programmed)") {
    MachineConfig m = test::xyz_lift_machine();
    m.lift_min_dist_mm = 10;
    LiftRig rig(program, m);
    rig.start();
    bool both = false;
    rig.run_until([&] {
      both = both || (rig.hli().lift_active[Z] && rig.hli().lift_suppressed[Z]);
      return rig.hli().block_nr_r == 40;
    });
    rig.run_to_end();
    CHECK(both);
    CHECK(rig.z_peak == Approx(14));
    CHECK(rig.axis(Z) == Approx(14));
    rig.require_within_limits();
  }
  SECTION("Lifting: suppressed, within a_max") {
    MachineConfig m = test::xyz_lifting_machine();
    m.lift_min_dist_mm = 10;
    LiftRig rig(program, m);
    rig.start();
    bool suppressed = false;
    rig.run_until([&] {
      suppressed = suppressed || rig.hli().lift_suppressed[Z];
      return rig.done();
    });
    CHECK(suppressed);
    CHECK(rig.z_peak == Approx(14));
    CHECK(rig.largest_z_acceleration() <= m.axes[Z].a_max * (1 + 1e-6));
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-2 DOWN lowers instead; G91 makes POS and POS_LIMIT relative for this motion only", "[lift][channel]") {
  LiftRig rig("N10 G01 X0 Z10 F6000\nN20 Z[LIFT_START DOWN G91 POS=-2 POS_LIMIT=-8]\nN30 X60\nN40 Z[LIFT_END]\n"
              "N50 X70\nN60 M30\n",
              test::xyz_lift_machine());
  rig.start();
  rig.run_to_end();
  CHECK(rig.hli().channel_state == ChannelState::program_end);
  CHECK(rig.z_floor == Approx(2).margin(1e-6));
  CHECK(rig.axis(Z) == Approx(8));
  rig.require_within_limits();
}

TEST_CASE("LIFT-8 Advanced Lifting accepts no higher override while it lowers than at the start of lowering",
          "[lift][channel]") {
  MachineConfig m = test::xyz_lift_machine();
  m.override_max_percent = 150;
  LiftRig rig(cross_block, m);
  rig.start();
  rig.run_until([&] { return rig.z_peak > 29.9 && rig.axis(Z) < 29.5; });  // lowering
  REQUIRE(rig.hli().lift_active[Z]);
  rig.control.override.command_w = 1500;
  double fastest = 0;
  rig.run_until([&] {
    if (rig.axis(Z) > 12 + 1e-6) fastest = std::max(fastest, rig.hli().path_velocity);
    return rig.hli().block_nr_r == 70;
  });
  INFO("fastest while lowering " << fastest << " mm/s");
  CHECK(fastest <= 100 + 1e-6);  // F6000 at the 100 % in force when lowering began
  CHECK(rig.axis(Z) == Approx(12));
  rig.run_to_end();
  CHECK(rig.hli().channel_state == ChannelState::program_end);
  rig.require_within_limits();
}

TEST_CASE("LIFT-8 Advanced Lifting while rising: a higher override as far as the lift axis can still land in time",
          "[lift][channel]") {
  MachineConfig m = test::xyz_lift_machine();
  m.override_max_percent = 150;
  // Hovering at 30 over a long range with room to spare: the raise is taken.
  LiftRig rig(cross_block, m);
  rig.control.override.command_w = 500;
  rig.start();
  rig.run_until([&] { return rig.axis(Z) > 29.99; });
  rig.control.override.command_w = 1500;
  double fastest = 0;
  rig.run_until([&] {
    fastest = std::max(fastest, rig.hli().path_velocity);
    return rig.hli().block_nr_r == 70;
  });
  CHECK(fastest > 100);
  CHECK(rig.axis(Z) == Approx(12));  // and it still landed in time
  rig.run_to_end();
  rig.require_within_limits();
}

TEST_CASE("LIFT-6 DDTG-8 delete distance to go in a lift range: the lift axis lands first; skipping LIFT_END is "
          "error 51016",
          "[lift][channel]") {
  SECTION("a short cut to the next block: the lift lands on POS, the path goes on") {
    LiftRig rig(cross_block, test::xyz_lift_machine());
    rig.start();
    rig.run_until([&] { return rig.hli().block_nr_r == 30 && rig.axis(Z) > 20; });
    rig.control.delete_distance_to_go.command_w = true;
    rig.run_to_end();
    CHECK(rig.hli().channel_state == ChannelState::program_end);
    CHECK(rig.axis(Z) == Approx(12));
    rig.require_within_limits();
  }
  SECTION("an end marker beyond LIFT_END: 51016") {
    LiftRig rig("N10 G01 X0 Z10 F6000\nN20 Z[LIFT_START POS=12 POS_LIMIT=30]\nN30 X40\nN40 X80\nN50 Z[LIFT_END]\n"
                "N60 #DEL DIST2GO [END=1]\nN70 X90\nN80 M30\n",
                test::xyz_lift_machine());
    rig.control.delete_distance_to_go_activation.command_w = 1;
    rig.control.delete_distance_to_go_activation.enable_w = true;
    rig.start();
    rig.run_until([&] { return rig.hli().block_nr_r == 30 && rig.axis(Z) > 20; });
    rig.control.delete_distance_to_go.command_w = true;
    rig.run_to_end();
    CHECK(rig.hli().channel_state == ChannelState::error);
    CHECK(rig.hli().last_error_id == 51016);
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-2 the path feed is reduced where the lift axis could not make POS in time", "[lift][channel]") {
  // 30 mm up in 10 mm of path: at F6000 (100 mm/s) the path would take 0.1 s.
  const std::string program =
      "N10 G01 X0 Z10 F6000\nN20 Z[LIFT_START POS=40 POS_LIMIT=40]\nN30 X10\nN40 Z[LIFT_END]\nN50 X20\nN60 M30\n";
  for (const MachineConfig& m : {test::xyz_lift_machine(), test::xyz_lifting_machine()}) {
    LiftRig rig(program, m);
    rig.start();
    double fastest_in_range = 0;
    rig.run_until([&] {
      if (rig.hli().block_nr_r == 30) fastest_in_range = std::max(fastest_in_range, rig.hli().path_velocity);
      return rig.hli().block_nr_r == 50;
    });
    INFO(m.name << ": fastest in the range " << fastest_in_range << " mm/s");
    CHECK(fastest_in_range < 100 * 0.8);
    CHECK(rig.axis(Z) == Approx(40).margin(1e-9));  // there when the path left the range
    rig.run_to_end();
    CHECK(rig.hli().channel_state == ChannelState::program_end);
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-3 a feed hold while Lifting adds the path's braking to the lift axis: beyond a_max, within "
          "P-AXIS-00442",
          "[lift][channel]") {
  const MachineConfig m = test::xyz_lifting_machine();
  // 60 mm at 100 mm/s, 20 mm up: the lift axis moves fast in the middle.
  LiftRig rig("N10 G01 X0 Z10 F6000\nN20 Z[LIFT_START POS=10 POS_LIMIT=30]\nN30 X60\nN40 Z[LIFT_END]\nN50 M30\n", m);
  rig.start();
  rig.run_until([&] { return rig.axis(Z) > 14; });  // rising at speed
  rig.control.feedhold.command_w = true;
  rig.run_until([&] { return rig.hli().path_velocity == 0; });
  rig.control.feedhold.command_w = false;
  rig.run_to_end();
  const double a = rig.largest_z_acceleration();
  INFO("largest |a| of Z " << a << " mm/s^2, a_max " << m.axes[Z].a_max << ", P-AXIS-00442 limit "
                           << m.axes[Z].accel_error_limit());
  CHECK(a > m.axes[Z].a_max);
  CHECK(a <= m.axes[Z].accel_error_limit() * (1 + 1e-6));
  rig.require_within_limits();
}

TEST_CASE("LIFT-2 LIFT-3 an insert stop mark in a lift range: Lifting stands with the path, Advanced Lifting goes on",
          "[lift][channel]") {
  for (const MachineConfig& m : {test::xyz_lift_machine(), test::xyz_lifting_machine()}) {
    LiftRig rig(cross_block, m);
    rig.control.insert_cmd.enable_w = true;
    rig.control.continue_motion.enable_w = true;
    rig.start();
    rig.run_until([&] { return rig.hli().block_nr_r == 30; });
    // A stop mark 3 mm further on with M00 (ISC-1, ISC-5), relative once.
    rig.control.insert_cmd.command_w = {3 * hli_units_per_mm, 2, 0, 0, 0};
    rig.control.insert_cmd.semaphor_rw = true;
    rig.run_until([&] { return (rig.hli().stop_conditions_r & stop_condition::insert_stop_at_dist) != 0; });
    REQUIRE((rig.hli().stop_conditions_r & stop_condition::insert_stop_at_dist) != 0);
    const double z_at_stop = rig.axis(Z), x_at_stop = rig.axis(X);
    for (int i = 0; i < 1500; ++i) rig.step();
    CHECK(rig.axis(X) == Approx(x_at_stop).margin(1e-9));
    if (m.lift_method == LiftMethod::path_based) CHECK(rig.axis(Z) == z_at_stop);
    else CHECK(rig.axis(Z) > z_at_stop + 1);
    rig.control.continue_motion.command_w = true;
    rig.step();
    rig.run_to_end();
    CHECK(rig.hli().channel_state == ChannelState::program_end);
    CHECK(rig.axis(Z) == Approx(12));
    rig.require_within_limits();
  }
}

TEST_CASE("LIFT-2 RIG-3 a drive error while Advanced Lifting lifts: the channel ends only once the lift axis has "
          "braked to rest, jerk-limited",
          "[lift][channel]") {
  // scenarios/lift/overload_wrong_parameterisation.yaml's program: the error
  // comes while Z rises fast; the path stops in less time than Z needs.
  LiftRig rig("N10 G01 X0 Y0 Z10 F6000\nN20 Z[LIFT_START POS=12 POS_LIMIT=100]\nN30 X200\nN40 Z[LIFT_END]\nN50 M30\n",
              test::xyz_lift_machine());
  rig.start();
  rig.run_until([&] { return rig.axis(Z) > 30; });
  REQUIRE(rig.hli().lift_active[Z]);
  rig.channel.drive_error("Z", "acceleration P-AXIS-00442");
  int64_t cycles = 0;
  while (!rig.channel.finished() && cycles++ < 100000) rig.step();
  REQUIRE(rig.channel.finished());
  CHECK(rig.hli().channel_state == ChannelState::error);
  const size_t n = rig.z.size();
  REQUIRE(n > 3);
  CHECK(rig.z[n - 1] == Approx(rig.z[n - 2]).margin(1e-9));  // Z stands when the channel ends
  CHECK(rig.z[n - 2] == Approx(rig.z[n - 3]).margin(1e-9));
  rig.require_within_limits();
}

// Found by the channel fuzz (lift seed 278, PLC resetting, DPS-3): a feed
// hold stands the path, but the Advanced Lifting axis goes on rising in
// time; a reset then stopped it dead (jerk 15.8e6 mm/s^3). It is ignored
// (a warning) until the lift axis stands too.
TEST_CASE("DPS-3 LIFT-2 channel: a reset while the path stands but the lift axis still moves is ignored",
          "[DPS-3][channel][lift]") {
  LiftRig rig(cross_block, test::xyz_lift_machine());
  rig.control.reset.enable_w = true;
  rig.start();
  rig.run_until([&] { return rig.hli().lift_active[Z]; });
  rig.control.feedhold.command_w = true;
  rig.run_until([&] { return rig.hli().feedhold.state_r && rig.hli().path_velocity == 0; });
  REQUIRE(rig.channel.setpoints()[Z].velocity != 0);  // the lift axis still rises
  rig.channel.take_events();
  rig.control.reset.command_w = true;
  rig.step();
  CHECK(rig.hli().channel_state == ChannelState::active);
  CHECK_FALSE(rig.hli().reset.state_r);
  bool warned = false;
  for (const Event& e : rig.channel.take_events()) warned = warned || e.message.rfind("reset ignored", 0) == 0;
  CHECK(warned);
  rig.control.reset.command_w = false;
  rig.run_until([&] {
    return std::abs(rig.channel.setpoints()[Z].velocity) < 1e-9 && std::abs(rig.channel.setpoints()[Z].acceleration) < 1e-9;
  });
  REQUIRE(rig.k < 100000);
  rig.control.reset.command_w = true;  // the lift axis stands now: the reset acts
  rig.step();
  CHECK(rig.hli().reset.state_r);
  CHECK(rig.hli().channel_state == ChannelState::ready);
  for (int i = 0; i < 50; ++i) rig.step();
  rig.require_within_limits();
}

// TF5200_lift_function.txt, "Path smoothing and lifting": with G261 the
// other axes are contoured into and out of the range where the lift axis
// does not move in the block before LIFT_START or directly after LIFT_END
// (2nd case); where it moves there, that corner stops (1st case).
