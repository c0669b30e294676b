// The reset control unit: aborts the program where the path stands; the
// channel is READY for a new start (the way to a block search, DPS-3).
#include <catch2/catch.hpp>
#include <string>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

const char* const program = "N10 G01 X100 F6000\nN20 Y50\nN30 M30\n";

// Runs cycles with `control` from cycle k on until `done` holds (at most n).
template <typename Done>
int64_t run_until(Channel& channel, int64_t k, const HliControl& control, Done done, int64_t n = 100000) {
  for (const int64_t end = k + n; k < end; ++k) {
    channel.step(k, control);
    if (done(channel.hli())) return k + 1;
  }
  FAIL("condition not reached");
  return k;
}

}  // namespace

TEST_CASE("DPS-3 reset: ignored while the path moves; standing in feed hold it aborts the program, READY",
          "[DPS-3][channel]") {
  Channel channel(test::xyz_machine(), program);
  HliControl control = test::start_command(true);
  int64_t k = run_until(channel, 0, control, [](const HliState& s) { return s.dist_prog_start > 100000; });
  control.program_start.command_w = false;
  control.reset = {true, true};
  channel.step(k++, control);  // moving: a warning, nothing else
  CHECK(channel.hli().channel_state == ChannelState::active);
  CHECK_FALSE(channel.hli().reset.state_r);
  std::vector<Event> events = channel.take_events();
  REQUIRE_FALSE(events.empty());
  CHECK(events.back().message.find("reset ignored") != std::string::npos);
  control.reset = {false, true};
  control.feedhold = {true, true};
  k = run_until(channel, k, control, [](const HliState& s) { return s.path_velocity == 0; });
  const double stopped_x = channel.setpoints()[0].position;
  control.reset = {true, true};
  channel.step(k++, control);
  CHECK(channel.hli().reset.state_r);
  CHECK(channel.hli().channel_state == ChannelState::ready);
  CHECK(channel.hli().dist_prog_start == 0);
  CHECK(channel.setpoints()[0].position == stopped_x);  // aborted where it stood
  // A new start runs the program again from there; feed hold released.
  control.reset = {false, true};
  control.feedhold = {false, true};
  control.program_start = {true, true};
  k = run_until(channel, k, control, [](const HliState& s) { return s.channel_state == ChannelState::program_end; });
  CHECK(channel.setpoints()[0].position == Approx(100));
  CHECK(channel.setpoints()[1].position == Approx(50));
  CHECK(channel.hli().dist_prog_start == Approx((100 - stopped_x + 50) * hli_units_per_mm));
}

TEST_CASE("DPS-3 reset: after program end the channel can start again", "[DPS-3][channel]") {
  Channel channel(test::xyz_machine(), program);
  HliControl control = test::start_command(true);
  int64_t k = run_until(channel, 0, control, [](const HliState& s) { return s.channel_state == ChannelState::program_end; });
  control.program_start.command_w = false;
  control.reset = {true, true};
  channel.step(k++, control);
  CHECK(channel.hli().channel_state == ChannelState::ready);
  CHECK_FALSE(channel.finished());
}
