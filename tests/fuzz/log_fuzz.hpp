#pragma once
// The log fuzz (RIG-4, RIG-9): real logs of small in-process runs, mutated
// (log_mutation.hpp), and every mutant fed to every reader of a log: the
// verdict (`hil run`, `hil check`: read_run_log, log_problems, judge_run,
// the check's text, the plots' files), `hil export` (CSV), `hil compare`
// against the original, `hil rerun`. Each mutant runs in a child process
// with an address-space limit and a CPU-time limit; it holds if
//
//  - nothing crashes, hangs or runs out of memory, and no exception leaves
//    a reader but the documented ones (a file with no LCM event in it;
//    hil rerun's "cannot rerun" errors, its exit status 2);
//  - a mutant that must fail (log_mutation.hpp: truncated, a forged or
//    changed RUN_END cycle, a record dropped, duplicated or renamed, a
//    length field or a lock-step cycle changed, ...) is never judged PASS;
//  - hil compare never calls a mutant of a compared channel identical, hil
//    rerun never one of the cnc's own output;
//  - the export accounts for every message (rows, undecodable, too wide,
//    unknown channels).
#include <cstdint>
#include <string>
#include <vector>

#include "log_mutation.hpp"

namespace hil::fuzz {

struct BaseLog {
  std::string name, path;
  bool passes = false;  // as judged by the rig; a failing one must stay failed
  LogRecords records;
  int64_t bytes = 0;
};

// Runs the fuzz's two scenarios in-process into `dir` (a passing one, and
// one with planned faults and a failing expectation) and reads their logs.
// Throws std::runtime_error if a run does not come out as planned, or the
// field map (log_mutation.hpp) disagrees with lcm-gen on any record.
std::vector<BaseLog> make_base_logs(const std::string& dir);

struct LogFuzzOptions {
  std::string work_dir;          // mutants and the readers' output
  unsigned cpu_limit_s = 10;     // per mutant
  int64_t memory_limit_mb = 512;  // address space per mutant beyond the fuzz's own
  bool rerun = true;
};

struct MutantResult {
  uint64_t seed = 0;
  std::string base;
  MutationKind kind = MutationKind::truncate;
  std::string what;
  bool changed = true;
  std::string verdict;  // "PASS", "FAIL", or what the check path refused with
  std::vector<std::string> failures;  // empty: every reader held
  double wall_s = 0;
  int64_t peak_rss_kb = 0;  // the readers' process's peak resident set (what of the fuzz it touched, and theirs)
};

// One seeded mutant of one of `bases`, through every reader, in a child process.
MutantResult run_mutant(const std::vector<BaseLog>& bases, uint64_t seed, const LogFuzzOptions& options);

// The same without a child process (a crash ends the caller): for reproducing one.
MutantResult run_mutant_here(const std::vector<BaseLog>& bases, uint64_t seed, const LogFuzzOptions& options);

// The mutant of `seed` (for writing it to a file and trying it by hand).
Mutant mutant_of(const std::vector<BaseLog>& bases, uint64_t seed, std::string* base_name = nullptr);

}  // namespace hil::fuzz
