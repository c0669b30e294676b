#pragma once
// One scenario's outcome in a suite (RIG-5, RIG-9): what the summary table,
// JUnit and JSON show. `hil run` writes it into the run folder as
// summary.yaml; the suite that started it reads it back.
#include <optional>
#include <string>
#include <vector>

namespace hil::rig {

enum class Outcome { passed, failed, error, skipped };

// "PASSED", "FAILED", "ERROR" (could not run: bad file, a node that did not
// start), "SKIPPED" (not run, and why is in first_failure).
const char* outcome_name(Outcome outcome);
std::optional<Outcome> outcome_of(const std::string& name);

struct RunSummary {
  std::string scenario_file;
  std::string name;                       // the scenario's
  std::vector<std::string> requirements;  // the SPEC IDs it names
  Outcome outcome = Outcome::error;
  double simulated_s = 0;
  double wall_s = 0;
  std::string first_failure;  // the first failed expectation, else the first reason, the error, why skipped
  std::string run_dir;
  double real_time_factor() const { return wall_s > 0 ? simulated_s / wall_s : 0; }
};

void write_run_summary(const RunSummary& summary, const std::string& path);
// Throws std::runtime_error for a file that is not a summary.
RunSummary read_run_summary(const std::string& path);

}  // namespace hil::rig
