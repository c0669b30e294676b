// LIFT-7: the channel's HLI has lift_active / lift_suppressed for every
// axis (gpAx[axis_idx]^.ipo_state), FALSE in a program without a lift.
#include <catch2/catch.hpp>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "test_machine.hpp"

using namespace hil;

TEST_CASE("LIFT-7 channel: lift_active / lift_suppressed per axis, FALSE without a lift", "[channel][lift]") {
  const MachineConfig m = test::xyzc_machine();
  cnc::Channel channel(m, "N10 G01 X10 Z5 F3000\nN20 M30\n");
  REQUIRE(channel.hli().lift_active.size() == m.axes.size());
  REQUIRE(channel.hli().lift_suppressed.size() == m.axes.size());
  bool any = false;
  test::run_program(channel, nullptr, [&](int64_t, const HliState& s, HliControl&) {
    for (size_t i = 0; i < m.axes.size(); ++i) any = any || s.lift_active.at(i) || s.lift_suppressed.at(i);
  });
  CHECK(channel.hli().channel_state == ChannelState::program_end);
  CHECK_FALSE(any);
}
