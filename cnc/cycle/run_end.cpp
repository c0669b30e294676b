#include "run_end.hpp"

#include <cmath>
#include <string>

namespace hil::cnc {

RunEnd::RunEnd(const Scenario& scenario)
    : max_time_s_(scenario.max_time_s),
      settle_cycles_(std::llround(scenario.settle_time_s / scenario.machine.cycle_time_s())),
      max_cycles_(std::llround(scenario.max_time_s / scenario.machine.cycle_time_s())) {}

bool RunEnd::settled(const Channel& channel, int64_t cycle) {
  if (!channel.finished()) finished_at_ = -1;  // a reset after program end: the run goes on
  else if (finished_at_ < 0) finished_at_ = cycle;
  return finished_at_ >= 0 && cycle - finished_at_ >= settle_cycles_;
}

Event RunEnd::timeout_event() const {
  Event e;
  e.message = "run exceeded run.max_time_s = " + std::to_string(max_time_s_) + " s of simulated time; stopped";
  return e;
}

}  // namespace hil::cnc
