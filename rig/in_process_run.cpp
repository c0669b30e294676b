#include "in_process_run.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/spdlog.h>

#include <deque>
#include <memory>

#include "axis_sim_node.hpp"
#include "cnc_node.hpp"
#include "fault_bus.hpp"
#include "in_process_bus.hpp"
#include "logger_node.hpp"
#include "participant.hpp"
#include "plc_sim_node.hpp"
#include "run_identity.hpp"
#include "scenario.hpp"

namespace hil::rig {
namespace {

// A node's inbox and handshake on its own side of the bus (with the
// scenario's faults on what it sends, RIG-8); the node is made on the inbox.
struct Attendee {
  Attendee(lcm_support::Bus& bus, const FaultPlan& faults, int64_t run_id, const std::string& name)
      : side(bus, faults, name), inbox(side, run_id), participant(inbox, name) {}
  // The exit status its process gets when the node ends normally with `status`.
  int exit(int status) const { return side.killed() ? 128 + 9 : status; }
  lcm_support::FaultInjectingBus side;
  lcm_support::Inbox inbox;
  lcm_support::Participant participant;
};

// As a process would: an exception ends the node with status 1.
template <typename Body>
int guarded(const std::string& node, Body body) {
  try {
    return body();
  } catch (const std::exception& e) {
    spdlog::error("[{}] {}", node, e.what());
    return 1;
  }
}

}  // namespace

std::vector<logger::ProcessExit> run_in_process(const std::string& resolved_file, const std::string& log_file,
                                                const std::string& output_file, int64_t run_id, double pace) {
  const auto previous = spdlog::default_logger();
  spdlog::set_default_logger(spdlog::basic_logger_mt("in_process", output_file, true));
  spdlog::set_pattern("[%H:%M:%S.%e] [%l] %v");

  const std::string text = read_text(resolved_file);
  const Scenario scenario = load_scenario_file(resolved_file);
  std::vector<std::string> participants{"cnc", "plc_sim"};
  for (const AxisConfig& axis : scenario.machine.axes) participants.push_back("axis_sim " + axis.name);

  lcm_support::InProcessBus bus;
  // The logger first: it records every message from the first on.
  logger::LoggerNode logger(bus, log_file, run_id, participants, std::make_pair(text, scenario.nc_program),
                             false);
  const FaultPlan no_faults;
  Attendee logger_attendee(bus, no_faults, run_id, "logger");
  int64_t announced_cycle = -1;
  logger.on_progress([&](int64_t cycle) {  // the heartbeat the CNC's flow control waits for
    if (cycle < announced_cycle + 32) return;
    announced_cycle = cycle;
    logger_attendee.participant.announce_alive(cycle);
  });
  std::deque<Attendee> axis_attendees;
  std::deque<axis::AxisSimNode> axes;
  for (const AxisConfig& axis : scenario.machine.axes) {
    axis_attendees.emplace_back(bus, scenario.faults, run_id, "axis_sim " + axis.name);
    axes.emplace_back(axis, scenario.machine.cycle_time_s(), axis_attendees.back().inbox);
  }
  Attendee plc_attendee(bus, scenario.faults, run_id, plc::PlcSimNode::source);
  plc::PlcSimNode plc(scenario, plc_attendee.inbox);

  logger_attendee.participant.announce_ready();
  for (Attendee& a : axis_attendees) a.participant.announce_ready();
  plc_attendee.participant.announce_ready();

  std::vector<std::string> cnc_participants;
  for (const AxisConfig& axis : scenario.machine.axes) cnc_participants.push_back("axis_sim " + axis.name);
  cnc_participants.insert(cnc_participants.end(), {"plc_sim", "logger"});
  std::vector<logger::ProcessExit> exits;
  lcm_support::FaultInjectingBus cnc_side(bus, scenario.faults, "cnc");
  cnc_node::CncTiming timing;
  timing.pace = pace;
  exits.push_back({"cnc", guarded("cnc", [&] {
                     return cnc_node::run_cnc(scenario, text, cnc_side, run_id, cnc_participants, timing);
                   })});
  bus.drain();  // the CNC's RUN_END reaches everyone

  // Each node ends as its process does once the CNC has ended (status 2:
  // the CNC never ended the run).
  std::vector<logger::ProcessExit> others;
  for (size_t i = 0; i < axes.size(); ++i)
    others.push_back({axes[i].name(), guarded(axes[i].name(), [&] {
                        Attendee& a = axis_attendees[i];
                        if (!a.participant.ended()) return a.exit(2);
                        a.participant.announce_end(axes[i].last_cycle());
                        return a.exit(0);
                      })});
  others.push_back({plc::PlcSimNode::source, guarded(plc::PlcSimNode::source, [&] {
                      lcm_support::Participant& p = plc_attendee.participant;
                      if (!p.ended()) return plc_attendee.exit(2);
                      p.announce_end(p.end_cycle(), plc.report(p.end_cycle()));
                      return plc_attendee.exit(0);
                    })});
  bus.drain();
  exits.push_back({"logger", guarded("logger", [&] {
                     logger.seal();
                     return logger.finish(log_file, 0);
                   })});
  exits.insert(exits.end(), others.begin(), others.end());

  spdlog::default_logger()->flush();
  spdlog::drop("in_process");
  spdlog::set_default_logger(previous);
  return exits;
}

}  // namespace hil::rig
