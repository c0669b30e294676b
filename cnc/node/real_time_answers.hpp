#pragma once
// RIG-6 real-time mode: which answers the CNC takes when it never waits,
// free of LCM and of time (the node says which cycle it is in). Cycle k's
// output goes out, then whatever arrives until tick k+1 is taken, counted by
// each participant's AnswerWatch: the answer to k in time, an older one late
// (used all the same: the newest the CNC has), older than one taken or the
// same again counted and not used, a later cycle refused (nobody answers a
// cycle not yet sent: forged). At tick k+1 the cycle ends: the PLC's newest
// control goes into cycle k+1 (none: the last stays in force), the drives'
// monitoring bits of every answer taken reach the channel, and a
// participant silent longer than its watchdog (machine parameters
// watchdog_cycles, plc_watchdog_cycles; cycles the CNC kept in time) is lost: the channel stops on the
// path, jerk-limited, as on a drive error. The logger answers no cycle: it
// is lost when its heartbeat is silent for longer than its timeout; there
// is no flow control (the CNC never waits for it).
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "answer_watch.hpp"
#include "cycle_loop.hpp"
#include "hli.hpp"
#include "machine_config.hpp"

namespace hil::cnc_node {

class RealTimeAnswers {
 public:
  // An axis_sim per axis of `machine`, the PLC; `watch_logger`: a logger takes part.
  RealTimeAnswers(const MachineConfig& machine, bool watch_logger, int64_t logger_timeout_ms);

  // Cycle `cycle`'s output goes out now: what arrives from here on is
  // taken in it.
  void begin(int64_t cycle) { cycle_ = cycle; }
  // An answer; false (refused) only for a cycle not yet sent.
  bool take_axis(size_t axis, int64_t cycle, int32_t errors);
  bool take_plc(int64_t cycle, const HliControl& control);
  // The logger's heartbeat, received at `wall_us`.
  void logger_alive(int64_t wall_us) { logger_heard_us_ = std::max(logger_heard_us_, wall_us); }

  struct Taken {
    std::optional<HliControl> control;       // the PLC's newest, none if nothing new came
    std::vector<int32_t> axis_errors;        // MONITOR_* bits per axis of the answers taken
    std::vector<cnc::LostParticipant> lost;  // lost at the end of this cycle
  };
  // The cycle ends (the next tick has come, at wall clock `now_us`);
  // `overrun`: the CNC woke for it when the one after was due already — it
  // was held off itself, nobody had a cycle time to answer, the cycle does
  // not count towards a watchdog.
  Taken end_cycle(int64_t now_us, bool overrun = false);

  // The drives (machine order), then the PLC.
  const std::vector<AnswerWatch>& watches() const { return watches_; }
  // Everyone lost so far and the cycle it was lost in, for the RUN_END.
  const std::vector<std::pair<std::string, int64_t>>& lost() const { return lost_so_far_; }

 private:
  bool take(size_t who, int64_t cycle);

  std::vector<AnswerWatch> watches_;
  std::vector<std::string> axes_;  // the drives' axes, by watch
  std::vector<bool> lost_;         // by watch
  std::vector<int32_t> errors_;    // by axis, this cycle
  std::optional<HliControl> control_;
  int64_t cycle_ = 0;
  bool watch_logger_, logger_lost_ = false;
  int64_t logger_timeout_ms_;
  int64_t logger_heard_us_ = 0;
  std::vector<std::pair<std::string, int64_t>> lost_so_far_;
};

}  // namespace hil::cnc_node
