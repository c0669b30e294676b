#include "messages.hpp"

namespace hil::lcm_support {

hil::event_t to_message(const Event& e, int64_t cycle, int64_t utime, const std::string& source) {
  hil::event_t m;
  m.utime = utime;
  m.cycle = cycle;
  m.severity = static_cast<int8_t>(e.severity);
  m.id = e.id;
  m.parameter = e.parameter;
  m.source = source;
  m.axis = e.axis;
  m.nc_line = e.nc_line;
  m.block_nr = e.block_nr;
  m.value = e.value;
  m.limit = e.limit;
  m.message = e.message;
  return m;
}

Event from_message(const hil::event_t& m) {
  return {static_cast<Severity>(m.severity), m.id, m.parameter, m.axis, m.nc_line, m.block_nr,
          m.value, m.limit, m.message};
}

hil::hli_state_t to_message(const HliState& s, int64_t utime) {
  hil::hli_state_t m;
  m.utime = utime;
  m.cycle = s.cycle;
  m.channel_state = static_cast<int8_t>(s.channel_state);
  m.block_nr_r = s.block_nr_r;
  m.block_count_r = s.block_count_r;
  m.stop_conditions_r = s.stop_conditions_r;
  m.dist_prog_start = s.dist_prog_start;
  m.path_velocity = s.path_velocity;
  m.last_error_id = s.last_error_id;
  m.n_axes = static_cast<int16_t>(s.axis_name.size());
  m.axis_name = s.axis_name;
  m.axis_position_r = s.axis_position_r;
  m.program_start.request_r = s.program_start.request_r;
  m.program_start.state_r = s.program_start.state_r;
  m.feedhold.request_r = s.feedhold.request_r;
  m.feedhold.state_r = s.feedhold.state_r;
  m.override.request_r = s.override.request_r;
  m.override.state_r = s.override.state_r;
  m.delete_distance_to_go.request_r = s.delete_distance_to_go.request_r;
  m.delete_distance_to_go.state_r = s.delete_distance_to_go.state_r;
  m.delete_distance_to_go_activation.request_r = s.delete_distance_to_go_activation.request_r;
  m.delete_distance_to_go_activation.state_r = s.delete_distance_to_go_activation.state_r;
  m.delete_distance_to_go_active_r = s.delete_distance_to_go_active_r;
  m.m_function_request_r = s.m_function_request_r;
  m.m_function_nr_r = s.m_function_nr_r;
  m.backward_motion.request_r = s.backward_motion.request_r;
  m.backward_motion.state_r = s.backward_motion.state_r;
  return m;
}

HliState from_message(const hil::hli_state_t& m) {
  HliState s;
  s.cycle = m.cycle;
  s.channel_state = static_cast<ChannelState>(m.channel_state);
  s.block_nr_r = m.block_nr_r;
  s.block_count_r = m.block_count_r;
  s.stop_conditions_r = m.stop_conditions_r;
  s.dist_prog_start = m.dist_prog_start;
  s.path_velocity = m.path_velocity;
  s.last_error_id = m.last_error_id;
  s.axis_name = m.axis_name;
  s.axis_position_r = m.axis_position_r;
  s.program_start.request_r = m.program_start.request_r;
  s.program_start.state_r = m.program_start.state_r;
  s.feedhold.request_r = m.feedhold.request_r;
  s.feedhold.state_r = m.feedhold.state_r;
  s.override.request_r = m.override.request_r;
  s.override.state_r = m.override.state_r;
  s.delete_distance_to_go.request_r = m.delete_distance_to_go.request_r;
  s.delete_distance_to_go.state_r = m.delete_distance_to_go.state_r;
  s.delete_distance_to_go_activation.request_r = m.delete_distance_to_go_activation.request_r;
  s.delete_distance_to_go_activation.state_r = m.delete_distance_to_go_activation.state_r;
  s.delete_distance_to_go_active_r = m.delete_distance_to_go_active_r;
  s.m_function_request_r = m.m_function_request_r;
  s.m_function_nr_r = m.m_function_nr_r;
  s.backward_motion.request_r = m.backward_motion.request_r;
  s.backward_motion.state_r = m.backward_motion.state_r;
  return s;
}

hil::hli_control_t to_message(const HliControl& c, int64_t utime) {
  hil::hli_control_t m;
  m.utime = utime;
  m.cycle = c.cycle;
  m.program_start.command_w = c.program_start.command_w;
  m.program_start.enable_w = c.program_start.enable_w;
  m.feedhold.command_w = c.feedhold.command_w;
  m.feedhold.enable_w = c.feedhold.enable_w;
  m.override.command_w = c.override.command_w;
  m.override.enable_w = c.override.enable_w;
  m.delete_distance_to_go.command_w = c.delete_distance_to_go.command_w;
  m.delete_distance_to_go.enable_w = c.delete_distance_to_go.enable_w;
  m.delete_distance_to_go_activation.command_w = c.delete_distance_to_go_activation.command_w;
  m.delete_distance_to_go_activation.enable_w = c.delete_distance_to_go_activation.enable_w;
  m.m_function_ack.command_w = c.m_function_ack.command_w;
  m.m_function_ack.enable_w = c.m_function_ack.enable_w;
  m.backward_motion.command_w = c.backward_motion.command_w;
  m.backward_motion.enable_w = c.backward_motion.enable_w;
  return m;
}

HliControl from_message(const hil::hli_control_t& m) {
  HliControl c;
  c.cycle = m.cycle;
  c.program_start.command_w = m.program_start.command_w;
  c.program_start.enable_w = m.program_start.enable_w;
  c.feedhold.command_w = m.feedhold.command_w;
  c.feedhold.enable_w = m.feedhold.enable_w;
  c.override.command_w = m.override.command_w;
  c.override.enable_w = m.override.enable_w;
  c.delete_distance_to_go.command_w = m.delete_distance_to_go.command_w;
  c.delete_distance_to_go.enable_w = m.delete_distance_to_go.enable_w;
  c.delete_distance_to_go_activation.command_w = m.delete_distance_to_go_activation.command_w;
  c.delete_distance_to_go_activation.enable_w = m.delete_distance_to_go_activation.enable_w;
  c.m_function_ack.command_w = m.m_function_ack.command_w;
  c.m_function_ack.enable_w = m.m_function_ack.enable_w;
  c.backward_motion.command_w = m.backward_motion.command_w;
  c.backward_motion.enable_w = m.backward_motion.enable_w;
  return c;
}

std::string monitor_names(int32_t bits) {
  static const std::pair<int32_t, const char*> names[] = {
      {hil::axis_state_t::MONITOR_ACCELERATION, "acceleration P-AXIS-00442"},
      {hil::axis_state_t::MONITOR_VELOCITY, "velocity P-AXIS-00440"},
      {hil::axis_state_t::MONITOR_FOLLOWING_ERROR, "following error P-AXIS-00168/00169"},
      {hil::axis_state_t::MONITOR_SOFTWARE_LIMIT, "software limit switch P-AXIS-00177/00178"}};
  std::string out;
  for (const auto& [bit, name] : names)
    if (bits & bit) out += (out.empty() ? "" : ", ") + std::string(name);
  return out.empty() ? "monitoring" : out;
}

}  // namespace hil::lcm_support
