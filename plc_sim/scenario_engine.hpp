#pragma once
// The PLC simulator's program (RIG-5): runs a scenario's timeline against
// the HLI, cycle by cycle, and checks its expectations.
#include <map>
#include <optional>
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
  // The HLI cycle it was decided in; none: at the run's end (never reached,
  // a whole-run window, an event expectation).
  std::optional<int64_t> cycle;
};

class ScenarioEngine {
 public:
  // The scenario's field names and values were checked when it was read.
  explicit ScenarioEngine(const Scenario& scenario);

  // One PLC cycle on the CNC's HLI state; returns the control to write back.
  const HliControl& cycle(const HliState& state);
  // An event seen on the bus (from any node but this one).
  void observe(const Event& event);
  // Verdict at the end of the run: one result per expectation. `end_cycle`:
  // the run's last cycle (the CNC's RUN_END); a whole-run never: / always:
  // passes only if the PLC saw every cycle up to it. Without: the last
  // cycle seen.
  std::vector<ExpectationResult> finish(std::optional<int64_t> end_cycle = std::nullopt) const;

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
    bool reached = false;  // decided
    ExpectationResult result;
  };
  ExpectationResult evaluate(const Pending& p, const HliState& state) const;
  // never: / always: in an open window; decides p on a break or the window's end.
  void watch(Pending& p, const HliState& state, bool missed_cycles);

  std::vector<TimelineStep> timeline_;
  std::vector<bool> fired_;
  std::vector<Pending> pending_;
  std::vector<EventExpectation> expected_events_;
  std::vector<Event> seen_events_;
  bool allow_errors_;
  int m_function_ack_cycles_;
  int function_waited_[4] = {};  // cycles the current M, H, S, T function has waited
  double cycle_time_s_;
  int64_t last_cycle_ = -1;  // the last HLI state seen
  HliControl control_;
};

}  // namespace hil::plc
