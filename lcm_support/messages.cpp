#include "messages.hpp"

namespace hil::lcm_support {
namespace {

// A control unit's fields between the HLI structs and the LCM types, either way.
template <typename To, typename From>
void copy_state(To& to, const From& from) {
  to.request_r = from.request_r;
  to.state_r = from.state_r;
}

template <typename To, typename From>
void copy_control(To& to, const From& from) {
  to.command_w = from.command_w;
  to.enable_w = from.enable_w;
}

}  // namespace

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
  copy_state(m.program_start, s.program_start);
  copy_state(m.feedhold, s.feedhold);
  copy_state(m.override, s.override);
  copy_state(m.delete_distance_to_go, s.delete_distance_to_go);
  copy_state(m.delete_distance_to_go_activation, s.delete_distance_to_go_activation);
  m.delete_distance_to_go_active_r = s.delete_distance_to_go_active_r;
  m.m_function_request_r = s.m_function_request_r;
  m.m_function_nr_r = s.m_function_nr_r;
  copy_state(m.backward_motion, s.backward_motion);
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
  copy_state(s.program_start, m.program_start);
  copy_state(s.feedhold, m.feedhold);
  copy_state(s.override, m.override);
  copy_state(s.delete_distance_to_go, m.delete_distance_to_go);
  copy_state(s.delete_distance_to_go_activation, m.delete_distance_to_go_activation);
  s.delete_distance_to_go_active_r = m.delete_distance_to_go_active_r;
  s.m_function_request_r = m.m_function_request_r;
  s.m_function_nr_r = m.m_function_nr_r;
  copy_state(s.backward_motion, m.backward_motion);
  return s;
}

hil::hli_control_t to_message(const HliControl& c, int64_t utime) {
  hil::hli_control_t m;
  m.utime = utime;
  m.cycle = c.cycle;
  copy_control(m.program_start, c.program_start);
  copy_control(m.feedhold, c.feedhold);
  copy_control(m.override, c.override);
  copy_control(m.delete_distance_to_go, c.delete_distance_to_go);
  copy_control(m.delete_distance_to_go_activation, c.delete_distance_to_go_activation);
  copy_control(m.m_function_ack, c.m_function_ack);
  copy_control(m.backward_motion, c.backward_motion);
  return m;
}

HliControl from_message(const hil::hli_control_t& m) {
  HliControl c;
  c.cycle = m.cycle;
  copy_control(c.program_start, m.program_start);
  copy_control(c.feedhold, m.feedhold);
  copy_control(c.override, m.override);
  copy_control(c.delete_distance_to_go, m.delete_distance_to_go);
  copy_control(c.delete_distance_to_go_activation, m.delete_distance_to_go_activation);
  copy_control(c.m_function_ack, m.m_function_ack);
  copy_control(c.backward_motion, m.backward_motion);
  return c;
}

std::string monitor_names(int32_t bits) {
  static const std::pair<int32_t, const char*> names[] = {
      {hil::axis_state_t::MONITOR_ACCELERATION, "acceleration P-AXIS-00442"},
      {hil::axis_state_t::MONITOR_VELOCITY, "velocity P-AXIS-00440"},
      {hil::axis_state_t::MONITOR_FOLLOWING_ERROR, "following error P-AXIS-00168/00169"},
      {hil::axis_state_t::MONITOR_SOFTWARE_LIMIT, "software limit switch P-AXIS-00177/00178"},
      {hil::axis_state_t::MONITOR_NOT_FINITE, "setpoint not finite"}};
  std::string out;
  for (const auto& [bit, name] : names)
    if (bits & bit) out += (out.empty() ? "" : ", ") + std::string(name);
  return out.empty() ? "monitoring" : out;
}

}  // namespace hil::lcm_support
