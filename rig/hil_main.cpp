// The `hil` command: run scenarios through the whole rig, check and compare logs.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "command_line.hpp"
#include "config_error.hpp"
#include "export_command.hpp"
#include "golden_command.hpp"
#include "file_schema.hpp"
#include "plots.hpp"
#include "report.hpp"
#include "root_cause.hpp"
#include "program_check.hpp"
#include "run_log.hpp"
#include "run_command.hpp"
#include "run_scenario.hpp"
#include "tools.hpp"

namespace {

std::string own_directory() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string(".") : exe.parent_path().string();
}

// The part of the verdict a log shows on its own (RIG-4, RIG-9): the limits,
// and that it holds the whole run.
int check_log(const std::string& path, const std::string& plot_dir) {
  std::optional<hil::logger::CheckReport> check;
  const hil::logger::RunLog log = hil::logger::read_run_log(path, &check);
  if (!check) {
    std::cerr << path << ": no scenario (HIL_SCENARIO) in the log, so no limits to check against\n";
    for (const std::string& problem : hil::logger::log_problems(log.facts)) std::cerr << "  " << problem << '\n';
    return 2;
  }
  std::cout << "log " << path << ": " << (log.scenario ? log.scenario->name : "?") << ", "
            << log.last_cycle + 1 << " cycles, run id " << log.facts.run_id << '\n'
            << (log.facts.realtime ? hil::rig::format_real_time(log) : "") << hil::rig::format_check(log, *check);
  if (!plot_dir.empty()) std::cout << hil::rig::draw_plots(log, *check, plot_dir) << '\n';
  const std::vector<std::string> problems = hil::logger::log_problems(log.facts);
  std::cout << "refused traffic: " << hil::logger::describe_refused(log.facts) << '\n'
            << hil::rig::describe_expectation_counts(log.facts) << '\n'
            << "log complete: " << (problems.empty() ? "yes" : "NO") << '\n';
  for (const std::string& problem : problems) std::cout << "  " << problem << '\n';
  const bool passed = check->passed() && problems.empty();
  std::cout << (passed ? "CHECK PASSED" : "CHECK FAILED") << '\n';
  return passed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hil: hardware-in-the-loop rig for the CNC kernel"};
  app.require_subcommand(1);

  hil::rig::RunOptions run;
  run.bin_dir = own_directory();
  hil::rig::SuiteCommand suite;
  auto* run_cmd = app.add_subcommand(
      "run", "run scenarios through the whole rig and report: one file, or files and folders as a suite (RIG-5, RIG-9)");
  // No CLI::ExistingFile: the loader refuses a missing file or a directory
  // as it refuses any bad input, naming it, with exit status 2.
  run_cmd->add_option("scenarios", suite.paths, "scenario YAML files and folders (every *.yaml below, recursively)")
      ->required();
  run_cmd->add_option("--out", run.run_dir,
                      "run folder (default runs/<name>-<time>); of a suite: a folder per scenario below it "
                      "(default runs/suite-<time>)");
  run_cmd->add_option("--jobs,-j", suite.jobs, "scenarios run at once, each on its own port and CPU (default 1)")
      ->check(CLI::Range(1, 64));
  run_cmd->add_option("--shard", suite.shard,
                      "K/N: run only the K-th of N deterministic slices of the suite (a CI matrix, an Indexed Job)");
  run_cmd->add_option("-k", suite.patterns,
                      "only the scenarios whose file path or name contains PATTERN (case ignored; 'not PATTERN' "
                      "leaves out; several -k: any of them)")
      ->type_name("PATTERN")
      ->allow_extra_args(false);
  run_cmd->add_flag("-x,--exitfirst", suite.exit_first, "stop the suite at its first FAILED or ERROR (the rest SKIPPED)");
  run_cmd->add_flag("--lf,--last-failed", suite.last_failed,
                    "only the scenarios that failed when a suite last ran them here (.hil/last-failed); all if none");
  run_cmd->add_flag("--list", suite.list, "list the scenarios that would run (after -k, --lf, --shard), run none");
  run_cmd->add_option("--junit", suite.junit_file, "write JUnit XML results (one testcase per scenario)");
  run_cmd->add_option("--json", suite.json_file, "write the results as JSON");
  run_cmd->add_flag("--netns", suite.netns,
                    "each run of a suite in a network namespace of its own, loopback multicast set up (root)");
  run_cmd->add_option("--port", run.port,
                      "udpm port of this rig (default derived from the pid); a suite's jobs use it and those above")
      ->check(CLI::Range(1024, 65535));
  run_cmd->add_option("--bin-dir", run.bin_dir, "folder of the node executables");
  run_cmd->add_option("--cpu", run.cpu,
                      "CPU of the lock-step processes (cnc, drives, PLC); default: the CPU hil starts on; -1: anywhere")
      ->check(CLI::Range(-1, 4095));
  run_cmd->add_option("--fifo-priority", run.fifo_priority,
                      "SCHED_FIFO priority of the lock-step processes, the same for all, where the system allows "
                      "it (default 0: normal scheduling); real time runs 10 above it (default 20)")
      ->check(CLI::Range(0, 99));
  run_cmd->add_option("--answer-timeout-ms", run.answer_timeout_ms,
                      "lock-step: how long the CNC waits for an answer before it asks whether the participant's "
                      "process still runs (lost if not, waited for on if it does; default 5000; docs/RELIABILITY.md)")
      ->check(CLI::Range(1, 600000));
  run_cmd->add_flag("--realtime", run.realtime,
                    "real-time mode (RIG-6): the CNC ticks on the wall clock at the machine's cycle time and never "
                    "waits for answers (as the scenario key run.realtime; docs/REALTIME.md)");
  run_cmd->add_option("--pace", run.pace,
                      "lock-step no faster than PACE x real time, to watch it (1: as the machine would run, 0.1: ten "
                      "times slower); the run and its log are the same as unpaced")
      ->check(CLI::PositiveNumber);
  run_cmd->add_flag("--spy", suite.spy,
                    "start lcm-spy on the run's URL, wait until it listens, then run paced (--pace, default 1); "
                    "one scenario, processes (docs/MONITORING.md)");
  run_cmd->add_flag("--in-process", run.in_process,
                    "every node in this process, on direct calls instead of LCM: the same messages and log, "
                    "no network (for suites)");

  std::vector<std::string> validate_files;
  auto* validate_cmd = app.add_subcommand(
      "validate", "check scenario files and their NC programs as 'hil run' would, without running them (KRN-8)");
  validate_cmd->add_option("scenarios", validate_files, "scenario YAML files")->required();

  std::string log_file;
  auto* check_cmd = app.add_subcommand("check", "check a recorded log against the limits in its manifest");
  check_cmd->add_option("log", log_file, "LCM event log")->required()->check(CLI::ExistingFile);
  std::string plot_dir;
  check_cmd->add_option("--plots", plot_dir, "also draw the PNG plots (gnuplot) into this folder");

  std::vector<std::string> pair;
  auto* compare_cmd = app.add_subcommand(
      "compare", "compare two logs message by message (determinism), or a log with a golden trace within 1e-9 mm "
                 "(docs/GOLDEN.md)");
  compare_cmd->add_option("logs", pair, "two LCM event logs or golden traces (.trace.xz)")
      ->required()
      ->expected(2)
      ->check(CLI::ExistingFile);

  std::string golden_out;
  auto* golden_cmd = app.add_subcommand(
      "golden", "write a log's golden trace: setpoints, HLI state and events, compact, for `hil compare` against a "
                "later build (docs/GOLDEN.md)");
  golden_cmd->add_option("log", log_file, "LCM event log of a rig run")->required()->check(CLI::ExistingFile);
  golden_cmd->add_option("--out", golden_out, "the trace file (.trace.xz)")->required();
  std::string golden_comment;
  golden_cmd->add_option("--comment", golden_comment, "where it came from, kept in the file (default: the log's path)");

  std::string spy_source = hil::rig::default_lcm_url;
  double speed = 1.0;
  auto* spy_cmd = app.add_subcommand("spy", "lcm-spy with every rig type decodable, live or on a log (RIG-7)");
  spy_cmd->add_option("source", spy_source, "a rig's LCM URL (hil run prints it) or a log file")
      ->capture_default_str();
  spy_cmd->add_option("--speed", speed, "playback speed of a log file (1 = the machine's pace, in simulated time)")
      ->check(CLI::PositiveNumber);

  std::string replay_url = hil::rig::default_lcm_url;
  auto* replay_cmd = app.add_subcommand("replay", "play a log onto an LCM URL with lcm-logplayer (RIG-7)");
  replay_cmd->add_option("log", log_file, "LCM event log")->required()->check(CLI::ExistingFile);
  replay_cmd->add_option("--url", replay_url, "where to play it (watch it there with hil spy URL)")
      ->capture_default_str();
  replay_cmd->add_option("--speed", speed, "1 = the machine's pace (simulated time), 2 = twice as fast")
      ->check(CLI::PositiveNumber);

  auto* logplayer_cmd = app.add_subcommand(
      "logplayer", "lcm-logplayer-gui on a log (seek, speed, channel filters), playing onto an LCM URL (RIG-7)");
  logplayer_cmd->add_option("log", log_file, "LCM event log")->required()->check(CLI::ExistingFile);
  logplayer_cmd->add_option("--url", replay_url, "where to play it (watch it there with hil spy URL)")
      ->capture_default_str();

  auto* rerun_cmd = app.add_subcommand(
      "rerun", "feed the PLC inputs of a recorded run into this CNC build in lock-step; report the first "
               "difference or 'identical' (RIG-7)");
  rerun_cmd->add_option("log", log_file, "LCM event log of a rig run")->required()->check(CLI::ExistingFile);

  std::string schema_of = "scenario";
  auto* schema_cmd = app.add_subcommand(
      "schema", "print the JSON Schema of scenario or machine files, made from the loaders' keys (schemas/, docs/SCENARIOS.md)");
  schema_cmd->add_option("file", schema_of, "scenario or machine")
      ->check(CLI::IsMember({"scenario", "machine"}))
      ->capture_default_str();

  std::string csv_dir;
  auto* export_cmd = app.add_subcommand("export", "a log as CSV files, one per channel, SI units (RIG-4, docs/EXPORT.md)");
  export_cmd->add_option("log", log_file, "LCM event log")->required()->check(CLI::ExistingFile);
  export_cmd->add_option("--csv", csv_dir, "folder for the CSV files")->required();

  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  try {
    if (*spy_cmd) return hil::rig::run_spy(run.bin_dir, spy_source, speed);
    if (*replay_cmd) return hil::rig::run_replay(log_file, replay_url, speed);
    if (*logplayer_cmd) return hil::rig::run_logplayer(log_file, replay_url);
  } catch (const std::exception& e) {
    std::cerr << "hil: " << e.what() << '\n';
    return 2;
  }
  if (*rerun_cmd) return hil::rig::exec_rerun(run.bin_dir, log_file);
  try {
    if (*run_cmd) return hil::rig::run_scenarios(suite, run);
    if (*validate_cmd) return hil::rig::validate_scenario_files(validate_files);
    if (*schema_cmd) {
      std::cout << (schema_of == "machine" ? hil::machine_schema() : hil::scenario_schema());
      return 0;
    }
    if (*check_cmd) return check_log(log_file, plot_dir);
    if (*export_cmd) return hil::rig::export_csv_command(log_file, csv_dir);
    if (*compare_cmd) return hil::rig::compare_command(pair[0], pair[1], std::cout);
    if (*golden_cmd) return hil::rig::write_golden_trace(log_file, golden_out, golden_comment, std::cout);
  } catch (const hil::ConfigError& e) {
    std::cerr << "hil: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "hil: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
