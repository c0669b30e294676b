#pragma once
// `hil run PATH...` (RIG-5, RIG-9): one scenario file runs as always (its
// whole report on stdout); several, a folder or a shard run as a suite with
// progress, a summary table and JUnit / JSON results.
#include <string>
#include <vector>

#include "run_scenario.hpp"

namespace hil::rig {

struct SuiteCommand {
  std::vector<std::string> paths;
  int jobs = 1;
  std::string shard;  // "K/N" or ""
  std::string junit_file, json_file;
  bool netns = false;
  std::vector<std::string> patterns;  // -k: only the scenarios matching one (suite_selection.hpp)
  bool exit_first = false;            // -x
  bool last_failed = false;           // --lf
  bool list = false;                  // --list: show what would run, run nothing
  bool spy = false;                   // --spy: lcm-spy on the run's URL first (live_spy.hpp)
};

// The exit status: 0 if every scenario passed (skipped ones aside), 1 if
// not. Throws ConfigError for what cannot run at all (exit status 2): a path
// that does not exist, a bad --shard, a single scenario file the loader refuses.
int run_scenarios(const SuiteCommand& command, const RunOptions& run);

}  // namespace hil::rig
