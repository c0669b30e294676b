#include "run_end.hpp"

#include <cmath>
#include <string>

#include "messages.hpp"

namespace hil::cnc_node {

void apply_drive_errors(cnc::Channel& channel, const MachineConfig& machine, const std::vector<int32_t>& errors) {
  for (size_t i = 0; i < errors.size() && i < machine.axes.size(); ++i)
    if (errors[i]) channel.drive_error(machine.axes[i].name, lcm_support::monitor_names(errors[i]));
}

RunEnd::RunEnd(const Scenario& scenario)
    : max_time_s_(scenario.max_time_s),
      settle_cycles_(std::llround(scenario.settle_time_s / scenario.machine.cycle_time_s())),
      max_cycles_(std::llround(scenario.max_time_s / scenario.machine.cycle_time_s())) {}

bool RunEnd::settled(const cnc::Channel& channel, int64_t cycle) {
  if (channel.finished() && finished_at_ < 0) finished_at_ = cycle;
  return finished_at_ >= 0 && cycle - finished_at_ >= settle_cycles_;
}

Event RunEnd::timeout_event() const {
  Event e;
  e.message = "run exceeded run.max_time_s = " + std::to_string(max_time_s_) + " s of simulated time; stopped";
  return e;
}

}  // namespace hil::cnc_node
