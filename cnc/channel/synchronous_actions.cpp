#include "synchronous_actions.hpp"

namespace hil::cnc {

bool SynchronousActions::queue(const Block& block) {
  for (const MFunction& m : block.m_functions) actions_.push_back({m.nr, 0, 0});
  if (block.dwell_s > 0) actions_.push_back({-1, block.dwell_s, 0});
  return !block.m_functions.empty() || block.dwell_s > 0;
}

bool SynchronousActions::run(const ControlUnitBool& ack, double t, HliState& hli) {
  const bool acknowledged = acknowledgement_(ack.command_w) && ack.enable_w;
  if (actions_.empty()) return false;
  // Each action done lets the next one start in the same cycle.
  while (!actions_.empty()) {
    const Action& action = actions_.front();
    if (action.m_function >= 0) {
      if (!hli.m_function_request_r) {
        hli.m_function_request_r = true;  // output; acknowledged in a later cycle
        hli.m_function_nr_r = action.m_function;
        hli.m_function_add_nr_r = action.add_nr;
        return false;
      }
      if (!acknowledged) return false;
      hli.m_function_request_r = false;
    } else {
      if (dwell_end_ < 0) dwell_end_ = t + action.dwell_s;
      if (t < dwell_end_ - 1e-9) return false;
      dwell_end_ = -1;
    }
    actions_.pop_front();
  }
  return true;
}

}  // namespace hil::cnc
