// Insert stop marks (TF5200_insert_stop_cmd.txt): ISC-1 .. ISC-9 through the
// channel, cycle by cycle, as the PLC drives them; every run also passes
// the offline limit check.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>

#include "channel.hpp"
#include "decoder.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

constexpr double hli = hli_units_per_mm;

// The PLC side: one channel, its control, cycle by cycle.
struct Rig {
  explicit Rig(const std::string& program, MachineConfig machine = test::xyz_machine())
      : machine_config(machine), channel(machine, program), checker(machine_config) {
    control.program_start.enable_w = true;
    control.insert_cmd.enable_w = true;
    control.continue_motion.enable_w = true;
    control.m_function_ack.enable_w = true;
  }
  MachineConfig machine_config;
  Channel channel;
  logger::LimitChecker checker;
  HliControl control;
  int64_t k = 0;

  const HliState& hli() const { return channel.hli(); }
  double x() const { return channel.setpoints()[0].position; }
  double y() const { return channel.setpoints()[1].position; }
  double dist() const { return hli().dist_prog_start / hli_units_per_mm; }
  void step() {
    channel.step(k, control);
    for (size_t i = 0; i < channel.setpoints().size(); ++i)
      checker.add_setpoint(static_cast<int>(i), k, channel.setpoints()[i].position);
    ++k;
    // The PLC: semaphor_rw follows the CNC once it has answered (ISC-1); pulses end.
    control.insert_cmd.semaphor_rw = hli().insert_cmd.semaphor_rw;
    control.continue_motion.command_w = false;
    control.m_function_ack.command_w = false;
    control.program_start.command_w = false;
  }
  void start() {
    control.program_start.command_w = true;
    step();
  }
  // The PLC writes command_w and raises the semaphore in one step.
  void insert(double dist_or_pos, int mode, int m = 0, int axis = 0, int32_t add = 0) {
    control.insert_cmd.command_w = {dist_or_pos, static_cast<uint16_t>(mode), static_cast<uint16_t>(axis),
                                    static_cast<uint16_t>(m), add};
    control.insert_cmd.semaphor_rw = true;
  }
  // Runs until `until` holds (false if it never does within max cycles).
  bool run_until(const std::function<bool()>& until, int64_t max = 200000) {
    for (int64_t i = 0; i < max; ++i) {
      step();
      if (until()) return true;
    }
    return false;
  }
  bool at_stop() const { return (hli().stop_conditions_r & stop_condition::insert_stop_at_dist) != 0; }
  bool run_to_stop() {
    return run_until([&] { return at_stop() || channel.finished(); });
  }
  void continue_motion() {
    control.continue_motion.command_w = true;
    step();
  }
  bool run_to_end() {
    return run_until([&] { return channel.finished(); });
  }
  bool within_limits() {
    const auto violations = checker.finish().violations;
    for (const auto& v : violations)
      UNSCOPED_INFO(v.axis << " " << v.quantity << " " << v.value << " > " << v.limit << " at " << v.worst_time_s
                           << " s, " << v.cycles << " cycles");
    return violations.empty();
  }
};

const char* line_x100 = "N10 G01 X100 F6000\nN20 M30\n";

}  // namespace

TEST_CASE("ISC-1 the semaphore: read and cleared while enabled, not read without it or while disabled",
          "[insert_stop]") {
  Rig rig(line_x100);
  rig.step();
  rig.control.insert_cmd.enable_w = false;
  rig.insert(200000, 2);
  rig.step();
  CHECK(rig.hli().insert_cmd.semaphor_rw);  // disabled: not read, the semaphore stays
  CHECK(rig.hli().insert_cmd.state_r.state == 0);
  rig.control.insert_cmd.enable_w = true;
  rig.step();
  CHECK_FALSE(rig.hli().insert_cmd.semaphor_rw);  // read and cleared
  CHECK(rig.hli().insert_cmd.state_r.state == 1);
  CHECK(rig.hli().insert_cmd.state_r.distance_of_next_stop == -1);  // ISC-2: the program is not started yet
  // New data without the semaphore is not taken.
  rig.control.insert_cmd.command_w.dist_or_pos = 700000;
  rig.step();
  rig.start();
  REQUIRE(rig.run_to_stop());
  CHECK(rig.x() == Approx(20).margin(1e-9));
  CHECK(rig.within_limits());
}

TEST_CASE("ISC-3 ISC-5 ISC-7 relative iterative: a stop every 20 mm, M00, continue motion, the last at the end",
          "[insert_stop]") {
  Rig rig(line_x100);
  rig.insert(200000, 0);  // before program start (ISC-6)
  rig.step();
  rig.start();
  for (double expected : {20.0, 40.0, 60.0, 80.0, 100.0}) {
    INFO("stop at " << expected);
    REQUIRE(rig.run_to_stop());
    REQUIRE_FALSE(rig.channel.finished());
    for (int i = 0; i < 5; ++i) rig.step();  // it stays
    CHECK(rig.x() == Approx(expected).margin(1e-9));
    CHECK(rig.dist() == Approx(expected).margin(1e-6));
    CHECK(rig.hli().path_velocity == 0);
    CHECK(rig.hli().stop_conditions_r == (stop_condition::m00_or_m01 | stop_condition::m0_stop |
                                          stop_condition::insert_stop_at_dist));
    CHECK(rig.hli().insert_cmd.state_r.state == 0);  // reached
    CHECK(rig.hli().insert_cmd.state_r.distance_of_next_stop == Approx(expected * hli));
    CHECK(rig.hli().insert_cmd.state_r.position_at_next_stop[0] == std::lround(expected * hli));
    rig.continue_motion();
    if (expected < 100) {
      CHECK(rig.hli().insert_cmd.state_r.state == 1);  // re-inserted after the continuation
      CHECK(rig.hli().insert_cmd.state_r.distance_of_next_stop == Approx((expected + 20) * hli));
    }
  }
  REQUIRE(rig.run_to_end());
  CHECK(rig.hli().channel_state == ChannelState::program_end);
  CHECK(rig.x() == Approx(100));
  CHECK(rig.within_limits());
}

TEST_CASE("ISC-3 DISTANCE table: clear, immediate stops, absolute, relative once", "[insert_stop]") {
  SECTION("relative iterative 0 clears a stop not yet reached") {
    Rig rig(line_x100);
    rig.start();
    rig.insert(500000, 0);
    rig.run_until([&] { return rig.hli().insert_cmd.state_r.state == 1 && rig.hli().path_velocity > 50; });
    rig.insert(0, 0);
    rig.step();
    REQUIRE(rig.run_until([&] { return rig.hli().insert_cmd.state_r.state == 0; }, 2000));
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());  // no stop: the program ran to its end
    CHECK(rig.within_limits());
  }
  SECTION("relative iterative < 0: an immediate one-off stop where the path stands") {
    Rig rig(line_x100);
    rig.start();
    rig.run_until([&] { return rig.x() > 30; });
    rig.insert(-10000, 0);
    REQUIRE(rig.run_to_stop());
    const double x = rig.x();
    CHECK(x > 30);
    CHECK(x < 40);  // stopped briefly, braking from 100 mm/s
    CHECK(rig.dist() == Approx(x).margin(1e-6));
    rig.continue_motion();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());  // one-off
    CHECK(rig.within_limits());
  }
  SECTION("absolute at or below the current distance: immediate; above: at the distance") {
    Rig rig(line_x100);
    rig.start();
    rig.run_until([&] { return rig.x() > 50; });
    rig.insert(300000, 1);  // 30 mm, passed
    REQUIRE(rig.run_to_stop());
    CHECK(rig.x() > 50);
    CHECK(rig.x() < 60);
    rig.continue_motion();
    rig.insert(800000, 1);
    REQUIRE(rig.run_to_stop());
    CHECK(rig.x() == Approx(80).margin(1e-9));
    CHECK(rig.dist() == Approx(80).margin(1e-6));
    rig.continue_motion();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());
    CHECK(rig.within_limits());
  }
  SECTION("relative once: <= 0 immediate, > 0 once from the current distance") {
    Rig rig(line_x100);
    rig.start();
    rig.run_until([&] { return rig.x() > 10; });
    rig.insert(0, 2);
    REQUIRE(rig.run_to_stop());
    const double x0 = rig.x();
    CHECK(x0 < 20);
    rig.insert(250000, 2);  // at the stop: set at once, from here
    rig.step();
    rig.continue_motion();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.x() == Approx(x0 + 25).margin(1e-9));
    rig.continue_motion();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());
    CHECK(rig.within_limits());
  }
}

TEST_CASE("ISC-6 during motion: a brief stop, then on to the new stop; a new stop replaces the old; beyond the end",
          "[insert_stop]") {
  Rig rig("N10 G01 X60 F6000\nN20 X60 Y40\nN30 X0 Y40\nN40 M30\n");
  rig.start();
  rig.run_until([&] { return rig.x() > 20 && rig.hli().path_velocity > 99; });
  rig.insert(900000, 1);  // 90 mm: on N20 at Y30
  bool stood = false;
  REQUIRE(rig.run_until([&] {
    stood = stood || rig.hli().path_velocity == 0;
    return stood;
  }, 1000));
  CHECK(rig.x() < 40);  // the brief stop (ISC-6)
  CHECK(rig.hli().insert_cmd.state_r.state == 1);
  rig.step();
  CHECK(rig.hli().insert_cmd.state_r.distance_of_next_stop == Approx(900000));
  CHECK(rig.hli().insert_cmd.state_r.position_at_next_stop[0] == 600000);
  CHECK(rig.hli().insert_cmd.state_r.position_at_next_stop[1] == 300000);
  rig.insert(1100000, 1);  // replaces it: 110 mm, on N30 at X50
  REQUIRE(rig.run_to_stop());
  CHECK(rig.x() == Approx(50).margin(1e-9));
  CHECK(rig.y() == Approx(40).margin(1e-9));
  CHECK(rig.dist() == Approx(110).margin(1e-6));
  rig.continue_motion();
  rig.insert(5000000, 2);  // 500 mm further: beyond the end, lands at the end
  REQUIRE(rig.run_to_stop());
  REQUIRE_FALSE(rig.channel.finished());
  CHECK(rig.x() == Approx(0).margin(1e-9));
  CHECK(rig.y() == Approx(40).margin(1e-9));
  CHECK(rig.hli().insert_cmd.state_r.distance_of_next_stop == Approx(1600000).margin(1));
  rig.continue_motion();
  REQUIRE(rig.run_to_end());
  CHECK(rig.hli().channel_state == ChannelState::program_end);
  CHECK(rig.within_limits());
}

TEST_CASE("ISC-3 the stop lands on the mark inside an arc, jerk-limited", "[insert_stop]") {
  Rig rig("N10 G01 X20 F3000\nN20 G03 X40 Y20 I0 J20\nN30 G01 Y60\nN40 M30\n");
  const double quarter = M_PI * 20 / 2;
  rig.insert((20 + quarter / 2) * hli, 1);
  rig.step();
  rig.start();
  REQUIRE(rig.run_to_stop());
  CHECK(rig.dist() == Approx(20 + quarter / 2).margin(1e-6));
  CHECK(rig.x() == Approx(20 + 20 * std::sin(M_PI / 4)).margin(1e-6));
  CHECK(rig.y() == Approx(20 - 20 * std::cos(M_PI / 4)).margin(1e-6));
  rig.continue_motion();
  REQUIRE(rig.run_to_end());
  CHECK(rig.within_limits());
}

TEST_CASE("ISC-5 M01 stops only while m01_stop_enable; M<n> with add_nr waits for the PLC", "[insert_stop]") {
  SECTION("M01 not enabled: no stop") {
    Rig rig(line_x100);
    rig.insert(300000, 2, 1);
    rig.step();
    rig.start();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());
  }
  SECTION("M01 enabled") {
    Rig rig(line_x100);
    rig.control.m01_stop_enable = {true, true};
    rig.insert(300000, 2, 1);
    rig.step();
    rig.start();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.x() == Approx(30).margin(1e-9));
    CHECK(rig.hli().stop_conditions_r == (stop_condition::m00_or_m01 | stop_condition::m1_stop |
                                          stop_condition::insert_stop_at_dist));
    rig.continue_motion();
    REQUIRE(rig.run_to_end());
  }
  SECTION("M<n>") {
    Rig rig(line_x100);
    rig.insert(300000, 2, 77, 0, -5);
    rig.step();
    rig.start();
    REQUIRE(rig.run_to_stop());
    for (int i = 0; i < 3; ++i) rig.step();
    CHECK(rig.x() == Approx(30).margin(1e-9));
    CHECK(rig.hli().m_function_request_r);
    CHECK(rig.hli().m_function_nr_r == 77);
    CHECK(rig.hli().m_function_add_nr_r == -5);
    CHECK(rig.hli().stop_conditions_r == (stop_condition::plc_acknowledge | stop_condition::wait_techno_ack |
                                          stop_condition::insert_stop_at_dist));
    rig.continue_motion();  // not what M<n> waits for
    CHECK(rig.at_stop());
    rig.control.m_function_ack.command_w = true;
    rig.step();
    rig.step();
    CHECK_FALSE(rig.at_stop());
    REQUIRE(rig.run_to_end());
    CHECK(rig.within_limits());
  }
}

TEST_CASE("ISC-5 M00 / M01 in the program: the stop state until continue motion", "[insert_stop]") {
  Rig rig("N10 G01 X10 F6000\nN20 M00\nN30 X20\nN40 M01\nN50 X30\nM30\n");
  rig.start();
  REQUIRE(rig.run_until([&] { return rig.hli().stop_conditions_r & stop_condition::m0_stop; }));
  CHECK(rig.x() == Approx(10));
  CHECK(rig.hli().stop_conditions_r == (stop_condition::m00_or_m01 | stop_condition::m0_stop));
  for (int i = 0; i < 10; ++i) rig.step();
  CHECK(rig.x() == Approx(10));
  rig.continue_motion();
  REQUIRE(rig.run_to_end());  // M01 without m01_stop_enable: on
  CHECK(rig.x() == Approx(30));
}

TEST_CASE("ISC-4 POSITION mode: the first time the axis reaches the position, not again", "[insert_stop]") {
  Rig rig("N10 G01 X50 F6000\nN20 X10\nN30 X50 Y10\nN40 M30\n");
  rig.insert(300000, 1, 0, 1);  // X = 30 absolute
  rig.step();
  rig.start();
  REQUIRE(rig.run_to_stop());
  CHECK(rig.x() == Approx(30).margin(1e-9));
  CHECK(rig.dist() == Approx(30).margin(1e-6));
  CHECK(rig.hli().insert_cmd.state_r.position_at_next_stop[0] == 300000);
  CHECK(rig.hli().insert_cmd.state_r.position_at_next_stop[1] == 0);
  rig.continue_motion();
  REQUIRE(rig.run_to_stop());
  CHECK(rig.channel.finished());  // passed X30 twice more: no stop
  SECTION("relative iterative") {
    Rig it("N10 G01 X50 F6000\nN20 X10\nM30\n");
    it.insert(200000, 0, 0, 1);  // every +20 mm of X from X0: X20, X40, then none (X60 never)
    it.step();
    it.start();
    REQUIRE(it.run_to_stop());
    CHECK(it.x() == Approx(20).margin(1e-9));
    it.continue_motion();
    REQUIRE(it.run_to_stop());
    CHECK(it.x() == Approx(40).margin(1e-9));
    it.continue_motion();
    REQUIRE(it.run_to_stop());  // X60 is never reached: at the end
    CHECK(it.x() == Approx(10).margin(1e-9));
    it.continue_motion();
    REQUIRE(it.run_to_end());
    CHECK(it.within_limits());
  }
}

TEST_CASE("ISC-8 #INSERT CMD in the program", "[insert_stop]") {
  SECTION("a stop 30 mm on, set at its line") {
    Rig rig("N10 G01 X10 F6000\nN20 #INSERT CMD ON [DIST=300000 REL_ONCE MNR=0]\nN30 X100\nM30\n");
    rig.start();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.x() == Approx(40).margin(1e-9));
    rig.continue_motion();
    REQUIRE(rig.run_to_end());
  }
  SECTION("two of ABS / REL / REL_ONCE: error 22130 with the line") {
    const DecodedProgram p =
        decode_program("N10 G01 X10 F6000\nN20 #INSERT CMD [DIST=5 ABS REL]\nM30\n", test::xyz_machine(), {0, 0, 0});
    REQUIRE(p.error);
    CHECK(p.error->id == 22130);
    CHECK(p.error->nc_line == 2);
    CHECK(p.error->block_nr == 20);
  }
  SECTION("defaults, OFF, DIST=0 REL clears") {
    const DecodedProgram p = decode_program(
        "#INSERT CMD [AXNR=2 MNR=5 ADDR=-3 DIST=100 ABS]\n#INSERT CMD OFF\n#INSERT CMD\n#INSERT CMD ON\n",
        test::xyz_machine(), {0, 0, 0});
    REQUIRE_FALSE(p.error);
    REQUIRE(p.blocks.size() == 4);
    const InsertCommand& c = *p.blocks[0].insert_cmd->command;
    CHECK(c.axis_nr == 2);
    CHECK(c.m_function_nr == 5);
    CHECK(c.add_nr == -3);
    CHECK(c.dist_or_pos == 100);
    CHECK(c.rel_abs_mode == 1);
    CHECK(p.blocks[1].insert_cmd->off);
    CHECK(p.blocks[2].insert_cmd->command->dist_or_pos == 0);  // #INSERT CMD [MNR=0 DIST=0 REL AXNR=0]
    CHECK(p.blocks[2].insert_cmd->command->rel_abs_mode == 0);
    CHECK_FALSE(p.blocks[3].insert_cmd->command);
  }
  SECTION("OFF clears the stop and stops at its program position") {
    Rig rig("N10 #INSERT CMD [DIST=500000 ABS]\nN20 G01 X30 F6000\nN30 #INSERT CMD OFF\nN40 X100\nM30\n");
    rig.start();
    bool stood_at_30 = false;
    REQUIRE(rig.run_until([&] {
      stood_at_30 = stood_at_30 || (rig.hli().path_velocity == 0 && std::abs(rig.x() - 30) < 1e-9);
      return rig.at_stop() || rig.channel.finished();
    }));
    CHECK(stood_at_30);
    CHECK(rig.channel.finished());
  }
}

TEST_CASE("ISC-9 backward: an iterative DISTANCE stop is kept and works backward; a one-off one is cleared",
          "[insert_stop]") {
  MachineConfig machine = test::xyz_machine();
  machine.fb_storage_size = 100000;
  SECTION("iterative") {
    Rig rig(line_x100, machine);
    rig.start();
    rig.insert(300000, 0);
    REQUIRE(rig.run_to_stop());
    const double first = rig.x();
    rig.continue_motion();
    rig.run_until([&] { return rig.x() > first + 10; });
    rig.control.backward_motion = {true, true};
    REQUIRE(rig.run_until([&] { return rig.hli().backward_motion.state_r; }));
    const double turned = rig.dist();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.hli().backward_motion.state_r);
    CHECK(rig.dist() == Approx(turned - 30).margin(1e-6));
    CHECK(rig.within_limits());
  }
  SECTION("one-off") {
    Rig rig(line_x100, machine);
    rig.start();
    rig.insert(800000, 1);
    rig.run_until([&] { return rig.x() > 30; });
    rig.control.backward_motion = {true, true};
    REQUIRE(rig.run_until([&] { return rig.hli().backward_motion.state_r; }));
    CHECK(rig.hli().insert_cmd.state_r.state == 0);
    rig.control.backward_motion = {false, false};
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());
    CHECK(rig.within_limits());
  }
}

TEST_CASE("ISC-4 POSITION table: relative once, absolute at the current position, relative iterative 0 clears",
          "[insert_stop]") {
  SECTION("relative once = 0: a stop at the current axis position, at once") {
    Rig rig(line_x100);
    rig.start();
    rig.run_until([&] { return rig.x() > 20; });
    rig.insert(0, 2, 0, 1);
    REQUIRE(rig.run_to_stop());
    const double x = rig.x();
    CHECK(x < 30);  // the brief stop, then at once
    rig.continue_motion();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());  // one-off
  }
  SECTION("relative once <> 0: once, relative to the axis position") {
    Rig rig(line_x100);
    rig.insert(-150000, 2, 0, 1);  // X - 15 mm: X never goes there, it lands at the end
    rig.step();
    rig.start();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.x() == Approx(100).margin(1e-9));
    rig.continue_motion();
    REQUIRE(rig.run_to_end());
    Rig once(line_x100);
    once.insert(250000, 2, 0, 1);
    once.step();
    once.start();
    REQUIRE(once.run_to_stop());
    CHECK(once.x() == Approx(25).margin(1e-9));
    once.continue_motion();
    REQUIRE(once.run_to_stop());
    CHECK(once.channel.finished());
  }
  SECTION("absolute = the current axis position: a stop there, at once") {
    Rig rig("N10 G01 Y30 F6000\nN20 X50\nM30\n");
    rig.insert(0, 1, 0, 1);  // X0, where X stands at the start
    rig.step();
    rig.start();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.y() == Approx(0).margin(1e-9));
    CHECK(rig.hli().insert_cmd.state_r.distance_of_next_stop == 0);
    rig.continue_motion();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());
  }
  SECTION("relative iterative = 0 clears a stop not yet reached") {
    Rig rig(line_x100);
    rig.insert(800000, 1, 0, 1);
    rig.step();
    rig.start();
    rig.run_until([&] { return rig.x() > 30; });
    rig.insert(0, 0, 0, 1);
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.finished());
    CHECK(rig.within_limits());
  }
}

TEST_CASE("ISC-4 KRN-7 modulo axis: absolute shifted into the range (at most a revolution), relative over several",
          "[insert_stop][modulo]") {
  // Fig. 6: G90 C300 turns -60 deg; an absolute stop at 90 deg is the first
  // 90 after that, 150 deg up on N20 (210 deg of C travel).
  {
    Rig rig("N10 G01 G90 C300 F10800\nN20 G91 C720\nN30 M30\n", test::xyzc_machine());
    rig.insert(900000, 1, 0, 4);
    rig.start();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.at_stop());
    CHECK(rig.channel.setpoints()[3].position == Approx(90).margin(1e-6));
    CHECK(rig.dist() == Approx(210).margin(1e-6));
    CHECK(rig.hli().insert_cmd.state_r.position_at_next_stop[0] == 900000);
    rig.continue_motion();
    REQUIRE(rig.run_to_end());
    CHECK(rig.hli().axis_position_r[3] == 3000000);  // -60 + 720 = 660: shown 300
    CHECK(rig.within_limits());
  }
  // Fig. 5: relative 450 deg from 0: one and a quarter revolutions.
  {
    Rig rig("N10 G01 G91 C1080 F10800\nN20 M30\n", test::xyzc_machine());
    rig.insert(4500000, 2, 0, 4);
    rig.start();
    REQUIRE(rig.run_to_stop());
    CHECK(rig.channel.setpoints()[3].position == Approx(450).margin(1e-6));
    CHECK(rig.hli().axis_position_r[3] == 900000);
    CHECK(rig.hli().insert_cmd.state_r.position_at_next_stop[0] == 900000);
    CHECK(rig.within_limits());
  }
}
