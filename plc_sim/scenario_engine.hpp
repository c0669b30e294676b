#pragma once
// The PLC simulator's program (RIG-5): runs a scenario's timeline against
// the HLI, cycle by cycle, and checks its expectations.
#include <map>
#include <string>
#include <vector>

#include "event.hpp"
#include "hli.hpp"
#include "scenario.hpp"

namespace hil::plc {

struct ExpectationResult {
  std::string what;
  bool passed = false;
  std::string detail;
};

class ScenarioEngine {
 public:
  // The scenario's field names and values were checked when it was read.
  explicit ScenarioEngine(const Scenario& scenario);

  // One PLC cycle on the CNC's HLI state; returns the control to write back.
  const HliControl& cycle(const HliState& state);
  // An event seen on the bus (from any node but this one).
  void observe(const Event& event);
  // Verdict at the end of the run: one result per expectation.
  std::vector<ExpectationResult> finish() const;

 private:
  // An axis' highest and lowest commanded position over a window.
  struct Extremes {
    double highest = 0, lowest = 0;
    bool seen = false;
  };
  struct Pending {
    Expectation expectation;
    bool opened = false;  // the window began (`since` held, or no `since`)
    int64_t opened_cycle = 0;
    std::map<std::string, Extremes> extremes;  // by axis, over the window
    double path_velocity_max = 0;              // |path_velocity|, over the window
    bool reached = false;
    ExpectationResult result;
  };
  ExpectationResult evaluate(const Pending& p, const HliState& state) const;

  std::vector<TimelineStep> timeline_;
  std::vector<bool> fired_;
  std::vector<Pending> pending_;
  std::vector<EventExpectation> expected_events_;
  std::vector<Event> seen_events_;
  bool allow_errors_;
  int m_function_ack_cycles_;
  int m_function_waited_ = 0;  // cycles the current M function has waited
  double cycle_time_s_;
  HliControl control_;
};

}  // namespace hil::plc
