// KRN-3, KRN-4: feed hold and override change the motion online, jerk-limited,
// without leaving the path; checked by the offline checker (RIG-4).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "channel_runner.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;
using hil::test::run_program;

namespace {

// A line, a tangent quarter circle (centre 50, 20), a line.
const char* contour = "N10 G01 X50 F3000\nN20 G03 X70 Y20 I0 J20\nN30 G01 Y60\nM30\n";

bool on_contour(double x, double y) {
  const double e = 1e-9;
  if (std::abs(y) <= e && x >= -e && x <= 50 + e) return true;
  if (std::abs(x - 70) <= e && y >= 20 - e && y <= 60 + e) return true;
  return x >= 50 - e && y <= 20 + e && std::abs(std::hypot(x - 50, y - 20) - 20) <= e;
}

void require_within_limits(logger::LimitChecker& checker) {
  for (const auto& v : checker.finish().violations)
    FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value << " > " << v.limit << " at " << v.time_s);
}

}  // namespace

TEST_CASE("KRN-3 KRN-4 feed hold stops on the path, jerk-limited, and the program resumes on release",
          "[feed_control]") {
  const MachineConfig m = test::xyz_machine();
  for (int64_t hold_at : {200, 700, 1000, 1400}) {  // on the line, near and on the arc
    INFO("feed hold at cycle " << hold_at);
    Channel channel(m, contour);
    logger::LimitChecker checker(m);
    int64_t stopped_at = -1;
    double held_x = 0, held_y = 0;
    run_program(channel, &checker, [&](int64_t k, const HliState& s, HliControl& c) {
      const double x = channel.setpoints()[0].position, y = channel.setpoints()[1].position;
      CHECK(on_contour(x, y));
      if (k == hold_at) c.feedhold = {true, true};
      if (k == hold_at + 1000) c.feedhold = {false, true};
      if (k > hold_at && k <= hold_at + 1000) {
        CHECK(s.feedhold.state_r);
        CHECK((s.stop_conditions_r & stop_condition::feedhold) != 0);
        if (stopped_at < 0 && s.path_velocity == 0) {
          stopped_at = k;
          held_x = x;
          held_y = y;
        }
        if (stopped_at >= 0) {  // stays where it stopped
          CHECK(x == held_x);
          CHECK(y == held_y);
        }
      }
    });
    CHECK(stopped_at > hold_at);
    CHECK(stopped_at < hold_at + 200);  // from 50 mm/s: 0.1 s, longer on the arc (lower path limits)
    CHECK(channel.hli().channel_state == ChannelState::program_end);
    CHECK(channel.setpoints()[0].position == 70);
    CHECK(channel.setpoints()[1].position == 60);
    require_within_limits(checker);
  }
}

TEST_CASE("KRN-3 KRN-4 override scales the path velocity; 0 stops; above 100 % only if configured",
          "[feed_control]") {
  MachineConfig m = test::xyz_machine();
  auto velocity_at = [&](const MachineConfig& machine, int32_t override, int64_t at_cycle, HliState* state) {
    Channel channel(machine, "G01 X300 F6000\nM30\n");  // 100 mm/s programmed
    logger::LimitChecker checker(machine);
    double v = -1;
    run_program(channel, &checker, [&](int64_t k, const HliState& s, HliControl& c) {
      c.override = {override, true};
      if (k == at_cycle) {
        v = s.path_velocity;
        if (state) *state = s;
      }
    }, 0, at_cycle + 2);
    require_within_limits(checker);
    return v;
  };
  CHECK(velocity_at(m, 1000, 1500, nullptr) == Approx(100).margin(1e-9));
  CHECK(velocity_at(m, 500, 1500, nullptr) == Approx(50).margin(1e-9));
  HliState s;
  CHECK(velocity_at(m, 0, 1500, &s) == 0);
  CHECK((s.stop_conditions_r & stop_condition::override_zero) != 0);
  CHECK(s.override.state_r == 0);
  // 150 % asked for, 100 % allowed: clamped, with a warning.
  CHECK(velocity_at(m, 1500, 1500, &s) == Approx(100).margin(1e-9));
  CHECK(s.override.state_r == 1000);
  m.override_max_percent = 150;
  CHECK(velocity_at(m, 1500, 1500, &s) == Approx(150).margin(1e-9));
  CHECK(s.override.state_r == 1500);

  Channel channel(test::xyz_machine(), "G01 X300 F6000\nM30\n");
  run_program(channel, nullptr, [](int64_t, const HliState&, HliControl& c) { c.override = {1500, true}; }, 0, 10);
  const std::vector<Event> events = channel.take_events();
  REQUIRE(events.size() == 1);
  CHECK(events[0].severity == Severity::warning);
  CHECK_THAT(events[0].message, Catch::Contains("override_max_percent"));
}

TEST_CASE("KRN-3 override and feed hold changed at random moments keep every axis' limits and the path",
          "[feed_control]") {
  MachineConfig m = test::xyz_machine();
  m.override_max_percent = 120;
  std::mt19937_64 rng(2026);
  std::uniform_int_distribution<int> gap(1, 300), value(0, 1200), coin(0, 3);
  for (int run = 0; run < 20; ++run) {
    Channel channel(m, contour);
    logger::LimitChecker checker(m);
    int64_t next_change = gap(rng);
    run_program(channel, &checker, [&](int64_t k, const HliState&, HliControl& c) {
      CHECK(on_contour(channel.setpoints()[0].position, channel.setpoints()[1].position));
      if (k < next_change) return;
      next_change = k + gap(rng);
      if (k > 6000) {  // let it finish
        c.override = {1000, true};
        c.feedhold = {};
      } else if (coin(rng) == 0) {
        c.feedhold = {!c.feedhold.command_w, true};
      } else {
        c.override = {value(rng), true};
      }
    });
    CHECK(channel.hli().channel_state == ChannelState::program_end);
    require_within_limits(checker);
  }
}

TEST_CASE("RIG-3 a drive error stops the channel on the path, jerk-limited, with the channel error on the HLI",
          "[feed_control]") {
  const MachineConfig m = test::xyz_machine();
  for (int64_t error_at : {300, 1000}) {  // on the line at full feed, on the arc
    INFO("drive error at cycle " << error_at);
    Channel channel(m, contour);
    logger::LimitChecker checker(m);
    int64_t k_error = -1;
    double v_at_error = 0;
    const int64_t end = run_program(channel, &checker, [&](int64_t k, const HliState& s, HliControl& c) {
      CHECK(on_contour(channel.setpoints()[0].position, channel.setpoints()[1].position));
      if (k == error_at) {
        v_at_error = s.path_velocity;
        channel.drive_error("X", "acceleration P-AXIS-00442");
        k_error = k;
      }
      if (k_error >= 0 && k > k_error) {
        CHECK(s.channel_state == ChannelState::error);
        CHECK((s.stop_conditions_r & stop_condition::channel_error) != 0);
        c.feedhold = {false, true};  // neither releasing feed hold nor a new start restarts it
        c.program_start = {k == k_error + 5, true};
      }
    });
    REQUIRE(v_at_error > 10);
    REQUIRE(channel.finished());
    CHECK(channel.hli().channel_state == ChannelState::error);
    CHECK(channel.hli().path_velocity == 0);
    CHECK(channel.hli().block_nr_r < 30);  // aborted before the last block
    // Stopped as fast as the path limits allow: from 50 mm/s without an
    // acceleration plateau, 2 sqrt(v / j) with the path jerk at j_max / 2
    // (the jerk share of the corner rule), plus the cycles to notice it.
    CHECK(end - k_error <= std::ceil(2 * std::sqrt(v_at_error / (0.5 * m.axes[0].j_max)) / m.cycle_time_s()) + 3);
    const auto events = channel.take_events();
    bool reported = false;
    for (const Event& e : events)
      reported = reported || (e.severity == Severity::error && e.axis == "X" &&
                              e.message.find("P-AXIS-00442") != std::string::npos);
    CHECK(reported);
    require_within_limits(checker);
  }
}

TEST_CASE("KRN-3 an override change in the cycle the path reaches a transition it crosses moving keeps the limits",
          "[feed_control]") {
  // The plan of a stretch ends at a limiting transition with v > 0 (a line
  // into a tangent arc, a feed change) between two cycles; replanned in the
  // next cycle (override changed), the path was taken from where the plan
  // ended, not from where it would be at that cycle: it stood still for the
  // rest of the cycle (1.66e6 mm/s^3 on X).
  const MachineConfig m = test::xyz_machine();
  for (const char* program : {"N50 G01 X-0.152 F808\nN60 G03 Y-13.41 I0 J-6.705\nM30\n",
                              "N10 G01 X5 F3000\nN20 X20 F6000\nM30\n"}) {
    INFO(program);
    int64_t reached = -1;  // the cycle in which the path is in the second block
    {
      Channel channel(m, program);
      run_program(channel, nullptr, [&](int64_t k, const HliState& s, HliControl&) {
        if (reached < 0 && s.block_count_r == 2) reached = k;
      });
    }
    REQUIRE(reached > 0);
    for (int64_t at = reached - 2; at <= reached + 1; ++at) {
      INFO("override 90 % applied in cycle " << at);
      Channel channel(m, program);
      logger::LimitChecker checker(m);
      run_program(channel, &checker, [&](int64_t k, const HliState&, HliControl& c) {
        if (k + 1 == at) c.override = {900, true};
      });
      CHECK(channel.hli().channel_state == ChannelState::program_end);
      require_within_limits(checker);
    }
  }
}
