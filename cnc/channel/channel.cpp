#include "channel.hpp"

#include <cmath>
#include <string>

#include "decoder.hpp"
#include "m_pre_output.hpp"

namespace hil::cnc {

Channel::Channel(MachineConfig machine, std::string nc_program)
    : machine_(std::move(machine)), nc_program_(std::move(nc_program)), path_(machine_, *this),
      feed_(machine_.override_max_percent), ddtg_(machine_), backward_(machine_) {
  for (const AxisConfig& axis : machine_.axes) hli_.axis_name.push_back(axis.name);
  hli_.axis_position_r.assign(machine_.axes.size(), 0);
  hli_.stop_conditions_r = stop_condition::ipo_input_empty;
  hli_.override.state_r = override_full;
}

bool Channel::finished() const {
  return hli_.channel_state == ChannelState::program_end ||
         (hli_.channel_state == ChannelState::error && !error_stop_.stopping());
}

void Channel::step(int64_t cycle, const HliControl& control) {
  cycle_ = cycle;
  apply_control(control);
  if (moving()) run_path(control, static_cast<double>(cycle - start_cycle_) * machine_.cycle_time_s());
  write_state();
}

void Channel::apply_control(const HliControl& control) {
  const bool feed_changed = feed_.apply(control, hli_, events_);
  const bool backward_changed = backward_.apply(control.backward_motion, hli_, events_);
  if (feed_changed || backward_changed) update_hold();
  if (ddtg_.apply(control, hli_.channel_state == ChannelState::active, hli_, events_)) update_hold();
  apply_program_start(control.program_start);
}

// KRN-4: control units act on the rising edge of command_w while enable_w.
void Channel::apply_program_start(const ControlUnitBool& start) {
  hli_.program_start.request_r = start.command_w && start.enable_w;
  if (!program_start_(start.command_w) || !start.enable_w) return;
  if (hli_.channel_state != ChannelState::ready) {
    Event ignored;
    ignored.severity = Severity::warning;
    ignored.message = std::string("program start ignored: channel is ") + to_string(hli_.channel_state);
    events_.raise(ignored);
    return;
  }
  start_program();
}

void Channel::start_program() {
  DecodedProgram program = decode_program(nc_program_, machine_, path_.setpoint_positions());
  if (program.error) {
    decode_failed_ = true;
    events_.raise(*program.error);  // reported at once; the blocks before it still run
  }
  std::vector<Event> warnings;
  path_.load(apply_m_pre_output(std::move(program.blocks), machine_, warnings));
  for (Event& warning : warnings) events_.raise(std::move(warning));
  start_cycle_ = cycle_;
  hli_.channel_state = ChannelState::active;
  path_.go_on_from_standstill(0);
  interpolate(0);
}

void Channel::run_path(const HliControl& control, double t) {
  if (actions_.run(control.m_function_ack, t, hli_)) update_hold();
  interpolate(t);
  const bool standing = path_.standing(t);
  if (error_stop_.stopping()) error_stop_.update(standing);
  if (ddtg_.pending() && standing && hli_.channel_state == ChannelState::active) start_short_cut(t);
  if (hli_.channel_state == ChannelState::active) change_direction(t, standing);
}

void Channel::interpolate(double t) {
  const PathProgress progress = path_.interpolate(t);
  hli_.dist_prog_start = distance_.value_mm(path_.front_covered()) * hli_units_per_mm;
  hli_.path_velocity = path_.path_velocity();
  if (progress == PathProgress::invalid_block) {
    const Block& block = path_.blocks()[*path_.invalid_block()];
    Event e = events_.at_block(Severity::error, "the motion of line " + std::to_string(block.nc_line) +
                                                    " has a length or limit that is not a finite number; "
                                                    "the path stops before it; program aborted");
    e.nc_line = block.nc_line;
    e.block_nr = block.block_nr;
    events_.raise(e);
    hli_.channel_state = ChannelState::error;
  }
  if (progress == PathProgress::setpoint_not_finite) {
    events_.raise(events_.at_block(Severity::error, "the interpolator computed a setpoint that is not a finite number; "
                                                    "the axes hold the last valid setpoint; program aborted"));
    hli_.channel_state = ChannelState::error;
  }
  if (progress == PathProgress::reached_contour_start)
    events_.raise(events_.at_block(Severity::warning, "backward motion reached the start of the stored contour "
                                                      "(program start, or P-STUP-00033 full); it stands there"));
  // The program ends once its last M functions and dwells are done; a
  // decode error stops the channel after every block decoded correctly.
  if (progress == PathProgress::all_blocks_run && !actions_.waiting() && hli_.channel_state != ChannelState::error)
    hli_.channel_state = decode_failed_ ? ChannelState::error : ChannelState::program_end;
}

void Channel::start_short_cut(double t) {
  const DeleteDistanceToGo::Outcome outcome = ddtg_.start_short_cut(path_, t, events_);
  update_hold();
  switch (outcome) {
    case DeleteDistanceToGo::Outcome::short_cut: path_.go_on_from_standstill(t); break;
    case DeleteDistanceToGo::Outcome::no_target: break;
    case DeleteDistanceToGo::Outcome::aborted: hli_.channel_state = ChannelState::error; break;
  }
}

void Channel::change_direction(double t, bool standing) {
  if (!backward_.turn_due(path_.direction(), standing, ddtg_.on_short_cut(), ddtg_.pending(), events_)) return;
  if (!path_.turn(t, backward_.stored_blocks())) return;
  update_hold();
  if (path_.empty() && path_.direction() == TravelDirection::backward)
    events_.raise(events_.at_block(Severity::warning, "backward motion: the stored contour begins here; it stands"));
  path_.go_on_from_standstill(t);
}

void Channel::drive_error(const std::string& axis, const std::string& what) {
  if (error_stop_.begin(axis, what, hli_.channel_state, events_)) update_hold();
}

void Channel::error_stop(const std::string& reason) {
  if (error_stop_.begin_for(reason, "", hli_.channel_state, events_)) update_hold();
}

PathHold Channel::hold() const {
  PathHold hold;
  hold.set(HoldReason::feedhold, hli_.feedhold.state_r);
  hold.set(HoldReason::short_cut_pending, ddtg_.pending());
  hold.set(HoldReason::channel_error, hli_.channel_state == ChannelState::error);
  hold.set(HoldReason::m_function_ack, actions_.waiting_for_acknowledgement());
  hold.set(HoldReason::dwell, actions_.in_dwell());
  hold.set(HoldReason::direction_change, backward_.change_pending(path_.direction()));
  return hold;
}

void Channel::update_hold() { path_.set_velocity_factor(hold().velocity_factor(hli_.override.state_r)); }

void Channel::reach_block(const Block& block, bool run_commands) {
  events_.set_block(block);
  if (!run_commands) return;
  if (actions_.queue(block)) update_hold();
  if (block.distance_prog_start) distance_.apply(*block.distance_prog_start);
}

void Channel::write_state() {
  hli_.cycle = cycle_;
  hli_.block_nr_r = events_.block_nr();
  hli_.block_count_r = events_.block_count();
  hli_.last_error_id = events_.last_error_id();
  hli_.backward_motion.state_r = path_.direction() == TravelDirection::backward;
  ddtg_.write(hli_);
  for (size_t i = 0; i < machine_.axes.size(); ++i)
    hli_.axis_position_r[i] = std::llround(setpoints()[i].position * hli_units_per_mm);
  hli_.program_start.state_r = hli_.channel_state == ChannelState::active;
  hli_.stop_conditions_r = hold().stop_conditions();
  if (hli_.override.state_r == 0) hli_.stop_conditions_r |= stop_condition::override_zero;
  if (hli_.channel_state != ChannelState::active) hli_.stop_conditions_r |= stop_condition::ipo_input_empty;
}

}  // namespace hil::cnc
