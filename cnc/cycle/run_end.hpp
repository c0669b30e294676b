#pragma once
// When a run ends (RIG-6): `settle_time_s` after the channel finished, or at
// `max_time_s` of simulated time.
#include <cstdint>

#include "channel.hpp"
#include "event.hpp"
#include "scenario.hpp"

namespace hil::cnc {

class RunEnd {
 public:
  explicit RunEnd(const Scenario& scenario);
  // Asked once per cycle, after its answers: has the run settled?
  bool settled(const Channel& channel, int64_t cycle);
  bool timed_out(int64_t cycle) const { return cycle >= max_cycles_; }
  // The error published when the run times out.
  Event timeout_event() const;

 private:
  double max_time_s_;
  int64_t settle_cycles_, max_cycles_;
  int64_t finished_at_ = -1;
};

}  // namespace hil::cnc
