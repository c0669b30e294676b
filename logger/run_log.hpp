#pragma once
// Reads a rig's LCM event log (RIG-4): the manifest that explains it, the
// axis traces, the HLI states and the events, decoded.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "event.hpp"
#include "limit_check.hpp"
#include "scenario.hpp"
#include "verdict.hpp"

namespace hil::logger {

struct LoggedEvent {
  int64_t cycle = 0;
  std::string source;
  Event event;
};

// One axis over the run, for plots: the CNC's setpoints and the drive's answers.
struct AxisTrace {
  std::vector<int64_t> cmd_cycle;
  std::vector<double> cmd_position, cmd_velocity, cmd_acceleration;
  std::vector<int64_t> act_cycle;
  std::vector<double> act_position, act_velocity, act_acceleration, following_error;
};

// The HLI signals people look at, per cycle.
struct HliTrace {
  std::vector<int64_t> cycle;
  std::vector<double> path_velocity, dist_prog_start_mm;
  std::vector<int64_t> block_nr_r;
  std::vector<int> channel_state;
  std::vector<int> block_search_state;  // block_search.state_r.state (DPS-3)
  std::vector<int32_t> stop_conditions;  // stop_conditions_r
  std::vector<double> override_percent;  // override.state_r in %
};

// RIG-6 real-time mode: the CNC's last statistics (rt_stats_t).
struct RealTimeFigures {
  int64_t cycle = 0;
  bool final = false;
  int32_t cycle_us = 0;
  std::string scheduling;  // the cnc's
  int64_t ticks = 0, overruns = 0;
  double jitter_p50_us = 0, jitter_p99_us = 0, jitter_max_us = 0;
  struct Answers {
    std::string name;
    int64_t in_time = 0, late = 0, missing = 0, out_of_order = 0, duplicate = 0, longest_gap_cycles = 0,
            watchdog_cycles = 0;
  };
  std::vector<Answers> participants;
  int64_t messages = 0;  // HIL_RT_STATS messages of the run in the log
};

struct RunLog {
  std::optional<Scenario> scenario;  // from HIL_SCENARIO
  std::string rig_version;
  std::vector<LoggedEvent> events;
  std::map<std::string, int64_t> messages_per_channel;
  int64_t last_cycle = -1;
  std::vector<AxisTrace> axes;  // in the scenario's axis order
  HliTrace hli;
  LogFacts facts;  // whether the log holds the whole run (verdict.hpp)
  std::optional<RealTimeFigures> real_time;  // the last HIL_RT_STATS, real-time runs only
};

// Reads `path`: the run of its first manifest (messages of other runs are
// counted and left out); feeds the axis traces into a LimitChecker built
// from the scenario, if there is one. Throws std::runtime_error if the file
// cannot be opened or holds no LCM event at all; whatever else is wrong with
// it (damaged records, undecodable messages, a scenario text that is none,
// a RUN_END cycle beyond what it holds) lands in `facts`, so the verdict
// fails it. What it allocates is bounded by the file's size.
RunLog read_run_log(const std::string& path, std::optional<CheckReport>* report = nullptr);

// Compares two logs channel by channel, message by message, on the payload
// bytes (all times in them are simulated, so equal runs give equal bytes)
// but for the run id, which differs from run to run. HIL_PARTICIPANT (the
// handshake), HIL_LOG_END (the logger's seal) and LCM_SELF_TEST are left
// out: they follow wall-clock order. Returns "" if identical, else the
// first difference; a damaged file is a difference. Throws as read_run_log.
std::string compare_run_logs(const std::string& a, const std::string& b);

}  // namespace hil::logger
