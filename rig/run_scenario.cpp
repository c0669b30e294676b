#include "run_scenario.hpp"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <thread>

#include "config_error.hpp"
#include "drive_model.hpp"
#include "in_process_run.hpp"
#include "node_errors.hpp"
#include "participant.hpp"
#include "plots.hpp"
#include "process.hpp"
#include "program_check.hpp"
#include "report.hpp"
#include "root_cause.hpp"
#include "run_identity.hpp"
#include "run_secret.hpp"
#include "run_log.hpp"
#include "run_page.hpp"
#include "run_summary.hpp"
#include "scenario.hpp"
#include "scenario_engine.hpp"
#include "scenario_set.hpp"
#include "variant_comparison.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

// The scenario as run, for every node: scenario.yaml with the machine inline
// and the NC program beside it in program.nc. A program of a million lines
// inline would cost every node seconds of YAML parsing; as a file it is read.
std::string write_resolved(const Scenario& scenario, const fs::path& dir) {
  YAML::Node root = YAML::Clone(scenario.resolved);
  root.remove("nc_program");
  root["nc_file"] = "program.nc";
  YAML::Emitter yaml;
  yaml << root;
  const fs::path file = dir / "scenario.yaml";
  std::ofstream(file) << yaml.c_str() << '\n';
  std::ofstream(dir / "program.nc", std::ios::binary) << scenario.nc_program;
  return file.string();
}

}  // namespace

std::string default_run_dir(const std::string& name) {
  const std::time_t now = std::time(nullptr);
  char time[32];
  std::strftime(time, sizeof time, "%Y%m%d-%H%M%S", std::localtime(&now));
  return "runs/" + name + "-" + time;
}

int rig_port(const RunOptions& options) {
  return options.port > 0 ? options.port : 20000 + static_cast<int>(::getpid() % 20000);
}

std::string rig_url(int port) {
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0&recv_buf_size=4194304";
}

namespace {

// Refuses, before anything starts, unknown HLI fields and drive models that
// would not be stable.
void validate(const Scenario& scenario) {
  plc::ScenarioEngine validate_timeline(scenario);
  for (const AxisConfig& axis : scenario.machine.axes) {
    try {
      axis::DriveModel(axis::drive_parameters(axis, scenario.machine.cycle_time_s()));
    } catch (const std::invalid_argument& e) {
      throw ConfigError("machine: axis " + axis.name + ": " + e.what());
    }
  }
}


// Every node a process of its own on a private udpm port; returns their
// exit statuses and says them in `processes`, and how the lock-step nodes
// (cnc, drives, PLC) were placed in `placed`. They share CPU `cpu` if it is
// >= 0: lock-step is a chain (the CNC waits for the drives, the drives for
// the CNC), so they gain little from running side by side, and a wake-up
// across CPUs is an inter-processor interrupt — in a VM an exit to the
// hypervisor. They run under SCHED_FIFO at one priority where the system
// allows: a message then does not preempt its sender, so the CNC sends a
// cycle's messages, then each receiver runs once and the CNC once more (5
// context switches a cycle for 3 axes instead of 8). The logger, which
// reads in batches, runs where and as the system puts it
// (docs/PERFORMANCE.md).
std::vector<logger::ProcessExit> run_processes(const Scenario& scenario, const fs::path& dir, const std::string& resolved,
                                               const std::string& log_file, const RunOptions& options,
                                               const std::string& run_id, int cpu, std::ostringstream& processes,
                                               std::string& placed) {
  const std::string url = rig_url(rig_port(options));
  const fs::path bin = options.bin_dir;
  // RIG-12: the run's secret, handed to each node outside the bus.
  const std::string key_file = (dir / "run.key").string();
  fs::remove(key_file);
  lcm_support::RunSecret::generate().write(key_file);
  auto node_output = [&](const std::string& name) { return node_output_file(dir.string(), name); };
  auto node_args = [&](const std::string& exe) {
    return std::vector<std::string>{(bin / exe).string(), "--scenario", resolved, "--url",      url,
                                    "--run-id",          run_id,  "--key-file", key_file};
  };

  // The logger is told every participant: it records until each has ended,
  // whenever it came up itself.
  std::vector<std::string> logger_args = {(bin / "hil_logger").string(), "--url", url, "--out", log_file,
                                          "--run-id", run_id, "--key-file", key_file, "--scenario", resolved,
                                          "--participants", "cnc",
                                          "plc_sim"};
  for (const AxisConfig& axis : scenario.machine.axes) logger_args.push_back("axis_sim " + axis.name);

  const auto wall_start = std::chrono::steady_clock::now();
  auto wall_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count(); };
  // Real time runs 10 above --fifo-priority (default 20): a lock-step run
  // beside it under SCHED_FIFO (its nodes as busy as they can be) must not
  // hold off its ticks (RIG-6, docs/REALTIME.md). Lock-step runs under
  // normal scheduling unless asked: a SCHED_FIFO chain that is always busy
  // starves every other process on its CPU (a tool that injects traffic,
  // another test), and gained steadiness, not speed (docs/PERFORMANCE.md).
  const int priority = scenario.realtime ? std::min(std::max(options.fifo_priority, 10) + 10, 99) : options.fifo_priority;
  const Placement lock_step{cpu, priority};
  std::vector<std::unique_ptr<Process>> nodes;
  nodes.push_back(std::make_unique<Process>("logger", logger_args, node_output("logger")));
  for (const AxisConfig& axis : scenario.machine.axes) {
    std::vector<std::string> args = node_args("axis_sim");
    args.insert(args.end(), {"--axis", axis.name});
    nodes.push_back(
        std::make_unique<Process>("axis_sim " + axis.name, args, node_output("axis_sim " + axis.name), lock_step));
  }
  nodes.push_back(std::make_unique<Process>("plc_sim", node_args("plc_sim"), node_output("plc_sim"), lock_step));
  std::vector<std::string> cnc_args = node_args("cnc");
  if (options.answer_timeout_ms > 0) cnc_args.insert(cnc_args.end(), {"--answer-timeout-ms", std::to_string(options.answer_timeout_ms)});
  if (options.pace > 0) cnc_args.insert(cnc_args.end(), {"--pace", std::to_string(options.pace)});
  Process cnc("cnc", cnc_args, node_output("cnc"), lock_step);
  placed = cpu >= 0 ? std::string(scenario.realtime ? ", the cycle nodes on CPU " : ", the lock-step nodes on CPU ") +
                          std::to_string(cpu)
                    : "";
  if (priority > 0)
    placed += cnc.fifo_refused().empty() ? ", SCHED_FIFO " + std::to_string(priority)
                                         : ", normal scheduling (SCHED_FIFO refused: " + cnc.fifo_refused() + ")";

  // Lock-step runs faster than real time; this bound only catches a hang.
  // A node that fails while the CNC runs is noted with the time (a node
  // exits 0 only after the CNC's RUN_END).
  const double wall_limit_s = 60 + 20 * scenario.max_time_s;
  std::vector<std::optional<double>> exited_during_run(nodes.size());
  std::optional<int> cnc_status;
  while (!(cnc_status = cnc.poll()) && wall_s() < wall_limit_s) {
    for (size_t i = 0; i < nodes.size(); ++i)
      if (const auto status = nodes[i]->poll(); status && *status != 0 && !exited_during_run[i])
        exited_during_run[i] = wall_s();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::vector<logger::ProcessExit> exits{{"cnc", cnc_status}};
  processes << "cnc " << (cnc_status ? std::to_string(*cnc_status) : "hung, killed: " + std::to_string(cnc.stop()));
  // The nodes end on their own: soon after the CNC's RUN_END, or cnc_silence
  // after a CNC that died. One deadline for all: 10 s for each in turn left
  // axis_sim X, waited for right after the logger, no margin (issue 33).
  const auto nodes_deadline =
      std::chrono::steady_clock::now() + lcm_support::cnc_silence + std::chrono::seconds(5);
  for (size_t i = 0; i < nodes.size(); ++i) {
    Process& node = *nodes[i];
    const std::optional<int> status = node.wait_for(std::chrono::duration_cast<std::chrono::milliseconds>(
        std::max(nodes_deadline - std::chrono::steady_clock::now(), std::chrono::steady_clock::duration::zero())));
    exits.push_back({node.name(), status});
    processes << ", " << node.name() << ' ' << (status ? std::to_string(*status) : "hung, killed");
    if (!status) node.stop();
    if (exited_during_run[i])
      processes << " (" << std::fixed << std::setprecision(1) << *exited_during_run[i]
                << " s into the run, while the cnc ran)" << std::defaultfloat;
  }
  return exits;
}

// What the summary table and JUnit show of a failed run: the root cause,
// else the first failed expectation, else the first reason.
std::string first_failure(const logger::RunLog& log, const logger::RunVerdict& verdict,
                          const std::vector<std::string>& causes) {
  if (verdict.passed) return "";
  if (!causes.empty()) return causes.front();
  for (const logger::LoggedEvent& e : log.events)
    if (e.event.verdict == Verdict::fail) return e.source + ": " + e.event.message;
  return verdict.reasons.empty() ? "" : verdict.reasons.front();
}

// One run of the rig in `run_dir`; `figures` (if given) gets the run's
// figures for the comparison of variants.
RunResult run_one(const Scenario& scenario, const std::string& run_dir, const RunOptions& options,
                  const std::string& variant, VariantFigures* figures) {
  RunResult result;
  result.run_dir = run_dir;
  fs::create_directories(result.run_dir);
  const fs::path dir = fs::absolute(result.run_dir);
  const std::string resolved = write_resolved(scenario, dir);
  result.log_file = (dir / "run.lcmlog").string();
  fs::remove(result.log_file);

  const std::string run_id = std::to_string(new_run_id());
  const auto wall_start = std::chrono::steady_clock::now();
  auto wall_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count(); };
  std::vector<logger::ProcessExit> exits;
  std::ostringstream processes;
  std::string where;
  if (options.in_process) {
    where = "in-process (every node in the hil process, no network)";
    exits = run_in_process(resolved, result.log_file, (dir / "nodes.out").string(), std::stoll(run_id), options.pace);
    for (const logger::ProcessExit& e : exits)
      processes << (e.name == "cnc" ? "" : ", ") << e.name << ' ' << (e.status ? std::to_string(*e.status) : "?");
  } else {
    const int cpu = options.cpu == -2 ? ::sched_getcpu() : options.cpu;
    std::string placed;
    exits = run_processes(scenario, dir, resolved, result.log_file, options, run_id, cpu, processes, placed);
    where = "LCM: " + rig_url(rig_port(options)) + placed;
    if (scenario.realtime)
      where += ", real time (" + std::to_string(scenario.machine.cycle_time_us) + " us ticks)";
  }
  const double run_wall_s = wall_s();
  result.wall_s = run_wall_s;
  // A participant the scenario kills (RIG-8) ends with SIGKILL on purpose.
  std::vector<logger::ProcessExit> unplanned;
  for (const logger::ProcessExit& e : exits)
    if (!(e.status == 128 + 9 && scenario.faults.kill_cycle(e.name))) unplanned.push_back(e);
  const NodeErrors node_errors = find_node_errors(unplanned, dir.string(), options.in_process);

  std::optional<logger::CheckReport> check;
  logger::RunLog log;
  try {
    log = logger::read_run_log(result.log_file, &check);
  } catch (const std::exception& e) {
    // Nothing recorded (a node that could not start): say why, in report.txt as well.
    const logger::RunVerdict verdict = logger::judge_run(exits, log.facts, std::string("no log: ") + e.what());
    std::ostringstream out;
    out << "scenario " << scenario.name << ": FAILED\n";
    for (const std::string& reason : verdict.reasons) out << "  because " << reason << '\n';
    out << node_errors.text() << "run folder: " << result.run_dir << '\n' << where << ", run id " << run_id << '\n'
        << "exit status: " << processes.str() << '\n';
    result.report = out.str();
    result.recorded = false;
    result.first_failure = !node_errors.nodes.empty() ? node_errors.first()
                           : verdict.reasons.empty()  ? e.what()
                                                      : verdict.reasons.front();
    std::ofstream(dir / "report.txt") << result.report;
    write_run_page(scenario, result, verdict, log, nullptr, {{}, "the run left no log"});
    if (figures) *figures = figures_of(variant, false, log, nullptr);
    return result;
  }
  // Violations the scenario provokes on purpose must be found; no other may be.
  std::string check_failure = check ? "" : "no scenario in the log, so no limits to check against";
  std::ostringstream violations_expected;
  if (check) {
    int unexpected = 0;
    for (const auto& v : check->violations) {
      bool expected = false;
      for (const auto& e : scenario.expected_violations) expected = expected || e.matches(v.axis, v.quantity);
      unexpected += expected ? 0 : 1;
    }
    if (unexpected > 0) check_failure = std::to_string(unexpected) + " limit violation(s) the scenario does not expect";
    for (const auto& e : scenario.expected_violations) {
      bool found = false;
      for (const auto& v : check->violations) found = found || e.matches(v.axis, v.quantity);
      if (!found && check_failure.empty()) check_failure = "an expected violation was not found";
      violations_expected << "expected violation: axis " << e.axis << " " << e.quantity << ": "
                          << (found ? "found" : "NOT FOUND") << '\n';
    }
  }
  logger::RunVerdict verdict = logger::judge_run(exits, log.facts, check_failure);
  result.passed = verdict.passed;
  result.simulated_s = (log.last_cycle + 1) * scenario.machine.cycle_time_s();
  const std::vector<std::string> causes =
      verdict.passed ? std::vector<std::string>{} : root_causes(scenario, log, node_errors, check ? &*check : nullptr);
  result.first_failure = first_failure(log, verdict, causes);
  verdict.reasons.insert(verdict.reasons.begin(), causes.begin(), causes.end());

  std::ostringstream out;
  const double simulated_s = result.simulated_s;
  int64_t messages = 0;
  for (const auto& entry : log.messages_per_channel) messages += entry.second;
  out << "scenario " << scenario.name;
  if (!scenario.requirements.empty()) {
    out << " (";
    for (size_t i = 0; i < scenario.requirements.size(); ++i) out << (i ? " " : "") << scenario.requirements[i];
    out << ")";
  }
  out << ": " << (result.passed ? "PASSED" : "FAILED") << '\n';
  for (const std::string& reason : verdict.reasons) out << "  because " << reason << '\n';
  out << node_errors.text();
  const std::vector<std::string> problems = logger::log_problems(log.facts);
  out << "run folder: " << result.run_dir << '\n'
      << where << ", run id " << run_id << '\n'
      << "log: " << result.log_file << " (" << messages << " messages, " << log.last_cycle + 1 << " cycles = "
      << simulated_s << " s simulated in " << run_wall_s << " s wall, " << simulated_s / run_wall_s
      << " x real time)\n"
      << "log complete: "
      << (!problems.empty() ? "NO (" + std::to_string(problems.size()) + " problems above)"
          : log.facts.realtime
              ? "yes (every participant ended, every cycle of the cnc's output, its statistics, closed by the logger)"
              : "yes (every participant ended, every cycle on every lock-step channel, closed by the logger)")
      << '\n'
      << "exit status: " << processes.str() << '\n'
      << "refused traffic: " << logger::describe_refused(log.facts) << '\n'
      << describe_expectation_counts(log.facts) << '\n';
  if (log.facts.realtime) out << format_real_time(log);
  PagePlots plots{{}, "the log has no scenario (HIL_SCENARIO): nothing names the axes and limits"};
  if (check) plots.note = draw_plots(log, *check, (dir / "plots").string(), &plots.images);
  if (check) out << format_check(log, *check) << violations_expected.str() << plots.note << '\n';
  else out << "offline check: the log has no scenario (HIL_SCENARIO)\n";
  result.report = out.str();
  std::ofstream(dir / "report.txt") << result.report;
  write_run_page(scenario, result, verdict, log, check ? &*check : nullptr, plots);
  if (figures) *figures = figures_of(variant, result.passed, log, check ? &*check : nullptr);
  return result;
}

// Each variant in a folder of its own, one after the other on the same port.
RunResult run_variants(const ScenarioSet& set, const std::string& run_dir, const RunOptions& options) {
  RunResult result;
  result.run_dir = run_dir;
  result.passed = true;
  std::vector<VariantFigures> figures;
  std::ostringstream runs;
  for (const ScenarioVariant& v : set.variants) {
    figures.emplace_back();
    const RunResult one = run_one(v.scenario, (fs::path(run_dir) / v.name).string(), options, v.name, &figures.back());
    result.passed = result.passed && one.passed;
    result.recorded = result.recorded && one.recorded;
    result.simulated_s += one.simulated_s;
    result.wall_s += one.wall_s;
    if (result.first_failure.empty() && !one.first_failure.empty())
      result.first_failure = "variant " + v.name + ": " + one.first_failure;
    if (result.log_file.empty()) result.log_file = one.log_file;
    runs << "=== variant " << v.name << " ===\n" << one.report << '\n';
  }
  bool comparisons_hold = true;
  const std::string checks = check_comparisons(figures, set.comparisons, comparisons_hold);
  result.passed = result.passed && comparisons_hold;
  if (result.first_failure.empty() && !comparisons_hold) result.first_failure = "a comparison of the variants fails";
  PagePlots plots;
  plots.note = draw_comparison_plots(set.name, figures, set.comparisons, run_dir, &plots.images);
  std::ostringstream out;
  out << "scenario " << set.name << " (" << set.variants.size() << " variants): " << (result.passed ? "PASSED" : "FAILED")
      << '\n';
  for (const VariantFigures& f : figures)
    if (!f.passed) out << "  because variant " << f.name << " failed\n";
  if (!comparisons_hold) out << "  because a comparison of the variants fails\n";
  out << "run folder: " << run_dir << " (a folder per variant)\n\n" << runs.str() << "=== the variants side by side ===\n"
      << format_variants(figures) << checks
      << plots.note << '\n'
      << "scenario " << set.name << ": " << (result.passed ? "PASSED" : "FAILED") << '\n';
  result.report = out.str();
  std::ofstream(fs::path(run_dir) / "report.txt") << result.report;
  write_set_page(set, result, figures, checks, plots);
  return result;
}

RunSummary summary_of(const std::string& scenario_file, const ScenarioSet& set, const RunResult& result) {
  RunSummary s;
  s.scenario_file = scenario_file;
  s.name = set.name;
  s.requirements = set.variants.front().scenario.requirements;
  s.outcome = result.passed ? Outcome::passed : result.recorded ? Outcome::failed : Outcome::error;
  s.simulated_s = result.simulated_s;
  s.wall_s = result.wall_s;
  s.first_failure = result.first_failure;
  s.run_dir = result.run_dir;
  return s;
}

}  // namespace

ScenarioSet load_valid_scenario_set(const RunOptions& options) {
  ScenarioSet set = load_scenario_set(options.scenario_file);
  for (ScenarioVariant& v : set.variants) {
    // --realtime goes into the scenario every node reads (RIG-6).
    if (options.realtime) {
      v.scenario.realtime = true;
      v.scenario.resolved["run"]["realtime"] = true;
    }
    if (v.scenario.realtime && options.pace > 0)
      throw ConfigError(options.scenario_file + ": --pace is for lock-step; a real-time run (" +
                        (options.realtime ? std::string("--realtime") : std::string("run.realtime")) +
                        ") ticks at the machine's cycle time already");
    // One thread cannot give each node its own wake-ups on the wall clock.
    if (v.scenario.realtime && options.in_process)
      throw ConfigError(options.scenario_file + ": --in-process runs in lock-step only; real-time mode (" +
                        (options.realtime ? std::string("--realtime") : std::string("run.realtime")) +
                        ") needs the processes (docs/REALTIME.md)");
    try {
      validate(v.scenario);
      check_nc_program(v.scenario);
    } catch (const ConfigError& e) {
      throw ConfigError(options.scenario_file + ": " + e.what() + (v.name.empty() ? "" : " (variant " + v.name + ")"));
    }
  }
  return set;
}

RunResult run_scenario(const RunOptions& options) {
  ScenarioSet set = load_valid_scenario_set(options);
  const std::string run_dir = options.run_dir.empty() ? default_run_dir(set.name) : options.run_dir;
  RunResult result = set.has_variants() ? run_variants(set, run_dir, options)
                                        : run_one(set.variants.front().scenario, run_dir, options, "", nullptr);
  write_run_summary(summary_of(options.scenario_file, set, result), (fs::path(run_dir) / "summary.yaml").string());
  return result;
}

}  // namespace hil::rig
