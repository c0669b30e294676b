#include "suite_run.hpp"

#include <unistd.h>

#include <chrono>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "config_error.hpp"
#include "process.hpp"
#include "scenario_set.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

// Loopback with a multicast route in a namespace of its own, as
// scripts/in_netns.sh: the run's traffic stays in it.
const std::vector<std::string> netns_prefix = {
    "unshare", "-n", "sh", "-c",
    "ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo && exec \"$@\"", "hil-netns"};

struct Pending {
  size_t index;  // in the suite's order
  bool realtime;
};

struct Running {
  size_t index;
  int slot;  // its port and CPU
  bool realtime;
  std::chrono::steady_clock::time_point start;
  std::unique_ptr<Process> process;
};


}  // namespace

bool SuiteResult::passed() const {
  for (const RunSummary& r : runs)
    if (r.outcome == Outcome::failed || r.outcome == Outcome::error) return false;
  return true;
}

std::string run_dir_of(const std::string& suite_dir, const std::string& scenario_file) {
  fs::path rel = fs::path(scenario_file).lexically_normal();
  if (rel.is_absolute() || *rel.begin() == "..") {
    rel = fs::absolute(rel).lexically_normal().relative_path();
  }
  return (fs::path(suite_dir) / rel.replace_extension()).string();
}

SuiteResult run_suite(const SuiteOptions& options, const SuiteListener& listener) {
  if (options.netns && ::geteuid() != 0)
    throw ConfigError("--netns: a network namespace needs root (without it, each run has a udpm port of its own)");
  const auto suite_start = std::chrono::steady_clock::now();
  auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  SuiteResult result;
  result.started = std::time(nullptr);
  result.out_dir = options.out_dir;
  result.runs.resize(options.files.size());

  // What cannot run is known before anything starts: a file the loader
  // refuses is an ERROR, a real-time scenario in an in-process suite SKIPPED.
  std::deque<Pending> pending;
  bool failure_seen = false;  // for -x
  for (size_t i = 0; i < options.files.size(); ++i) {
    RunSummary& s = result.runs[i];
    s.scenario_file = options.files[i];
    s.run_dir = run_dir_of(options.out_dir, options.files[i]);
    bool realtime = options.run.realtime;
    try {
      const ScenarioSet set = load_scenario_set(options.files[i]);
      s.name = set.name;
      s.requirements = set.variants.front().scenario.requirements;
      for (const ScenarioVariant& v : set.variants) realtime = realtime || v.scenario.realtime;
    } catch (const std::exception& e) {
      s.outcome = Outcome::error;
      s.first_failure = e.what();
      failure_seen = true;
      if (listener.finished) listener.finished(s);
      continue;
    }
    if (realtime && options.run.in_process) {
      s.outcome = Outcome::skipped;
      s.first_failure = "real-time mode needs the processes, the suite runs --in-process";
      if (listener.finished) listener.finished(s);
      continue;
    }
    pending.push_back({i, realtime});
  }

  const int jobs = std::max(1, options.jobs);
  const int base_port = options.run.port > 0 ? options.run.port : 20000 + static_cast<int>(::getpid() % 20000);
  const long cpus = std::max(1L, ::sysconf(_SC_NPROCESSORS_ONLN));
  const std::string self = (fs::path(options.run.bin_dir) / "hil").string();
  std::vector<Running> running;
  std::vector<bool> slot_busy(static_cast<size_t>(jobs), false);

  auto start = [&](const Pending& p) {
    const int slot = static_cast<int>(std::find(slot_busy.begin(), slot_busy.end(), false) - slot_busy.begin());
    slot_busy[static_cast<size_t>(slot)] = true;
    RunSummary& s = result.runs[p.index];
    fs::create_directories(s.run_dir);
    fs::remove(fs::path(s.run_dir) / "summary.yaml");
    std::vector<std::string> args = options.netns ? netns_prefix : std::vector<std::string>{};
    args.insert(args.end(), {self, "run", s.scenario_file, "--out", s.run_dir, "--bin-dir", options.run.bin_dir,
                             "--port", std::to_string(base_port + slot)});
    if (options.run.in_process) args.push_back("--in-process");
    if (options.run.realtime) args.push_back("--realtime");
    if (options.run.pace > 0) args.insert(args.end(), {"--pace", std::to_string(options.run.pace)});
    // Runs side by side each get a CPU of their own for their lock-step chain.
    const int cpu = options.run.cpu != -2 ? options.run.cpu : jobs > 1 ? static_cast<int>(slot % cpus) : -2;
    if (cpu != -2) args.insert(args.end(), {"--cpu", std::to_string(cpu)});
    if (options.run.fifo_priority > 0) args.insert(args.end(), {"--fifo-priority", std::to_string(options.run.fifo_priority)});
    if (options.run.answer_timeout_ms > 0)
      args.insert(args.end(), {"--answer-timeout-ms", std::to_string(options.run.answer_timeout_ms)});
    if (listener.started) listener.started(s.scenario_file);
    running.push_back({p.index, slot, p.realtime, std::chrono::steady_clock::now(),
                       std::make_unique<Process>(s.scenario_file, args, (fs::path(s.run_dir) / "hil.out").string())});
  };

  auto finish = [&](Running& r, int status) {
    slot_busy[static_cast<size_t>(r.slot)] = false;
    RunSummary& s = result.runs[r.index];
    const std::string output = (fs::path(s.run_dir) / "hil.out").string();
    try {
      RunSummary child = read_run_summary((fs::path(s.run_dir) / "summary.yaml").string());
      child.scenario_file = s.scenario_file;  // as the suite names it
      s = child;
    } catch (const std::exception&) {
      // No summary: the run did not get as far (exit 2: refused; or a crash).
      s.outcome = Outcome::error;
      s.wall_s = seconds_since(r.start);
      const std::string said = last_line_of(output);
      s.first_failure = "hil run exited with status " + std::to_string(status) + (said.empty() ? "" : ": " + said);
    }
    failure_seen = failure_seen || s.outcome == Outcome::failed || s.outcome == Outcome::error;
    if (listener.finished) listener.finished(s);
  };

  // A real-time run has the machine to itself: its ticks are on the wall clock.
  while (!pending.empty() || !running.empty()) {
    if (options.exit_first && failure_seen) {
      for (const Pending& p : pending) {
        RunSummary& s = result.runs[p.index];
        s.outcome = Outcome::skipped;
        s.first_failure = "not run: -x stops the suite at its first failure";
        if (listener.finished) listener.finished(s);
      }
      pending.clear();
    }
    const bool exclusive = !running.empty() && running.front().realtime;
    while (!pending.empty() && !exclusive && static_cast<int>(running.size()) < jobs &&
           (!pending.front().realtime || running.empty())) {
      start(pending.front());
      pending.pop_front();
      if (running.back().realtime) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (listener.waiting) listener.waiting();
    for (auto it = running.begin(); it != running.end();) {
      if (const std::optional<int> status = it->process->poll()) {
        finish(*it, *status);
        it = running.erase(it);
      } else {
        ++it;
      }
    }
  }
  result.wall_s = seconds_since(suite_start);
  return result;
}

}  // namespace hil::rig
