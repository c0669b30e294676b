// KRN-4 (HLI program start, block_nr_r, block_count_r), DPS-1 (covered
// distance, so far for lines and arcs), KRN-2 (a decode error stops the
// channel after the last good block), KRN-3 (limits over a whole program).
#include <catch2/catch.hpp>

#include <cmath>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;
using hil::test::run_program;
using hil::test::start_command;

namespace {

const char* program =
    "N10 G00 X10 Y10 Z5\n"
    "N20 G01 Z-2 F600\n"
    "N30 X80 F3000\n"
    "N40 G03 X100 Y30 I0 J20\n"
    "N50 M30\n";

}  // namespace

TEST_CASE("KRN-4 channel: the program starts on a rising edge of command_w while enable_w", "[channel]") {
  Channel channel(test::xyz_machine(), program);
  channel.step(0, start_command(true, false));  // not enabled
  CHECK(channel.hli().channel_state == ChannelState::ready);
  CHECK(channel.hli().stop_conditions_r == stop_condition::ipo_input_empty);
  channel.step(1, start_command(true, true));  // still high, no new edge
  CHECK(channel.hli().channel_state == ChannelState::ready);
  channel.step(2, start_command(false, true));
  channel.step(3, start_command(true, true));  // rising edge while enabled
  CHECK(channel.hli().channel_state == ChannelState::active);
  CHECK(channel.hli().program_start.state_r);
  CHECK(channel.hli().program_start.request_r);
  CHECK(channel.hli().block_nr_r == 10);
  CHECK(channel.hli().block_count_r == 1);
  CHECK(channel.hli().stop_conditions_r == 0);
  channel.step(4, start_command(false, true));
  channel.step(5, start_command(true, true));  // an edge while running is refused
  const std::vector<Event> events = channel.take_events();
  REQUIRE(events.size() == 1);
  CHECK(events[0].severity == Severity::warning);
  CHECK_THAT(events[0].message, Catch::Contains("channel is ACTIVE"));
}

TEST_CASE("KRN-4 DPS-1 channel: block_nr_r, block_count_r and dist_prog_start follow the interpolator",
          "[channel]") {
  Channel channel(test::xyz_machine(), program);
  channel.step(0, start_command(true));
  std::vector<int64_t> blocks_seen{channel.hli().block_nr_r};
  double previous_dist = 0;
  int64_t k = 1;
  for (; !channel.finished(); ++k) {
    channel.step(k, HliControl{});
    const HliState& s = channel.hli();
    if (s.block_nr_r != blocks_seen.back()) blocks_seen.push_back(s.block_nr_r);
    CHECK(s.dist_prog_start >= previous_dist);  // only grows going forward
    previous_dist = s.dist_prog_start;
    // HLI positions are the commanded positions in 0.1 um.
    CHECK(s.axis_position_r[0] == std::llround(channel.setpoints()[0].position * 1e4));
  }
  CHECK(blocks_seen == std::vector<int64_t>{10, 20, 30, 40, 50});
  const HliState& end = channel.hli();
  CHECK(end.channel_state == ChannelState::program_end);
  CHECK(end.block_count_r == 5);
  // 15 + 7 + 70 + a quarter circle of radius 20: the exact path lengths.
  const double expected_mm = std::sqrt(10.0 * 10 + 10 * 10 + 5 * 5) + 7 + 70 + 20 * M_PI / 2;
  CHECK(end.dist_prog_start == Approx(expected_mm * 1e4).epsilon(1e-12));
  CHECK(channel.setpoints()[0].position == 100);
  CHECK(channel.setpoints()[1].position == 30);
  CHECK(channel.setpoints()[2].position == -2);
  CHECK(channel.setpoints()[0].velocity == 0);
}

TEST_CASE("KRN-3 channel: a whole program stays within every axis' limits", "[channel]") {
  const MachineConfig machine = test::xyz_machine();
  Channel channel(machine, std::string(program) + "G00 X0 Y0 Z0\n");
  logger::LimitChecker checker(machine);
  run_program(channel, &checker);
  const logger::CheckReport report = checker.finish();
  for (const auto& v : report.violations) FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value);
  // The limits are used, not only respected: the profile is time-optimal per block.
  CHECK(report.axes[0].cmd_a > 0.9 * machine.axes[0].a_max);
}

TEST_CASE("KRN-2 channel: after a decode error the channel runs the good blocks, then stops in error",
          "[channel]") {
  Channel channel(test::xyz_machine(), "N10 G01 X10 F6000\nN20 Y5\nN30 G41\nN40 X100\nM30\n");
  channel.step(0, start_command(true));
  const std::vector<Event> events = channel.take_events();
  REQUIRE(events.size() == 1);  // reported when decoding reaches it, at program start
  CHECK(events[0].nc_line == 3);
  CHECK(events[0].block_nr == 30);
  CHECK(channel.hli().channel_state == ChannelState::active);
  run_program(channel, nullptr, nullptr, 1);
  CHECK(channel.hli().channel_state == ChannelState::error);
  CHECK(channel.hli().block_nr_r == 20);
  CHECK((channel.hli().stop_conditions_r & stop_condition::channel_error) != 0);
  // Never beyond what was decoded correctly: the end of N20.
  CHECK(channel.setpoints()[0].position == 10);
  CHECK(channel.setpoints()[1].position == 5);
}

TEST_CASE("KRN-4 stop_conditions_r: PLC_ACKNOWLEDGE and WAIT_TECHNO_ACK while an M function waits, DELAY_TIME in a dwell",
          "[channel]") {
  Channel channel(test::xyz_machine(), "N10 G1 X10 F3000\nN20 M48\nN30 #TIME 0.2\nN40 X20\nM30\n");
  const int32_t waiting = stop_condition::plc_acknowledge | stop_condition::wait_techno_ack;
  int64_t acknowledged_at = -1, waiting_cycles = 0, dwell_cycles = 0, moving_cycles = 0;
  run_program(channel, nullptr, [&](int64_t k, const HliState& s, HliControl& c) {
    c.m_function_ack.enable_w = true;
    c.m_function_ack.command_w = s.m_function_request_r && k % 50 == 0;  // acknowledges late
    if (s.m_function_request_r) {
      CHECK((s.stop_conditions_r & waiting) == waiting);
      CHECK((s.stop_conditions_r & stop_condition::delay_time) == 0);
      ++waiting_cycles;
      if (c.m_function_ack.command_w) acknowledged_at = k;
    } else if ((s.stop_conditions_r & stop_condition::delay_time) != 0) {
      CHECK((s.stop_conditions_r & waiting) == 0);
      ++dwell_cycles;
    } else if (s.path_velocity > 0) {
      CHECK(s.stop_conditions_r == 0);
      ++moving_cycles;
    }
  });
  CHECK(acknowledged_at > 0);
  CHECK(waiting_cycles >= 2);
  CHECK(dwell_cycles == Approx(200).margin(2));
  CHECK(moving_cycles > 100);
  CHECK(channel.hli().channel_state == ChannelState::program_end);
}

TEST_CASE("DPS-2 #DISTANCE PROG START CLEAR after an M function and a dwell acts once they are done", "[channel]") {
  // In program order: while N20's M function waits for its acknowledgement
  // and N30 dwells, dist_prog_start still shows N10's 10 mm; N40 clears it
  // after them (fuzz seed 15009636: the CLEAR acted when the interpolator
  // reached it, before the dwell, and showed 0 through it).
  Channel channel(test::xyz_machine(),
                  "N10 G1 X10 F3000\nN20 M48\nN30 #TIME 0.2\nN40 #DISTANCE PROG START CLEAR\nN50 X20\nM30\n");
  int64_t waiting_cycles = 0, cleared_cycles = 0;
  run_program(channel, nullptr, [&](int64_t k, const HliState& s, HliControl& c) {
    c.m_function_ack.enable_w = true;
    c.m_function_ack.command_w = s.m_function_request_r && k % 50 == 0;
    const bool waits = s.m_function_request_r || (s.stop_conditions_r & stop_condition::delay_time) != 0;
    if (waits) {
      CHECK(s.dist_prog_start == Approx(10 * hli_units_per_mm));
      ++waiting_cycles;
    } else if (s.block_nr_r == 50 && s.path_velocity > 0) {
      CHECK(s.dist_prog_start < 10 * hli_units_per_mm);
      ++cleared_cycles;
    }
  });
  CHECK(waiting_cycles > 200);
  CHECK(cleared_cycles > 100);
  CHECK(channel.hli().dist_prog_start == Approx(10 * hli_units_per_mm));  // N50 alone
  CHECK(channel.hli().channel_state == ChannelState::program_end);
}
