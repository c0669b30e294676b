#pragma once
// `hil run`: starts every process of a scenario on a private LCM port in
// lock-step, waits for the end, checks the log offline and reports (RIG-5).
#include <string>

#include "scenario_set.hpp"

namespace hil::rig {

struct RunOptions {
  std::string scenario_file;
  std::string run_dir;       // "" = runs/<name>-<time> below the current folder
  int port = 0;              // 0 = derived from the process id
  std::string bin_dir;       // where cnc, axis_sim, plc_sim, hil_logger are
  bool quiet = false;        // summary line only
  bool in_process = false;   // every node in this process on the in-process bus (in_process_run.hpp)
  int cpu = -2;              // the CPU of the lock-step nodes: -2 the one hil starts on, -1 anywhere
  int fifo_priority = 0;     // SCHED_FIFO priority of the lock-step nodes, one for all; 0: normal scheduling
  bool realtime = false;     // real-time mode (RIG-6) whatever the scenario's run.realtime says
  int answer_timeout_ms = 0;  // the lock-step CNC's watchdog per cycle (RIG-6); 0: the cnc's default, 5000
  double pace = 0;            // lock-step no faster than pace x real time (--pace); 0: as fast as it goes
};

struct RunResult {
  bool passed = false;
  std::string run_dir;
  std::string log_file;
  std::string report;
  double simulated_s = 0;     // of every variant
  double wall_s = 0;          // the runs', without loading and checking
  std::string first_failure;  // the first failed expectation, else the first reason ("" if passed)
  bool recorded = true;       // false: no log (a node could not start), an ERROR in a suite
};

// Throws ConfigError for a scenario that cannot run. Leaves report.txt and
// summary.yaml (run_summary.hpp) in the run folder.
RunResult run_scenario(const RunOptions& options);
// The scenario file of `options` loaded and checked as a run needs it: its
// timeline's HLI fields, the drive models, the NC program decoded as a
// whole (KRN-8); throws ConfigError naming the file.
ScenarioSet load_valid_scenario_set(const RunOptions& options);

// "runs/<name>-<YYYYmmdd-HHMMSS>": a run's folder unless --out says.
std::string default_run_dir(const std::string& name);

// The rig's LCM URL for a port: multicast that never leaves the machine
// (ttl=0) and a receive buffer deep enough for lock-step bursts.
std::string rig_url(int port);
// The run's udpm port: --port, else derived from the process id.
int rig_port(const RunOptions& options);

}  // namespace hil::rig
