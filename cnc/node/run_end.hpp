#pragma once
// The parts of the CNC node's cycle loop that `cnc --rerun` must repeat
// exactly (RIG-6, RIG-7): how the drives' answers reach the channel, and
// when the run ends.
#include <cstdint>
#include <vector>

#include "channel.hpp"
#include "event.hpp"
#include "scenario.hpp"

namespace hil::cnc_node {

// The axes' monitoring error bits answering a cycle (axis_state_t.errors),
// handed to the channel before it computes the next one (RIG-3).
void apply_drive_errors(cnc::Channel& channel, const MachineConfig& machine, const std::vector<int32_t>& errors);

// The run ends `settle_time_s` after the channel finished, or at
// `max_time_s` of simulated time.
class RunEnd {
 public:
  explicit RunEnd(const Scenario& scenario);
  // Asked once per cycle, after its answers: has the run settled?
  bool settled(const cnc::Channel& channel, int64_t cycle);
  bool timed_out(int64_t cycle) const { return cycle >= max_cycles_; }
  // The error published when the run times out.
  Event timeout_event() const;

 private:
  double max_time_s_;
  int64_t settle_cycles_, max_cycles_;
  int64_t finished_at_ = -1;
};

}  // namespace hil::cnc_node
