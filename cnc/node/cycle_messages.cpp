#include "cycle_messages.hpp"

#include <hil/axis_setpoint_t.hpp>

#include "bus.hpp"
#include "channels.hpp"
#include "messages.hpp"

namespace hil::cnc_node {
namespace {

template <typename T>
EncodedMessage encoded(const std::string& channel, const T& message) {
  return {channel, lcm_support::encode(message)};
}

}  // namespace

std::vector<cnc::DriveError> drive_errors(const MachineConfig& machine, const std::vector<int32_t>& errors) {
  std::vector<cnc::DriveError> out;
  for (size_t i = 0; i < errors.size() && i < machine.axes.size(); ++i)
    if (errors[i]) out.push_back({machine.axes[i].name, lcm_support::monitor_names(errors[i])});
  return out;
}

EncodedMessage event_message(const Event& event, const MachineConfig& machine, int64_t cycle, int64_t run_id) {
  hil::event_t m = lcm_support::to_message(event, cycle, cycle * machine.cycle_time_us, "cnc");
  m.run_id = run_id;
  return encoded(channels::event, m);
}

std::vector<EncodedMessage> cycle_messages(const cnc::Channel& channel, const MachineConfig& machine,
                                           const std::vector<Event>& events, int64_t cycle, int64_t run_id) {
  std::vector<EncodedMessage> out;
  for (const Event& e : events) out.push_back(event_message(e, machine, cycle, run_id));
  const int64_t utime = cycle * machine.cycle_time_us;
  const auto& setpoints = channel.setpoints();
  for (size_t i = 0; i < setpoints.size(); ++i) {
    hil::axis_setpoint_t m;
    m.run_id = run_id;
    m.utime = utime;
    m.cycle = cycle;
    m.axis = machine.axes[i].name;
    m.position = setpoints[i].position;
    m.velocity = setpoints[i].velocity;
    m.acceleration = setpoints[i].acceleration;
    out.push_back(encoded(channels::axis_command(m.axis), m));
  }
  hil::hli_state_t state = lcm_support::to_message(channel.hli(), utime);
  state.run_id = run_id;
  out.push_back(encoded(channels::hli_state, state));
  return out;
}

}  // namespace hil::cnc_node
