#include "run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>

#include "config_error.hpp"
#include "live_spy.hpp"
#include "scenario_files.hpp"
#include "scenario_set.hpp"
#include "suite_page.hpp"
#include "suite_progress.hpp"
#include "suite_results.hpp"
#include "suite_run.hpp"
#include "suite_selection.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

std::string suite_name(const SuiteCommand& command) {
  std::string name = "hil run";
  for (const std::string& p : command.paths) name += " " + p;
  return command.shard.empty() ? name : name + " --shard " + command.shard;
}

void write_results(const SuiteCommand& command, const SuiteResult& suite) {
  if (!command.junit_file.empty()) write_junit(suite, suite_name(command), command.junit_file);
  if (!command.json_file.empty()) write_json(suite, suite_name(command), command.json_file);
}

// On a terminal, "running FILE, 0:12" rewritten every second while one
// scenario runs (a long one would otherwise say nothing until its report).
class ElapsedLine {
 public:
  explicit ElapsedLine(const std::string& file) {
    if (::isatty(STDOUT_FILENO) != 1) return;
    thread_ = std::thread([this, file] {
      const auto start = std::chrono::steady_clock::now();
      std::unique_lock<std::mutex> lock(mutex_);
      do {
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << "\rrunning " << file << ", " << format_elapsed(s) << std::flush;
      } while (!done_.wait_for(lock, std::chrono::seconds(1), [this] { return finished_; }));
      std::cout << "\r\033[K" << std::flush;
    });
  }
  ~ElapsedLine() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      finished_ = true;
    }
    done_.notify_one();
    thread_.join();
  }

 private:
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable done_;
  bool finished_ = false;
};

// --spy: lcm-spy listening on the run's URL before the run starts, the run paced.
std::unique_ptr<LiveSpy> start_spy(RunOptions& run) {
  if (run.in_process) throw ConfigError("--spy watches the run on LCM: not with --in-process");
  const ScenarioSet set = load_valid_scenario_set(run);  // a refused file leaves no window open
  if (run.pace <= 0) run.pace = 1;
  if (run.port <= 0) run.port = rig_port(run);
  if (run.run_dir.empty()) run.run_dir = default_run_dir(set.name);
  fs::create_directories(run.run_dir);
  const std::string url = rig_url(run.port);
  const std::string output = (fs::path(run.run_dir) / "lcm-spy.out").string();
  std::cout << "lcm-spy on " << url << ": waiting until it listens\n" << std::flush;
  auto spy = std::make_unique<LiveSpy>(run.bin_dir, url, run.port, output);
  std::cout << "lcm-spy listens; the run goes at " << run.pace << " x real time\n" << std::flush;
  return spy;
}

// One file: in this process, its whole report on stdout.
int run_single(const SuiteCommand& command, RunOptions run) {
  run.scenario_file = command.paths.front();
  std::unique_ptr<LiveSpy> spy = command.spy ? start_spy(run) : nullptr;
  RunResult result;
  const std::time_t started = std::time(nullptr);
  try {
    ElapsedLine elapsed(run.scenario_file);
    result = run_scenario(run);
  } catch (const ConfigError& e) {
    // Refused before it ran (exit status 2): CI still gets a result file that says why.
    SuiteResult refused;
    refused.started = started;
    refused.runs.push_back({run.scenario_file, "", {}, Outcome::error, 0, 0, e.what(), ""});
    write_results(command, refused);
    throw;
  }
  std::cout << result.report;
  if (spy) {
    std::cout << "close lcm-spy to end\n" << std::flush;
    spy->wait_closed();
  }
  if (!command.junit_file.empty() || !command.json_file.empty()) {
    SuiteResult suite;
    suite.started = started;
    suite.out_dir = result.run_dir;
    suite.wall_s = result.wall_s;
    suite.runs.push_back(read_run_summary((fs::path(result.run_dir) / "summary.yaml").string()));
    write_results(command, suite);
  }
  return result.passed ? 0 : 1;
}

}  // namespace

int run_scenarios(const SuiteCommand& command, const RunOptions& run) {
  std::error_code ec;
  const bool selecting = !command.patterns.empty() || command.last_failed || command.list;
  const bool single = command.paths.size() == 1 && command.shard.empty() && !selecting &&
                      !fs::is_directory(command.paths[0], ec);
  if (single) return run_single(command, run);
  if (command.spy) throw ConfigError("--spy watches one run: give one scenario file");

  SuiteOptions options;
  options.files = collect_scenario_files(command.paths);
  if (!command.shard.empty()) options.files = shard_of(options.files, parse_shard(command.shard));
  options.files = matching(options.files, command.patterns);
  if (command.last_failed) {
    std::string note;
    options.files = last_failed(options.files, note);
    if (!note.empty()) std::cout << note << '\n';
  }
  if (command.list) {
    std::cout << list_scenarios(options.files);
    return 0;
  }
  options.jobs = command.jobs;
  options.exit_first = command.exit_first;
  options.netns = command.netns;
  options.run = run;
  options.out_dir = run.run_dir.empty() ? default_run_dir("suite") : run.run_dir;
  fs::create_directories(options.out_dir);

  std::cout << suite_name(command) << ": " << options.files.size() << " scenario(s), " << command.jobs
            << " at a time, " << (run.in_process ? "in-process" : command.netns ? "processes, a network namespace each"
                                                                                 : "processes, a udpm port each")
            << ", run folders below " << options.out_dir << '\n'
            << std::flush;
  SuiteProgress progress(std::cout, options.files.size(), ::isatty(STDOUT_FILENO) == 1);
  const SuiteResult suite = run_suite(options, {[&](const std::string& file) { progress.started(file); },
                                                [&](const RunSummary& r) { progress.finished(r); },
                                                [&] { progress.waiting(); }});
  progress.close();
  const std::string table = format_summary_table(suite);
  std::cout << '\n' << table;
  std::ofstream(fs::path(options.out_dir) / "summary.txt") << table;
  write_suite_page(suite, suite_name(command));
  write_results(command, suite);
  record_failures(suite);
  return suite.passed() ? 0 : 1;
}

}  // namespace hil::rig
