#pragma once
// The PLC on the bus (RIG-1, RIG-5): answers every HLI_STATE with an
// HLI_CONTROL from the scenario's timeline, checks the expectations and
// reports them at the end of the run: one event per expectation, its
// verdict a field, and their number in its RUN_END, so that the rig can
// tell a log that lost a verdict from one that holds them all (RIG-9).
#include <hil/hli_state_t.hpp>

#include <cstdint>
#include <string>

#include "inbox.hpp"
#include "scenario.hpp"
#include "scenario_engine.hpp"

namespace hil::plc {

class PlcSimNode {
 public:
  static inline const std::string source = "plc_sim";

  PlcSimNode(const Scenario& scenario, lcm_support::Inbox& inbox);

  // Publishes one event per expectation, its verdict a field (the text is
  // for people); returns how many it published.
  int report(int64_t cycle);
  // The last HLI_STATE cycle taken (-1: none yet).
  int64_t last_cycle() const { return last_cycle_; }

 private:
  void on_state(const hil::hli_state_t& m);

  ScenarioEngine engine_;
  lcm_support::Bus& bus_;
  int64_t run_id_;
  int64_t watchdog_cycles_;
  int64_t last_cycle_ = -1;
  int64_t utime_ = 0;
};

}  // namespace hil::plc
