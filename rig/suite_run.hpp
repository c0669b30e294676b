#pragma once
// `hil run PATH...` with more than one scenario: a suite (RIG-5, RIG-9).
// Each scenario runs as a `hil run FILE` child of its own, up to --jobs at
// once, each on its own udpm port (or in its own network namespace), its
// outcome read back from the summary.yaml it leaves in its run folder.
#include <ctime>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "run_scenario.hpp"
#include "run_summary.hpp"
#include "scenario_files.hpp"

namespace hil::rig {

struct SuiteOptions {
  std::vector<std::string> files;  // collect_scenario_files, shard_of
  int jobs = 1;
  std::string out_dir;      // a folder per scenario below it
  bool netns = false;       // each run in a network namespace of its own (root)
  bool exit_first = false;  // -x: after the first FAILED or ERROR start no more (the rest SKIPPED)
  RunOptions run;           // what every run gets: bin_dir, port (the first of `jobs`), mode, placement
};

struct SuiteResult {
  std::vector<RunSummary> runs;  // in the order of the files
  double wall_s = 0;
  std::time_t started = 0;  // wall clock at the suite's start
  std::string out_dir;
  bool passed() const;           // no run FAILED or had an ERROR (SKIPPED ones aside; an empty shard passes)
};

// What the suite reports while it runs: a run started (file) or ended (its
// summary); `waiting` is called every 20 ms in between.
struct SuiteListener {
  std::function<void(const std::string& file)> started;
  std::function<void(const RunSummary& run)> finished;
  std::function<void()> waiting;
};

// The run folder of a scenario file in the suite folder: its path below the
// current folder without .yaml (an absolute path's without the leading /).
std::string run_dir_of(const std::string& suite_dir, const std::string& scenario_file);

// Throws ConfigError if the suite cannot start (--netns without root).
SuiteResult run_suite(const SuiteOptions& options, const SuiteListener& listener);

}  // namespace hil::rig
