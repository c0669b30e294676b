// The `cnc` process (RIG-1, RIG-6, RIG-7): the CNC (cnc_node.hpp) on LCM,
// or `--rerun LOG`: a recorded run's PLC inputs fed into this build.
#include <iostream>

#include "command_line.hpp"
#include "cnc_node.hpp"
#include "node_options.hpp"
#include "fault_bus.hpp"
#include "udpm_bus.hpp"
#include "rerun.hpp"
#include "run_identity.hpp"
#include "scenario.hpp"

int main(int argc, char** argv) {
  CLI::App app{"cnc: the CNC node of the HIL rig, clock master in lock-step or in real time (run.realtime)"};
  hil::lcm_support::NodeOptions options;
  hil::lcm_support::add_node_options(app, options);
  std::vector<std::string> participants;
  app.add_option("--participants", participants,
                 "nodes to wait for before cycle 0 (default: every axis_sim, plc_sim, logger)");
  int answer_timeout_ms = 5000, logger_timeout_ms = 2000;
  app.add_option("--answer-timeout-ms", answer_timeout_ms, "lock-step watchdog per cycle")->check(CLI::PositiveNumber);
  app.add_option("--logger-timeout-ms", logger_timeout_ms, "the logger's heartbeat may fall silent this long")
      ->check(CLI::PositiveNumber);
  double pace = 0;
  app.add_option("--pace", pace,
                 "lock-step no faster than PACE x real time (1: as the machine would; the log is the same)")
      ->check(CLI::PositiveNumber);
  std::string rerun_log;
  app.add_option("--rerun", rerun_log,
                 "instead of a live run: feed the PLC inputs recorded in this log into this build in lock-step "
                 "and report the first difference (RIG-7)")
      ->check(CLI::ExistingFile);
  // A rerun needs neither a scenario file nor a rig: the log has both.
  for (const char* option : {"--scenario", "--url", "--run-id"})
    app.get_option(option)->required(false)->excludes("--rerun");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  if (rerun_log.empty() && (options.scenario_file.empty() || options.url.empty() || options.run_id <= 0)) {
    std::cerr << "cnc: --scenario, --url and --run-id are required (or --rerun LOG)\n";
    return 2;
  }
  // 1 is "differs": a log that cannot be rerun is bad input (2), said on stderr.
  if (!rerun_log.empty()) try {
      return hil::cnc_node::rerun(rerun_log, std::cout);
    } catch (const std::exception& e) {
      std::cerr << "cnc --rerun: " << e.what() << '\n';
      return 2;
    }
  return hil::lcm_support::guarded_main("cnc", [&] {
    const std::string text = hil::read_text(options.scenario_file);
    const hil::Scenario scenario = hil::load_scenario_file(options.scenario_file);
    if (participants.empty()) {
      for (const auto& axis : scenario.machine.axes) participants.push_back("axis_sim " + axis.name);
      participants.push_back("plc_sim");
      participants.push_back("logger");
    }
    // Real time (RIG-6): SCHED_FIFO (hil run sets it already) and locked memory where allowed.
    const hil::lcm_support::RealTimeProcess process =
        scenario.realtime ? hil::lcm_support::enter_real_time() : hil::lcm_support::RealTimeProcess{};
    const auto bus =
        hil::lcm_support::with_faults(hil::lcm_support::run_bus(options), scenario.faults, "cnc");
    return hil::cnc_node::run_cnc(
        scenario, text, *bus, options.run_id, participants,
        {std::chrono::milliseconds(answer_timeout_ms), std::chrono::milliseconds(logger_timeout_ms), pace}, process);
  });
}
