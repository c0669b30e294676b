#include "axis_sim_node.hpp"

#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <spdlog/spdlog.h>

#include "channels.hpp"
#include "messages.hpp"

namespace hil::axis {

AxisSimNode::AxisSimNode(const AxisConfig& axis, double cycle_time_s, lcm_support::Inbox& inbox)
    : axis_(axis), bus_(inbox.bus()), run_id_(inbox.run_id()), drive_(drive_parameters(axis, cycle_time_s)),
      monitor_(axis), source_("axis_sim " + axis.name) {
  inbox.on<hil::axis_setpoint_t>(channels::axis_command(axis.name),
                                 [this](const hil::axis_setpoint_t& m, const lcm::ReceiveBuffer&) {
                                   // each cycle is integrated once, in order
                                   if (m.cycle != last_cycle_ + 1 || m.axis != axis_.name) return false;
                                   on_setpoint(m);
                                   return true;
                                 });
}

void AxisSimNode::on_setpoint(const hil::axis_setpoint_t& m) {
  last_cycle_ = m.cycle;
  const DriveOutput out = drive_.step(m.position, m.velocity);
  std::vector<Event> events;
  const MonitorState monitored = monitor_.check(
      {m.position, m.velocity, out.position, out.velocity, out.acceleration, out.following_error}, events);
  for (const Event& e : events) {
    spdlog::warn("{}", describe(e));
    hil::event_t em = lcm_support::to_message(e, m.cycle, m.utime, source_);
    em.run_id = run_id_;
    bus_.publish(channels::event, em);
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
  bus_.publish(channels::axis_state(axis_.name), s);
}

}  // namespace hil::axis
