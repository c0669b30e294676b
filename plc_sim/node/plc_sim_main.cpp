// The `plc_sim` process (RIG-1, RIG-5): the PLC (plc_sim_node.hpp) on LCM.
// Failed expectations are a verdict, not an error: the exit status is 0
// whenever the node did its job.
#include <spdlog/spdlog.h>

#include <optional>

#include "command_line.hpp"
#include "node_options.hpp"
#include "fault_bus.hpp"
#include "udpm_bus.hpp"
#include "participant.hpp"
#include "real_time_process.hpp"
#include "plc_sim_node.hpp"
#include "scenario.hpp"

int main(int argc, char** argv) {
  using hil::plc::PlcSimNode;
  CLI::App app{"plc_sim: simulated PLC of the HIL rig, runs the scenario timeline"};
  hil::lcm_support::NodeOptions options;
  hil::lcm_support::add_node_options(app, options);
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  return hil::lcm_support::guarded_main(PlcSimNode::source, [&] {
    const hil::Scenario scenario = hil::load_scenario_file(options.scenario_file);
    // Real time (RIG-6): SCHED_FIFO (hil run sets it already) and locked memory where allowed.
    std::optional<hil::lcm_support::RealTimeProcess> real_time;
    if (scenario.realtime) real_time = hil::lcm_support::enter_real_time();
    const auto bus =
        hil::lcm_support::with_faults(hil::lcm_support::run_bus(options), scenario.faults, "plc_sim");
    hil::lcm_support::Inbox inbox(*bus, options.run_id);
    PlcSimNode node(scenario, inbox);
    hil::lcm_support::Participant participant(inbox, PlcSimNode::source);
    if (!participant.wait_for_start(std::chrono::seconds(30))) {
      spdlog::error("the CNC did not start a run within 30 s");
      return 2;
    }
    if (real_time) hil::lcm_support::publish_real_time(inbox, *real_time, PlcSimNode::source);
    using hil::lcm_support::cnc_silence;
    if (!participant.serve_until_end(cnc_silence, [&] { return node.last_cycle(); })) {
      spdlog::error("the CNC is gone: nothing from it for {} s after cycle {}", cnc_silence.count(), node.last_cycle());
      return 2;
    }
    const int verdicts = node.report(participant.end_cycle());
    participant.announce_end(participant.end_cycle(), verdicts);
    if (!inbox.ledger().empty()) spdlog::warn("refused: {}", inbox.ledger().describe());
    return 0;
  });
}
