#pragma once
// One cycle loop for every way the CNC runs (RIG-6, RIG-7), free of LCM:
// the channel steps with the PLC's answer to the cycle before, its output
// goes out, the answers to the cycle come back, the drives' errors reach the
// channel, and the run ends when it has settled or timed out. The clock is
// a policy: lock-step over LCM (the node waits for every participant's
// answer), recorded input (`cnc --rerun` takes the answers from a log and
// compares the output with it), and the wall clock (real-time mode:
// cnc/node/real_time_answers.hpp, tick_clock.hpp).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "channel.hpp"
#include "event.hpp"
#include "hli.hpp"
#include "scenario.hpp"

namespace hil::cnc {

// A drive's monitoring error answering a cycle (RIG-3).
struct DriveError {
  std::string axis;
  std::string what;  // the monitors, e.g. "acceleration P-AXIS-00442"
};

// A participant that stopped answering (the lock-step watchdog, or in real
// time its watchdog in cycles, RIG-6): the run goes on without it, and the
// channel stops as on a drive error.
struct LostParticipant {
  std::string name;  // "axis_sim X", "plc_sim", "logger"
  std::string axis;  // the drive's axis, "" for any other participant
  std::string what;  // e.g. "no answer to cycle 812 within 5000 ms"
  std::string parameter;  // the machine parameter of the watchdog that fired, e.g. "watchdog_cycles"
};

// What came back for one cycle.
struct CycleAnswers {
  std::optional<HliControl> control;  // none: the PLC's last control stays in force
  std::vector<DriveError> drive_errors;
  std::vector<LostParticipant> lost;  // lost in this cycle
};

class CyclePolicy {
 public:
  virtual ~CyclePolicy() = default;
  // The channel's output of `cycle` with the events raised in it; false
  // stops the run.
  virtual bool publish(int64_t cycle, const Channel& channel, const std::vector<Event>& events) = 0;
  // An event of the loop itself (the run timed out); false stops the run.
  virtual bool publish_event(int64_t cycle, const Event& event) = 0;
  // The answers to `cycle`; none: the run cannot go on.
  virtual std::optional<CycleAnswers> answers(int64_t cycle) = 0;
};

enum class RunOutcome {
  settled,            // the channel finished and the settle time passed
  timed_out,          // max_time_s of simulated time
  publish_refused,    // the policy stopped the run at an output
  answers_missing,    // the policy had no answers to a cycle
};

struct CycleLoopResult {
  RunOutcome outcome = RunOutcome::settled;
  int64_t last_cycle = 0;
};

CycleLoopResult run_cycles(Channel& channel, const Scenario& scenario, CyclePolicy& policy);

}  // namespace hil::cnc
