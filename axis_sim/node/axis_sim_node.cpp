#include "axis_sim_node.hpp"

#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <spdlog/spdlog.h>

#include "channels.hpp"
#include "messages.hpp"

namespace hil::axis {

AxisSimNode::AxisSimNode(const AxisConfig& axis, double cycle_time_s, lcm_support::Inbox& inbox)
    : axis_(axis), bus_(inbox.bus()), run_id_(inbox.run_id()), cycle_time_s_(cycle_time_s),
      cycle_us_(static_cast<int64_t>(cycle_time_s * 1e6 + 0.5)), drive_(drive_parameters(axis, cycle_time_s)),
      monitor_(axis), source_("axis_sim " + axis.name) {
  inbox.on<hil::axis_setpoint_t>(channels::axis_command(axis.name),
                                 [this](const hil::axis_setpoint_t& m, const lcm::ReceiveBuffer&) {
                                   // Each cycle is integrated once, in order. Setpoints lost on
                                   // the way (RIG-8) leave a gap, bridged; a gap longer than the
                                   // watchdog allows cannot be (the CNC has stopped the channel
                                   // by then): a setpoint that far ahead is forged.
                                   if (m.axis != axis_.name || m.cycle <= last_cycle_ ||
                                       m.cycle > last_cycle_ + 1 + axis_.watchdog_cycles)
                                     return false;
                                   bridge_gap(m.cycle);
                                   on_setpoint(m);
                                   return true;
                                 });
}

// As a drive in interpolated position mode does when setpoints are missing:
// it goes on at the last commanded velocity, and monitors as ever.
void AxisSimNode::bridge_gap(int64_t cycle) {
  if (last_cycle_ < 0) return;  // none yet: the drive was at rest
  hil::axis_setpoint_t held = last_setpoint_;
  for (int64_t k = last_cycle_ + 1; k < cycle; ++k) {
    held.cycle = k;
    held.utime = last_setpoint_.utime + (k - last_setpoint_.cycle) * cycle_us_;
    held.position += held.velocity * cycle_time_s_;
    step(held, false);
  }
}

void AxisSimNode::on_setpoint(const hil::axis_setpoint_t& m) {
  step(m, true);
  last_setpoint_ = m;
}

void AxisSimNode::step(const hil::axis_setpoint_t& m, bool answer) {
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
  if (answer) bus_.publish(channels::axis_state(axis_.name), s);
}

}  // namespace hil::axis
