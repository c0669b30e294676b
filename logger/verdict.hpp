#pragma once
// RIG-9, the verdict, free of LCM: when a log holds a whole run, and when a
// run passes. docs/RELIABILITY.md says it in words ("a PASS means ...").
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fault_plan.hpp"
#include "traffic.hpp"

namespace hil::logger {

// What a run's log shows about itself (read_run_log fills it in).
struct LogFacts {
  int64_t run_id = 0;
  bool manifest = false;  // this run's HIL_MANIFEST
  bool scenario = false;  // HIL_SCENARIO, written by the logger after it
  bool sealed = false;    // HIL_LOG_END: the logger closed the log on purpose
  std::vector<std::string> logger_missing;  // whose end the seal says the logger did not see
  int64_t logger_socket_drops = 0;          // datagrams the kernel dropped at the logger's socket

  std::vector<std::string> participants;  // who must announce RUN_END: the manifest's, the cnc, not the logger
  std::set<std::string> ended;            // whose RUN_END the log holds
  std::optional<int64_t> end_cycle;       // the cnc's RUN_END
  std::map<std::string, int64_t> lost;    // whom the cnc lost (the watchdog), at which cycle

  // The cycle of every message on each lock-step channel (AXIS_<X>_CMD,
  // AXIS_<X>_STATE, HLI_STATE, HLI_CONTROL), in log order; each must hold
  // every cycle 0 .. end_cycle once (in real time only the CNC's output).
  std::map<std::string, std::vector<int64_t>> lock_step;

  // RIG-6 real-time mode (the scenario's run.realtime): answers may be late
  // or missing by nature (counted in the statistics, not a gap in the log);
  // the log must hold the CNC's final statistics (HIL_RT_STATS).
  bool realtime = false;
  bool rt_stats_final = false;

  // What was not taken, by who did not take it: "log" (found reading it),
  // "logger" (the seal), and every node (its RUN_END).
  std::map<std::string, traffic::Ledger> refused;

  // RIG-8: the faults the scenario planned. On a channel they act on, the
  // log must hold exactly what the plan lets through (each cycle as often as
  // sent: none if dropped, damaged or never released, twice if duplicated);
  // refusals there, a participant they act on lost, a participant they kill
  // exiting by SIGKILL are the faults' doing, not a broken run.
  FaultPlan faults;

  // What of the log cannot be read (the file not whole records, a
  // HIL_SCENARIO that is no scenario): the run it holds may be incomplete.
  std::vector<std::string> unreadable;
  // The logger's seal: the records it wrote before it (log_summary_t.recorded)
  // and the cnc's end cycle it saw; and the records the log holds before and
  // after it (it is the last). A log edited after the run differs here.
  std::optional<int64_t> seal_recorded, seal_cycle;
  int64_t records_before_seal = 0, records_after_seal = 0;

  int expectations = -1;               // the scenario's expectations (expect + expect_events), -1 unknown
  int verdict_pass = 0, verdict_fail = 0;  // plc_sim's verdict events (event_t.verdict)
  std::optional<int32_t> verdicts_announced;  // how many plc_sim says it published (its RUN_END)
};

// Every reason the log does not hold a whole run; empty if it does. In
// lock-step: every participant's answer for every cycle; in real time:
// every cycle of the CNC's output, its final statistics. Both: every
// participant's RUN_END, the log closed by the logger, nothing unreadable.
std::vector<std::string> log_problems(const LogFacts& facts);

struct ProcessExit {
  std::string name;
  std::optional<int> status;  // none: hung, killed by hil
};

struct RunVerdict {
  bool passed = false;
  std::vector<std::string> reasons;  // why not
};

// A run passes only if every process exited 0, the log holds the whole run
// (log_problems), every expectation's verdict is in it and none failed, and
// the offline check passed (`check_failure` empty).
RunVerdict judge_run(const std::vector<ProcessExit>& exits, const LogFacts& facts, const std::string& check_failure);

// What every node refused, for the report: "cnc: AXIS_Y_STATE: 1 wrong cycle", or "none".
std::string describe_refused(const LogFacts& facts);

// Who of a run has ended, as the logger sees it: it closes the log when
// every participant it was told of (by hil run, or the manifest; never
// just those whose READY it happened to hear) has announced RUN_END or the
// cnc lost it.
class Attendance {
 public:
  // A participant whose RUN_END closes the log (the logger itself is none).
  void expect(const std::string& name) {
    if (name != "logger") expected_.insert(name);
  }
  // A RUN_END; the cnc's names the cycle and whom it lost.
  void ended(const std::string& name, int64_t cycle, const std::vector<std::string>& lost);

  bool cnc_ended() const { return end_cycle_ >= 0; }
  int64_t end_cycle() const { return end_cycle_; }  // -1 before the cnc's RUN_END
  // Every participant ended or was lost, the cnc's end included.
  bool complete() const { return cnc_ended() && missing().empty(); }
  // Participants neither ended nor lost.
  std::vector<std::string> missing() const;
  const std::set<std::string>& lost() const { return lost_; }

 private:
  std::set<std::string> expected_{"cnc"}, ended_, lost_;
  int64_t end_cycle_ = -1;
};

}  // namespace hil::logger
