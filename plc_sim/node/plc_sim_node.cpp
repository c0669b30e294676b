#include "plc_sim_node.hpp"

#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <spdlog/spdlog.h>

#include "channels.hpp"
#include "messages.hpp"

namespace hil::plc {

PlcSimNode::PlcSimNode(const Scenario& scenario, lcm_support::Inbox& inbox)
    : engine_(scenario), bus_(inbox.bus()), run_id_(inbox.run_id()),
      watchdog_cycles_(scenario.machine.plc_watchdog_cycles) {
  inbox.on<hil::hli_state_t>(channels::hli_state, [this](const hil::hli_state_t& m, const lcm::ReceiveBuffer&) {
    // Each cycle once, in order; a state lost on the way (RIG-8) is a PLC
    // cycle missed, but not more than the watchdog allows (further ahead: forged).
    if (m.cycle <= last_cycle_ || m.cycle > last_cycle_ + 1 + watchdog_cycles_) return false;
    on_state(m);
    return true;
  });
  inbox.on<hil::event_t>(channels::event, [this](const hil::event_t& m, const lcm::ReceiveBuffer&) {
    if (m.source != source) engine_.observe(lcm_support::from_message(m));
    return true;
  });
}

int PlcSimNode::report(int64_t cycle) {
  int published = 0;
  for (const ExpectationResult& r : engine_.finish(cycle)) {
    Event e;
    e.severity = r.passed ? Severity::info : Severity::error;
    e.verdict = r.passed ? Verdict::pass : Verdict::fail;  // what the rig counts
    e.message = std::string(r.passed ? "PASS " : "FAIL ") + r.what + ":" + r.detail;
    (r.passed ? spdlog::info("{}", e.message) : spdlog::error("{}", e.message));
    // Stamped with the cycle it was decided in; published at the end, when
    // the run's last cycle is known (whole-run windows, events never seen).
    hil::event_t m = lcm_support::to_message(e, r.cycle.value_or(cycle), utime_, source);
    m.run_id = run_id_;
    bus_.publish(channels::event, m);
    ++published;
  }
  return published;
}

void PlcSimNode::on_state(const hil::hli_state_t& m) {
  last_cycle_ = m.cycle;
  utime_ = m.utime;
  const HliControl& control = engine_.cycle(lcm_support::from_message(m));
  hil::hli_control_t out = lcm_support::to_message(control, m.utime);
  out.run_id = run_id_;
  bus_.publish(channels::hli_control, out);
}

}  // namespace hil::plc
