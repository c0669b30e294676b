#include "log_fuzz.hpp"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

#include "csv_export.hpp"
#include "fuzz_rng.hpp"
#include "plot_export.hpp"
#include "report.hpp"
#include "rerun.hpp"
#include "run_log.hpp"
#include "run_scenario.hpp"
#include "verdict.hpp"

namespace hil::fuzz {
namespace {

namespace fs = std::filesystem;

// The fuzz's scenarios: short runs on the XYZ machine (a few hundred
// cycles, a few thousand records), so that a mutant is read in milliseconds.
constexpr const char* program = R"(  %log_fuzz
  N10 G01 X3 Y2 F6000
  N20 G03 X5 Y0 I2 J0
  N30 M7
  N40 M30
)";

std::string scenario_text(const std::string& name, bool failing) {
  std::ostringstream s;
  s << "name: " << name << "\nrequirements: [RIG-4, RIG-9]\nmachine: " << HIL_SOURCE_DIR
    << "/config/xyz_machine.yaml\nnc_program: |\n"
    << program << "run:\n  max_time_s: 3\n  settle_time_s: 0.02\n";
  // The failing one: planned faults on every kind of lock-step channel
  // (the verdict's planned-copies check) and an expectation that fails.
  if (failing)
    s << "fault_seed: 5\nfaults:\n  - {duplicate: AXIS_X_STATE, percent: 20, from_s: 0.05}\n"
         "  - {drop: HLI_CONTROL, percent: 10, from_s: 0.05}\n";
  s << "plc:\n  m_function_ack_cycles: 3\n  timeline:\n"
       "    - when: {cycle: 2}\n      set: {program_start.enable_w: true, program_start.command_w: true}\n"
       "    - when: {channel_state: ACTIVE}\n      set: {program_start.command_w: false}\n"
       "expect:\n  - when: program_end\n    channel_state: PROGRAM_END\n"
    << (failing ? "    block_nr_r: 30\n" : "    block_nr_r: 40\n");
  return s.str();
}

// The readers' refusals their callers turn into exit status 2 with the reason.
bool documented_refusal(const std::string& what) {
  return what.find("is not an LCM event log") != std::string::npos || what.find("cannot open LCM log") != std::string::npos;
}

struct Outcome {
  std::string verdict;
  std::vector<std::string> failures;
};

// `hil run` / `hil check`: the log read, judged, printed, plotted.
void check_path(const BaseLog& base, const Mutant& m, const std::string& path, const std::string& scratch, Outcome& o) {
  std::optional<logger::CheckReport> check;
  logger::RunLog log;
  try {
    log = logger::read_run_log(path, &check);
  } catch (const std::runtime_error& e) {
    o.verdict = std::string("refused: ") + e.what();
    if (!documented_refusal(e.what())) o.failures.push_back(std::string("read_run_log threw: ") + e.what());
    return;
  }
  const std::string check_failure = !check ? "no scenario in the log"
                                    : check->passed() ? ""
                                                      : std::to_string(check->violations.size()) + " limit violation(s)";
  const logger::RunVerdict v = logger::judge_run({{"cnc", 0}}, log.facts, check_failure);
  o.verdict = v.passed ? "PASS" : "FAIL";
  // A failing run stays failed whatever is done to its messages, but for
  // a flipped bit in a value (the failed verdict's byte, say): nothing in a
  // log vouches for the values.
  const bool must_fail = m.must_fail || (!base.passes && m.kind != MutationKind::flip_bytes);
  if (m.changed && must_fail && v.passed) o.failures.push_back("judged PASS");
  if (check) {
    const std::string text = rig::format_check(log, *check) + (log.facts.realtime ? rig::format_real_time(log) : "");
    (void)text;
    logger::write_plot_files(log, *check, scratch + "/plots");
  }
  (void)logger::describe_refused(log.facts);
}

// `hil export`: every message is a row, or counted as left out.
void export_path(const std::string& path, const std::string& scratch, Outcome& o) {
  try {
    const logger::CsvExport x = logger::export_csv(path, scratch + "/csv");
    int64_t accounted = 0;
    for (const auto& c : x.channels) accounted += c.rows + c.skipped + c.too_wide;
    for (const auto& u : x.unknown) accounted += u.second;
    for (const auto& u : x.too_many) accounted += u.second;
    if (accounted != x.messages)
      o.failures.push_back("export: " + std::to_string(x.messages) + " messages, " + std::to_string(accounted) +
                           " accounted for");
  } catch (const std::runtime_error& e) {
    if (!documented_refusal(e.what())) o.failures.push_back(std::string("export threw: ") + e.what());
  }
}

void compare_path(const BaseLog& base, const Mutant& m, const std::string& path, Outcome& o) {
  try {
    const std::string difference = logger::compare_run_logs(base.path, path);
    if (m.changed && m.must_differ && difference.empty()) o.failures.push_back("compare: identical");
  } catch (const std::runtime_error& e) {
    if (!documented_refusal(e.what())) o.failures.push_back(std::string("compare threw: ") + e.what());
  }
}

// `hil rerun`: any std::runtime_error (a ConfigError from the log's
// scenario among them) is its "cannot rerun", exit status 2.
void rerun_path(const Mutant& m, const std::string& path, Outcome& o) {
  std::ostringstream out;
  try {
    const int status = cnc_node::rerun(path, out);
    if (m.changed && m.must_rerun_differ && status == 0) o.failures.push_back("rerun: identical");
  } catch (const std::runtime_error&) {
  }
}

Outcome read_everywhere(const BaseLog& base, const Mutant& m, const std::string& path, const std::string& scratch,
                        bool rerun) {
  Outcome o;
  // Anything but the documented refusals escaping a reader is a failure
  // (std::bad_alloc, std::length_error: a length was trusted).
  auto guarded = [&](const char* reader, auto&& read) {
    try {
      read();
    } catch (const std::exception& e) {
      o.failures.push_back(std::string(reader) + ": exception " + e.what());
    }
  };
  guarded("check", [&] { check_path(base, m, path, scratch, o); });
  guarded("export", [&] { export_path(path, scratch, o); });
  guarded("compare", [&] { compare_path(base, m, path, o); });
  if (rerun) guarded("rerun", [&] { rerun_path(m, path, o); });
  std::error_code ec;
  fs::remove_all(scratch, ec);
  return o;
}

// A line each: the verdict, then the failures.
std::string serialise(const Outcome& o) {
  auto line = [](std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text + '\n';
  };
  std::string s = line(o.verdict);
  for (const std::string& f : o.failures) s += line(f);
  return s;
}

int64_t address_space_bytes() {
  std::ifstream statm("/proc/self/statm");
  int64_t size = 0;
  statm >> size;
  return size * sysconf(_SC_PAGESIZE);
}

const BaseLog& base_of(const std::vector<BaseLog>& bases, Rng& rng) {
  return bases[static_cast<size_t>(rng.integer(0, static_cast<int64_t>(bases.size()) - 1))];
}

MutantResult prepare(const std::vector<BaseLog>& bases, uint64_t seed, const LogFuzzOptions& options, Mutant& m,
                     const BaseLog*& base, std::string& path) {
  Rng rng(seed);
  base = &base_of(bases, rng);
  m = mutate(base->records, rng);
  MutantResult r;
  r.seed = seed;
  r.base = base->name;
  r.kind = m.kind;
  r.what = m.what;
  r.changed = m.changed;
  fs::create_directories(options.work_dir);
  path = (fs::path(options.work_dir) / ("mutant_" + std::to_string(seed) + ".lcmlog")).string();
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(m.bytes.data()),
                                              static_cast<std::streamsize>(m.bytes.size()));
  return r;
}

std::string scratch_dir(const LogFuzzOptions& options, uint64_t seed) {
  return (fs::path(options.work_dir) / ("readers_" + std::to_string(seed))).string();
}

}  // namespace

std::vector<BaseLog> make_base_logs(const std::string& dir) {
  std::vector<BaseLog> bases;
  for (const bool failing : {false, true}) {
    BaseLog b;
    b.name = failing ? "log_fuzz_faults_failing" : "log_fuzz_passing";
    const fs::path run_dir = fs::path(dir) / b.name;
    fs::create_directories(run_dir);
    const std::string file = (fs::path(dir) / (b.name + ".yaml")).string();
    std::ofstream(file) << scenario_text(b.name, failing);
    rig::RunOptions options;
    options.scenario_file = file;
    options.run_dir = run_dir.string();
    options.in_process = true;
    options.quiet = true;
    const rig::RunResult run = rig::run_scenario(options);
    if (run.passed == failing)
      throw std::runtime_error(b.name + ": the run " + (run.passed ? "passed" : "failed") + ", it should not:\n" + run.report);
    b.passes = run.passed;
    b.path = run.log_file;
    b.records = read_records(b.path);
    b.bytes = static_cast<int64_t>(fs::file_size(b.path));
    for (const logger::LogRecord& r : b.records.records)
      if (const std::string wrong = check_field_map(r); !wrong.empty())
        throw std::runtime_error("the log fuzz's field map is out of date with lcmtypes/ (tests/fuzz/log_mutation.cpp): " +
                                 wrong);
    // The readers' own view of the unmutated log: what the mutants are measured against.
    if (const std::string d = logger::compare_run_logs(b.path, b.path); !d.empty())
      throw std::runtime_error(b.name + ": compares different with itself: " + d);
    std::ostringstream out;
    if (cnc_node::rerun(b.path, out) != 0) throw std::runtime_error(b.name + ": does not rerun identical: " + out.str());
    bases.push_back(std::move(b));
  }
  return bases;
}

Mutant mutant_of(const std::vector<BaseLog>& bases, uint64_t seed, std::string* base_name) {
  Rng rng(seed);
  const BaseLog& base = base_of(bases, rng);
  if (base_name) *base_name = base.name;
  return mutate(base.records, rng);
}

MutantResult run_mutant_here(const std::vector<BaseLog>& bases, uint64_t seed, const LogFuzzOptions& options) {
  Mutant m;
  const BaseLog* base = nullptr;
  std::string path;
  MutantResult r = prepare(bases, seed, options, m, base, path);
  const auto start = std::chrono::steady_clock::now();
  const Outcome o = read_everywhere(*base, m, path, scratch_dir(options, seed), options.rerun);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.verdict = o.verdict;
  r.failures = o.failures;
  if (r.failures.empty()) fs::remove(path);
  return r;
}

MutantResult run_mutant(const std::vector<BaseLog>& bases, uint64_t seed, const LogFuzzOptions& options) {
  Mutant m;
  const BaseLog* base = nullptr;
  std::string path;
  MutantResult r = prepare(bases, seed, options, m, base, path);
  const std::string scratch = scratch_dir(options, seed);
  std::fflush(stdout);
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    close(fds[0]);
    // Bounded memory: what the fuzz has mapped, and this much more. A
    // reader that trusts a length dies of std::bad_alloc (reported) rather
    // than taking the machine's memory.
    const rlim_t limit = static_cast<rlim_t>(address_space_bytes() + options.memory_limit_mb * 1024 * 1024);
    const rlimit as{limit, limit};
    setrlimit(RLIMIT_AS, &as);
    // CPU time, not wall time (as the channel fuzz): a loaded machine is no hang.
    itimerval cpu{};
    cpu.it_value.tv_sec = static_cast<time_t>(options.cpu_limit_s);
    setitimer(ITIMER_PROF, &cpu, nullptr);
    const std::string out = serialise(read_everywhere(*base, m, path, scratch, options.rerun));
    for (size_t done = 0; done < out.size();) {
      const ssize_t n = write(fds[1], out.data() + done, out.size() - done);
      if (n <= 0) _exit(3);
      done += static_cast<size_t>(n);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string in;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    in.append(buf, static_cast<size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  rusage usage{};
  while (wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_rss_kb = usage.ru_maxrss;
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    r.failures.push_back(std::string("died of signal ") + std::to_string(sig) + " (" + strsignal(sig) + ")" +
                         (sig == SIGPROF ? ": no end within " + std::to_string(options.cpu_limit_s) + " s of CPU time" : ""));
  } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    r.failures.push_back("the readers' process ended without a result");
  } else {
    std::istringstream lines(in);
    std::getline(lines, r.verdict);
    for (std::string line; std::getline(lines, line);) r.failures.push_back(line);
  }
  std::error_code ec;
  fs::remove_all(scratch, ec);
  if (r.failures.empty()) fs::remove(path, ec);  // a failing mutant stays, to be tried by hand
  return r;
}

}  // namespace hil::fuzz
