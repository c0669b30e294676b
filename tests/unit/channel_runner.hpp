#pragma once
// Drives a Channel cycle by cycle as the rig does, for the unit tests.
#include <cstdint>
#include <functional>

#include "channel.hpp"
#include "limit_check.hpp"

namespace hil::test {

inline HliControl start_command(bool command, bool enable = true) {
  HliControl c;
  c.program_start = {command, enable};
  return c;
}

// The PLC's answer for a cycle; the default leaves every unit alone.
using PlcStep = std::function<void(int64_t cycle, const HliState& state, HliControl& control)>;

// Starts the program in cycle `first_cycle` and runs until the channel has
// finished (or max_cycles); feeds the setpoints to `checker` if given.
// Returns the cycle after the last one run.
inline int64_t run_program(cnc::Channel& channel, logger::LimitChecker* checker = nullptr,
                           const PlcStep& plc = nullptr, int64_t first_cycle = 0, int64_t max_cycles = 400000) {
  HliControl control = start_command(true);
  int64_t k = first_cycle;
  for (; k < first_cycle + max_cycles; ++k) {
    channel.step(k, control);
    if (checker) {
      checker->add_hli_state(channel.hli());  // lift_active: the lift's overload range (LIFT-2)
      for (size_t i = 0; i < channel.setpoints().size(); ++i)
        checker->add_setpoint(static_cast<int>(i), k, channel.setpoints()[i].position);
    }
    if (channel.finished()) return k + 1;
    control.program_start.command_w = false;
    if (plc) plc(k, channel.hli(), control);
  }
  return k;
}

}  // namespace hil::test
