#pragma once
// RIG-6: which answers the CNC takes in lock-step, free of LCM. Every
// axis_sim and plc_sim answers each cycle; the CNC takes only the answer to
// the cycle it waits for, and only the first (anything else is refused and
// counted by the node: a forged or replayed higher cycle must not satisfy
// every cycle after it). A participant that has not answered when the
// watchdog fires is lost: the channel stops and the run goes on without
// waiting for it. The logger answers no cycle; its heartbeat must not fall
// silent for longer than its timeout, and it must not fall more than
// `logger_window` cycles behind: a logger descheduled on a loaded machine
// would otherwise lose datagrams at its full socket (RIG-9).
// With faults planned (RIG-8) the answers due in a cycle are those the plan
// lets arrive then (AnswerSchedule): none for a lost input, a late one for
// a delay, all at once after a freeze; an AnswerWatch per participant counts
// them, and its watchdog loses a participant silent for longer than its
// machine parameter (watchdog_cycles, plc_watchdog_cycles).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "answer_watch.hpp"
#include "cycle_loop.hpp"
#include "fault_plan.hpp"
#include "hli.hpp"
#include "machine_config.hpp"
#include "process_state.hpp"

namespace hil::cnc_node {

class LockStep {
 public:
  // An axis_sim per axis of `machine`; `watch_logger`: a logger takes part;
  // `faults`: the run's plan (it must outlive this), none or empty: every
  // answer in its own cycle.
  LockStep(const MachineConfig& machine, bool watch_logger, int64_t answer_timeout_ms, int64_t logger_timeout_ms,
           const FaultPlan* faults = nullptr);

  // Waits for the answers due in `cycle` from now on (call for every cycle, in order).
  void begin(int64_t cycle);
  // An answer; false (refused) unless it is one due now and not yet taken.
  bool take_axis(size_t axis, int64_t cycle, int32_t errors);
  bool take_plc(int64_t cycle, const HliControl& control);
  // The cycles whose answers are due now and not yet taken (a rerun feeds them).
  const std::vector<int64_t>& awaited_axis(size_t axis) const { return axes_.at(axis).awaited; }
  const std::vector<int64_t>& awaited_plc() const { return plc_.awaited; }
  // The counts of each participant's answers, drives first, the PLC last.
  std::vector<std::pair<std::string, AnswerCounts>> answer_counts() const;
  // Every participant not lost has answered the cycle.
  bool complete() const;
  // The cycle waited for.
  int64_t cycle() const { return cycle_; }
  // A participant's process, by name ("axis_sim X", "plc_sim", "logger").
  using Liveness = std::function<ProcessState(const std::string& name)>;
  // The answer timeout passed: whoever has not answered is lost, but for
  // one whose process `liveness` finds alive and running (a loaded host),
  // which is waited for on. Returns the names waited for. (The loss's event
  // does not name the process' state: a rerun, which has no process,
  // reproduces it word for word.)
  std::vector<std::string> lose_silent(const Liveness& liveness = {});

  static constexpr int64_t logger_window = 128;

  // The logger's heartbeat, received at `wall_us`: it has recorded the
  // cycles up to `recorded_cycle`.
  void logger_alive(int64_t wall_us, int64_t recorded_cycle) {
    logger_heard_us_ = std::max(logger_heard_us_, wall_us);
    logger_cycle_ = std::max(logger_cycle_, recorded_cycle);
  }
  // The cycle waited for is more than logger_window ahead of the logger:
  // wait for it before the next cycle.
  bool logger_behind() const { return watch_logger_ && !logger_.lost && cycle_ - logger_cycle_ > logger_window; }
  // At `now_us`: a logger silent, or behind, for longer than its timeout is
  // lost, unless `liveness` finds its process running (then it is waited
  // for: true).
  bool check_logger(int64_t now_us, const Liveness& liveness = {});

  struct Taken {
    std::optional<HliControl> control;     // the PLC's answer, none if lost
    std::vector<int32_t> axis_errors;      // MONITOR_* bits per axis, 0 if lost
    std::vector<cnc::LostParticipant> lost;  // lost in this cycle
  };
  // What the cycle brought (call once, when complete).
  Taken take();

  // Everyone lost so far and the cycle it was lost in, for the RUN_END.
  const std::vector<std::pair<std::string, int64_t>>& lost() const { return lost_so_far_; }

 private:
  struct Answerer {
    std::string name;
    std::string axis;
    std::string watchdog_parameter;
    AnswerWatch watch;
    std::optional<AnswerSchedule> schedule;  // with faults planned on it
    std::vector<int64_t> awaited;             // due now, not yet taken
    bool lost = false;
    int32_t errors = 0;  // of the answers taken this cycle
  };
  Answerer answerer(const std::string& name, const std::string& axis, const std::string& parameter,
                    int64_t watchdog_cycles, const FaultPlan* faults);
  // Takes one of the answers due: whether it was due; `use` whether it is new.
  bool take_due(Answerer& who, int64_t cycle, bool& use);
  void lose(Answerer& who, const std::string& what, const std::string& parameter = "");

  std::vector<Answerer> axes_;
  Answerer plc_;
  Answerer logger_;
  bool watch_logger_;
  int64_t answer_timeout_ms_, logger_timeout_ms_;
  int64_t cycle_ = -1;
  int64_t logger_heard_us_ = 0;
  int64_t logger_cycle_ = -1;
  int64_t logger_behind_since_us_ = -1;
  std::optional<HliControl> control_;
  std::vector<cnc::LostParticipant> newly_lost_;
  std::vector<std::pair<std::string, int64_t>> lost_so_far_;
};

}  // namespace hil::cnc_node
