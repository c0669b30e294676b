// The `axis_sim` node (RIG-1, RIG-3): one drive. Integrates one cycle per
// setpoint and answers with the actual state and its monitoring.
#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <spdlog/spdlog.h>

#include "channels.hpp"
#include "drive_model.hpp"
#include "drive_monitor.hpp"
#include "inbox.hpp"
#include "messages.hpp"
#include "node_options.hpp"
#include "participant.hpp"
#include "scenario.hpp"

namespace {

using namespace hil;

class AxisSimNode {
 public:
  AxisSimNode(const AxisConfig& axis, double cycle_time_s, lcm::LCM& lcm, lcm_support::Inbox& inbox)
      : axis_(axis), lcm_(lcm), run_id_(inbox.run_id()), drive_(axis::drive_parameters(axis, cycle_time_s)),
        monitor_(axis), source_("axis_sim " + axis.name) {
    inbox.on<hil::axis_setpoint_t>(channels::axis_command(axis.name),
                                   [this](const hil::axis_setpoint_t& m, const lcm::ReceiveBuffer&) {
                                     // each cycle is integrated once, in order
                                     if (m.cycle != last_cycle_ + 1 || m.axis != axis_.name) return false;
                                     on_setpoint(m);
                                     return true;
                                   });
  }

  const std::string& name() const { return source_; }
  int64_t last_cycle() const { return last_cycle_; }

 private:
  void on_setpoint(const hil::axis_setpoint_t& m) {
    last_cycle_ = m.cycle;
    const axis::DriveOutput out = drive_.step(m.position, m.velocity);
    std::vector<Event> events;
    const axis::MonitorState monitored = monitor_.check(
        {m.position, m.velocity, out.position, out.velocity, out.acceleration, out.following_error}, events);
    for (const Event& e : events) {
      spdlog::warn("{}", describe(e));
      hil::event_t em = lcm_support::to_message(e, m.cycle, m.utime, source_);
      em.run_id = run_id_;
      lcm_.publish(channels::event, &em);
    }
    hil::axis_state_t s;
    s.run_id = run_id_;
    s.utime = m.utime;
    s.cycle = m.cycle;
    s.axis = axis_.name;
    s.setpoint_position = m.position;
    s.position = out.position;
    s.modulo_position = axis_.in_modulo_range(out.position);
    s.velocity = out.velocity;
    s.acceleration = out.acceleration;
    s.following_error = out.following_error;
    s.warnings = monitored.warnings;
    s.errors = monitored.errors;
    lcm_.publish(channels::axis_state(axis_.name), &s);
  }

  AxisConfig axis_;
  lcm::LCM& lcm_;
  int64_t run_id_;
  axis::DriveModel drive_;
  axis::DriveMonitor monitor_;
  std::string source_;
  int64_t last_cycle_ = -1;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"axis_sim: simulated drive of one axis of the HIL rig"};
  hil::lcm_support::NodeOptions options;
  hil::lcm_support::add_node_options(app, options);
  std::string axis_name;
  app.add_option("--axis", axis_name, "axis name as in the machine configuration")->required();
  CLI11_PARSE(app, argc, argv);
  return hil::lcm_support::guarded_main("axis_sim " + axis_name, [&] {
    const hil::Scenario scenario = hil::load_scenario_file(options.scenario_file);
    const int index = scenario.machine.axis_index(axis_name);
    if (index < 0) throw std::runtime_error("axis '" + axis_name + "' is not on the machine");
    lcm::LCM lcm(options.url);
    hil::lcm_support::require_good(lcm, options.url);
    hil::lcm_support::Inbox inbox(lcm, options.run_id);
    AxisSimNode node(scenario.machine.axes[index], scenario.machine.cycle_time_s(), lcm, inbox);
    hil::lcm_support::Participant participant(lcm, inbox, node.name());
    if (!participant.wait_for_start(std::chrono::seconds(30))) {
      spdlog::error("the CNC did not start a run within 30 s");
      return 2;
    }
    if (!participant.serve_until_end(std::chrono::seconds(10))) {
      spdlog::error("no message for 10 s after cycle {}: the CNC is gone", node.last_cycle());
      return 2;
    }
    participant.announce_end(node.last_cycle());
    if (!inbox.ledger().empty()) spdlog::warn("refused: {}", inbox.ledger().describe());
    return 0;
  });
}
