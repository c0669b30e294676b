// The `axis_sim` process (RIG-1, RIG-3): one drive (axis_sim_node.hpp) on LCM.
#include <spdlog/spdlog.h>

#include <optional>

#include "command_line.hpp"
#include "axis_sim_node.hpp"
#include "node_options.hpp"
#include "fault_bus.hpp"
#include "udpm_bus.hpp"
#include "participant.hpp"
#include "real_time_process.hpp"
#include "scenario.hpp"

int main(int argc, char** argv) {
  CLI::App app{"axis_sim: simulated drive of one axis of the HIL rig"};
  hil::lcm_support::NodeOptions options;
  hil::lcm_support::add_node_options(app, options);
  std::string axis_name;
  app.add_option("--axis", axis_name, "axis name as in the machine configuration")->required();
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  return hil::lcm_support::guarded_main("axis_sim " + axis_name, [&] {
    const hil::Scenario scenario = hil::load_scenario_file(options.scenario_file);
    const int index = scenario.machine.axis_index(axis_name);
    if (index < 0) throw std::runtime_error("axis '" + axis_name + "' is not on the machine");
    // Real time (RIG-6): SCHED_FIFO (hil run sets it already) and locked memory where allowed.
    std::optional<hil::lcm_support::RealTimeProcess> real_time;
    if (scenario.realtime) real_time = hil::lcm_support::enter_real_time();
    const auto bus =
        hil::lcm_support::with_faults(hil::lcm_support::run_bus(options), scenario.faults, "axis_sim " + axis_name);
    hil::lcm_support::Inbox inbox(*bus, options.run_id);
    hil::axis::AxisSimNode node(scenario.machine.axes[index], scenario.machine.cycle_time_s(), inbox);
    hil::lcm_support::Participant participant(inbox, node.name());
    if (!participant.wait_for_start(std::chrono::seconds(30))) {
      spdlog::error("the CNC did not start a run within 30 s");
      return 2;
    }
    if (real_time) hil::lcm_support::publish_real_time(inbox, *real_time, node.name());
    using hil::lcm_support::cnc_silence;
    if (!participant.serve_until_end(cnc_silence, [&] { return node.last_cycle(); })) {
      spdlog::error("the CNC is gone: nothing from it for {} s after cycle {}", cnc_silence.count(), node.last_cycle());
      return 2;
    }
    participant.announce_end(node.last_cycle());
    if (!inbox.ledger().empty()) spdlog::warn("refused: {}", inbox.ledger().describe());
    return 0;
  });
}
