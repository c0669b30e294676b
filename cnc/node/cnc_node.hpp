#pragma once
// The CNC on the bus (RIG-1, RIG-6): the clock master. It wires the bus to
// the cycle loop (cnc/cycle): each cycle's setpoints and HLI state go out,
// and in lock-step it waits for every axis and the PLC to answer that cycle
// before the next. Which answers it takes is lock_step.hpp; what reaches it
// at all (this run's messages only) is lcm_support/inbox.hpp.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "bus.hpp"
#include "real_time_process.hpp"
#include "scenario.hpp"

namespace hil::cnc_node {

struct CncTiming {
  std::chrono::milliseconds answer{5000};  // the lock-step watchdog per cycle
  std::chrono::milliseconds logger{2000};  // the logger's heartbeat may fall silent this long
  // Lock-step at a pace to watch (issue 37, `hil run --pace F`): cycle k ends
  // no earlier than (k + 1) cycle times / F after cycle 0 began; 0: as fast as
  // the answers come. The run and its log are the same at any pace.
  double pace = 0;
};

// Waits (20 s at most) for every participant's READY, publishes the
// manifest, runs the cycles and announces the CNC's RUN_END. Returns the
// node's exit status: 0, or 3 if a participant was lost or missing. In
// real-time mode (scenario.realtime) the cycles tick on CLOCK_MONOTONIC at
// the machine's cycle time and never wait for answers (real_time_answers.hpp,
// tick_clock.hpp); `process` says how the process was scheduled.
int run_cnc(const Scenario& scenario, const std::string& scenario_text, lcm_support::Bus& bus, int64_t run_id,
            std::vector<std::string> participants, CncTiming timing,
            const lcm_support::RealTimeProcess& process = {});

}  // namespace hil::cnc_node
