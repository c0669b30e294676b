#include "synchronous_actions.hpp"
#include "tolerances.hpp"

namespace hil::cnc {

bool SynchronousActions::queue(const Block& block) {
  for (const MFunction& m : block.m_functions) actions_.push_back({m.address, m.nr, m.value, 0, 0});
  if (block.dwell_s > 0) actions_.push_back({dwell, 0, 0, block.dwell_s, 0});
  return !block.m_functions.empty() || block.dwell_s > 0;
}

bool& SynchronousActions::request(char address, HliState& hli) {
  switch (address) {
    case 'H': return hli.h_function_request_r;
    case 'S': return hli.s_function_request_r;
    case 'T': return hli.t_function_request_r;
    default: return hli.m_function_request_r;
  }
}

void SynchronousActions::output(const Action& action, HliState& hli) {
  switch (action.address) {
    case 'H': hli.h_function_nr_r = action.nr; break;
    case 'S': hli.s_function_value_r = action.value; break;
    case 'T': hli.t_function_nr_r = action.nr; break;
    default:
      hli.m_function_nr_r = action.nr;
      hli.m_function_add_nr_r = action.add_nr;
  }
  request(action.address, hli) = true;
}

bool SynchronousActions::run(const HliControl& control, double t, HliState& hli) {
  auto edge = [](RisingEdge& e, const ControlUnitBool& ack) { return e(ack.command_w) && ack.enable_w; };
  const bool acknowledged[] = {edge(m_ack_, control.m_function_ack), edge(h_ack_, control.h_function_ack),
                               edge(s_ack_, control.s_function_ack), edge(t_ack_, control.t_function_ack)};
  auto acknowledged_for = [&](char address) {
    return acknowledged[address == 'H' ? 1 : address == 'S' ? 2 : address == 'T' ? 3 : 0];
  };
  if (actions_.empty()) return false;
  // Each action done lets the next one start in the same cycle.
  while (!actions_.empty()) {
    const Action& action = actions_.front();
    if (action.address == 'D') {
      hli.tool_offset_nr_r = action.nr;  // selects the tool offset: no handshake
    } else if (action.address != dwell) {
      bool& requested = request(action.address, hli);
      if (!requested) {
        output(action, hli);
        return false;  // acknowledged in a later cycle
      } else {
        if (!acknowledged_for(action.address)) return false;
        requested = false;
      }
    } else {
      if (dwell_end_ < 0) dwell_end_ = t + action.dwell_s;
      if (t < dwell_end_ - tolerance::time_s) return false;
      dwell_end_ = -1;
    }
    actions_.pop_front();
    ++done_;
  }
  return true;
}

}  // namespace hil::cnc
