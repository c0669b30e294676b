#include "channel.hpp"

#include <algorithm>
#include <cmath>

#include "decoder.hpp"
#include "m_pre_output.hpp"
#include "position_profile.hpp"
#include "short_cut_target.hpp"

namespace hil::cnc {

Channel::Channel(MachineConfig machine, std::string nc_program)
    : machine_(std::move(machine)), nc_program_(std::move(nc_program)), setpoints_(machine_.axes.size()),
      look_ahead_(machine_) {
  for (const AxisConfig& axis : machine_.axes) hli_.axis_name.push_back(axis.name);
  hli_.axis_position_r.assign(machine_.axes.size(), 0);
  hli_.stop_conditions_r = stop_condition::ipo_input_empty;
  hli_.override.state_r = override_full;
}

std::vector<Event> Channel::take_events() {
  std::vector<Event> out;
  out.swap(events_);
  return out;
}

bool Channel::finished() const {
  return hli_.channel_state == ChannelState::program_end ||
         (hli_.channel_state == ChannelState::error && !error_stop_);
}

void Channel::drive_error(const std::string& axis, const std::string& what) {
  if (hli_.channel_state == ChannelState::error || hli_.channel_state == ChannelState::program_end) return;
  Event e = event_at_block(Severity::error,
                           "channel stopped: drive error on axis " + axis + " (" + what + "); program aborted");
  e.axis = axis;
  raise(e);
  error_stop_ = hli_.channel_state == ChannelState::active;
  hli_.channel_state = ChannelState::error;
  update_velocity_factor();
}

void Channel::update_velocity_factor() {
  const bool stop = hli_.feedhold.state_r || ddtg_requested_ || hli_.channel_state == ChannelState::error ||
                    !synchronous_.empty() || direction_change_pending();
  look_ahead_.set_velocity_factor(stop ? 0.0 : hli_.override.state_r / static_cast<double>(override_full));
  replan_ = true;
}

Event Channel::event_at_block(Severity severity, std::string message) const {
  Event e;
  e.severity = severity;
  e.nc_line = current_nc_line_;
  e.block_nr = hli_.block_nr_r;
  e.message = std::move(message);
  return e;
}

void Channel::raise(Event event) {
  if (event.severity == Severity::error) hli_.last_error_id = event.id;
  events_.push_back(std::move(event));
}

void Channel::step(int64_t cycle, const HliControl& control) {
  cycle_ = cycle;
  hli_.cycle = cycle;
  apply_velocity_control(control);
  apply_delete_distance_to_go(control);
  apply_program_start(control.program_start);
  if (hli_.channel_state == ChannelState::active || error_stop_) {
    const double t = static_cast<double>(cycle - start_cycle_) * machine_.cycle_time_s();
    run_synchronous_actions(control, t);
    interpolate(t);
    const bool standing = look_ahead_.empty() || t - plan_start_ >= plan_.duration();
    if (error_stop_ && standing) error_stop_ = false;
    if (ddtg_requested_ && standing && hli_.channel_state == ChannelState::active) start_short_cut(t);
    if (hli_.channel_state == ChannelState::active) change_direction(t, standing);
  }
  hli_.backward_motion.state_r = backward_;
  hli_.delete_distance_to_go.state_r = ddtg_requested_ || hli_.delete_distance_to_go_active_r;
  for (size_t i = 0; i < setpoints_.size(); ++i)
    hli_.axis_position_r[i] = std::llround(setpoints_[i].position * hli_units_per_mm);
  hli_.program_start.state_r = hli_.channel_state == ChannelState::active;
  hli_.stop_conditions_r = 0;
  if (hli_.feedhold.state_r) hli_.stop_conditions_r |= stop_condition::feedhold;
  if (hli_.override.state_r == 0) hli_.stop_conditions_r |= stop_condition::override_zero;
  if (hli_.channel_state == ChannelState::error) hli_.stop_conditions_r |= stop_condition::channel_error;
  if (hli_.channel_state != ChannelState::active) hli_.stop_conditions_r |= stop_condition::ipo_input_empty;
}

// Control units act on the rising edge of command_w while enable_w (KRN-4).
void Channel::apply_program_start(const ControlUnitBool& start) {
  hli_.program_start.request_r = start.command_w && start.enable_w;
  const bool rising = start.command_w && !previous_start_command_;
  previous_start_command_ = start.command_w;
  if (!rising || !start.enable_w) return;
  if (hli_.channel_state != ChannelState::ready) {
    Event ignored;
    ignored.severity = Severity::warning;
    ignored.message = std::string("program start ignored: channel is ") + to_string(hli_.channel_state);
    raise(ignored);
    return;
  }
  start_program();
}

// Feed hold and override are levels, not edges: they act while they are
// set, and the path is replanned from where it is (KRN-3).
void Channel::apply_velocity_control(const HliControl& control) {
  hli_.feedhold.request_r = control.feedhold.command_w && control.feedhold.enable_w;
  hli_.override.request_r = control.override.enable_w;
  int32_t value = control.override.enable_w ? control.override.command_w : override_full;
  const int32_t highest = machine_.override_max_percent * 10;
  if (value < 0 || value > highest) {
    if (value != previous_override_command_) {
      Event clamped;
      clamped.severity = Severity::warning;
      clamped.value = value / 10.0;
      clamped.limit = value < 0 ? 0 : highest / 10.0;
      clamped.message = "override " + std::to_string(value / 10.0) + " % is outside 0 .. " +
                        std::to_string(machine_.override_max_percent) + " % (override_max_percent); using " +
                        std::to_string(clamped.limit) + " %";
      raise(clamped);
    }
  }
  previous_override_command_ = value;
  value = std::clamp(value, 0, highest);
  // KRN-5: backward_motion is a level. A change of it stops the path, which
  // then goes on the other way (step); without P-STUP-00033 a request only
  // holds the path until it is withdrawn.
  const bool backward = control.backward_motion.command_w && control.backward_motion.enable_w;
  if (backward && !hli_.backward_motion.request_r && machine_.fb_storage_size == 0) {
    Event held = event_at_block(Severity::warning,
                                "backward motion on the path needs P-STUP-00033 fb_storage_size > 0; held until withdrawn");
    held.parameter = "P-STUP-00033";
    raise(held);
  }
  const bool backward_changed = backward != hli_.backward_motion.request_r;
  hli_.backward_motion.request_r = backward;
  const bool hold = hli_.feedhold.request_r;
  if (hold == hli_.feedhold.state_r && value == hli_.override.state_r && !backward_changed) return;
  hli_.feedhold.state_r = hold;
  hli_.override.state_r = value;
  update_velocity_factor();
}

// DDTG-1, DDTG-3: a rising edge of command_w while enable_w stops the path
// for a short cut; command_w cleared before the short cut starts cancels
// it, and the original contour goes on.
void Channel::apply_delete_distance_to_go(const HliControl& control) {
  const ControlUnitBool& unit = control.delete_distance_to_go;
  const bool commanded = unit.command_w && unit.enable_w;
  hli_.delete_distance_to_go.request_r = commanded;
  const bool rising = unit.command_w && !previous_ddtg_command_;
  previous_ddtg_command_ = unit.command_w;
  if (ddtg_requested_ && !commanded) {
    ddtg_requested_ = false;
    update_velocity_factor();
  } else if (rising && commanded && hli_.channel_state == ChannelState::active && !ddtg_requested_) {
    if (machine_.fb_storage_size > 0) {
      ddtg_requested_ = true;
      update_velocity_factor();
    } else {  // DDTG-11
      Event refused = event_at_block(Severity::warning,
                                     "delete distance to go ignored: it needs P-STUP-00033 fb_storage_size > 0");
      refused.parameter = "P-STUP-00033";
      raise(refused);
    }
  }
  // The end marker mask (DDTG-5), in force from the next short cut on.
  const ControlUnitUns32& activation = control.delete_distance_to_go_activation;
  hli_.delete_distance_to_go_activation.request_r = activation.enable_w;
  hli_.delete_distance_to_go_activation.state_r = activation.enable_w ? activation.command_w : 0;
}

void Channel::queue_synchronous_actions(const Block& block) {
  for (const MFunction& m : block.m_functions) synchronous_.push_back({m.nr, 0});
  if (block.dwell_s > 0) synchronous_.push_back({-1, block.dwell_s});
  if (!block.m_functions.empty() || block.dwell_s > 0) update_velocity_factor();
}

void Channel::run_synchronous_actions(const HliControl& control, double t) {
  const ControlUnitBool& ack = control.m_function_ack;
  const bool acknowledged = ack.command_w && ack.enable_w && !previous_m_ack_command_;
  previous_m_ack_command_ = ack.command_w;
  if (synchronous_.empty()) return;
  // Each action done lets the next one start in the same cycle.
  while (!synchronous_.empty()) {
    const SynchronousAction& action = synchronous_.front();
    if (action.m_function >= 0) {
      if (!hli_.m_function_request_r) {
        hli_.m_function_request_r = true;  // output; acknowledged in a later cycle
        hli_.m_function_nr_r = action.m_function;
        return;
      }
      if (!acknowledged) return;
      hli_.m_function_request_r = false;
    } else {
      if (dwell_end_ < 0) dwell_end_ = t + action.dwell_s;
      if (t < dwell_end_ - 1e-9) return;
      dwell_end_ = -1;
    }
    synchronous_.pop_front();
  }
  update_velocity_factor();
}

void Channel::start_short_cut(double t) {
  if (backward_) {
    start_backward_short_cut(t);
    return;
  }
  ddtg_requested_ = false;
  // The rest of the front block is dropped; what lies between it and the
  // target (non-motion blocks) runs at the stop position, before the short cut.
  const StopPoint stop = leave_front(t);
  const uint32_t mask = static_cast<uint32_t>(hli_.delete_distance_to_go_activation.state_r);
  const ShortCutTarget found = short_cut_target(blocks_, stop.block, mask);
  next_to_run_ = std::max(next_to_run_, stop.block + 1);  // after backward motion: ran already
  if (found.not_skippable) {  // DDTG-8: the path stays where it stopped
    const Block& command = blocks_[*found.not_skippable];
    Event refused = event_at_block(Severity::error, "delete distance to go in line " +
                                                        std::to_string(current_nc_line_) +
                                                        " must not skip the command in line " +
                                                        std::to_string(command.nc_line) + "; program aborted");
    refused.id = 51016;
    refused.nc_line = command.nc_line;
    refused.block_nr = command.block_nr;
    raise(refused);
    hli_.channel_state = ChannelState::error;
    next_to_look_ahead_ = next_to_run_ = blocks_.size();
    return;
  }
  if (found.channel_initialisation) {  // DDTG-8: the short cut ends before it
    const Block& command = blocks_[*found.channel_initialisation];
    Event ended = event_at_block(Severity::warning, "delete distance to go in line " +
                                                        std::to_string(current_nc_line_) + ": the command in line " +
                                                        std::to_string(command.nc_line) +
                                                        " needs channel initialisation; the short cut ends before it");
    ended.id = 51036;
    ended.nc_line = command.nc_line;
    ended.block_nr = command.block_nr;
    raise(ended);
  }
  if (!found.target) {  // DDTG-6: no motion block left to short-cut to
    Event none = event_at_block(
        Severity::warning, mask == 0 ? "delete distance to go: no further motion block; motion ends at the stop position"
                                     : "delete distance to go: no #DEL DIST2GO end marker valid for activation " +
                                           std::to_string(mask) + " before program end; motion ends at the stop position");
    none.id = 50810;
    raise(none);
    next_to_look_ahead_ = blocks_.size();
    return;
  }
  const size_t target = *found.target;
  next_to_look_ahead_ = target + 1;
  run_short_cut(stop, target, blocks_[target].motion.end, t);
}

Channel::StopPoint Channel::leave_front(double t) {
  const LookAheadBlock& front = look_ahead_.front();
  StopPoint stop;
  stop.block = front.block_index;
  stop.front_length = front.segment.length();
  stop.s = std::clamp(path_state_at(t).p, 0.0, stop.front_length);
  stop.rapid = on_short_cut() ? short_cut_rapid_ : blocks_[stop.block].motion.type == MotionType::rapid;
  stop.position = setpoint_positions();
  if (dps_counting_ && stop.front_length > 0)
    dps_before_front_ += direction_sign() * front.segment.covered_distance() * stop.s / stop.front_length;
  look_ahead_.clear();
  hli_.delete_distance_to_go_active_r = false;
  update_velocity_factor();
  return stop;
}

void Channel::run_short_cut(const StopPoint& stop, size_t target, const std::vector<double>& end, double t) {
  Motion cut;
  cut.type = stop.rapid ? MotionType::rapid : MotionType::linear;  // DDTG-2: linear, G00 if the interrupted block was
  cut.start = stop.position;
  cut.end = end;
  cut.feed = blocks_[target].motion.feed > 0 ? blocks_[target].motion.feed : blocks_[stop.block].motion.feed;
  PathSegment segment(cut, machine_);
  if (segment.length() > 0) {
    look_ahead_.push(target, std::move(segment), blocks_[target].slope);
    short_cut_target_ = target;
    short_cut_rapid_ = stop.rapid;
    hli_.delete_distance_to_go_active_r = true;
  }
  go_on_from_standstill(t);
}

void Channel::go_on_from_standstill(double t) {
  refill_look_ahead();
  if (!look_ahead_.empty()) begin_front({}, t);
  replan_ = false;
}

std::vector<double> Channel::setpoint_positions() const {
  std::vector<double> positions(setpoints_.size());
  for (size_t i = 0; i < positions.size(); ++i) positions[i] = setpoints_[i].position;
  return positions;
}

void Channel::start_program() {
  DecodedProgram program = decode_program(nc_program_, machine_, setpoint_positions());
  if (program.error) {
    decode_failed_ = true;
    raise(*program.error);  // reported at once; the blocks before it still run
  }
  std::vector<Event> warnings;
  blocks_ = apply_m_pre_output(std::move(program.blocks), machine_, warnings);
  for (Event& warning : warnings) raise(std::move(warning));
  start_cycle_ = cycle_;
  hli_.channel_state = ChannelState::active;
  go_on_from_standstill(0);
  interpolate(0);
}

void Channel::refill_look_ahead() {
  if (backward_) {
    refill_backward();
    return;
  }
  for (; !look_ahead_.full() && next_to_look_ahead_ < blocks_.size(); ++next_to_look_ahead_) {
    const Block& block = blocks_[next_to_look_ahead_];
    if (!block.has_motion) continue;
    // M functions, a dwell or a channel initialisation on its line or since
    // the last motion block: the path stands still where it starts.
    bool stop_before = false;
    for (size_t i = next_to_look_ahead_ + 1; i-- > 0;) {
      if (i < next_to_look_ahead_ && blocks_[i].has_motion) break;
      stop_before = stop_before || blocks_[i].stops_path();
    }
    if (next_to_look_ahead_ < blocks_begun_) stop_before = false;  // forward again after backward motion: ran already
    look_ahead_.push(next_to_look_ahead_, PathSegment(block.motion, machine_), block.slope, stop_before);
  }
}

void Channel::begin_front(const MotionState& state, double t0) {
  const LookAheadBlock& front = look_ahead_.front();
  run_blocks_without_motion(front.block_index);
  const Block& block = blocks_[front.block_index];
  hli_.block_nr_r = block.block_nr;
  hli_.block_count_r = block.block_count;
  current_nc_line_ = block.nc_line;
  if (!backward_ && front.block_index >= blocks_begun_) {
    queue_synchronous_actions(block);  // its M functions go out before its motion (MVS_SVS)
    blocks_begun_ = front.block_index + 1;
  }
  plan(state, t0);
}

// Replanning from a state on the plan continues it (the planner is
// time-optimal, so its tail is too); it is done at every block transition,
// where the look-ahead has seen one block more, and when override or feed
// hold change.
void Channel::plan(const MotionState& state, double t0) {
  const Stretch st = look_ahead_.stretch(state.v);
  plan_ = block_profile(state, st.length, st.v_end, st.lim, st.slope);
  plan_start_ = t0;
}

void Channel::finish_front() {
  const LookAheadBlock& front = look_ahead_.front();
  if (dps_counting_) dps_before_front_ += direction_sign() * front.segment.covered_distance();
  if (hli_.delete_distance_to_go_active_r && front.block_index == short_cut_target_)
    hli_.delete_distance_to_go_active_r = false;  // DDTG-4: the short cut is done
  if (!backward_) next_to_run_ = std::max(next_to_run_, front.block_index + 1);
  last_finished_block_ = front.block_index;
  look_ahead_.pop_front();
  refill_look_ahead();
}

// #DISTANCE PROG START and M30 act when the interpolator reaches them.
void Channel::run_blocks_without_motion(size_t up_to) {
  for (; next_to_run_ < up_to; ++next_to_run_) {
    const Block& block = blocks_[next_to_run_];
    hli_.block_nr_r = block.block_nr;
    hli_.block_count_r = block.block_count;
    current_nc_line_ = block.nc_line;
    queue_synchronous_actions(block);
    if (!block.distance_prog_start) continue;
    switch (*block.distance_prog_start) {
      case DistanceProgStart::on: dps_counting_ = true; break;
      case DistanceProgStart::off: dps_counting_ = false; break;
      case DistanceProgStart::clear: dps_before_front_ = 0; break;
    }
  }
}

MotionState Channel::path_state_at(double t) const { return plan_.at(t - plan_start_); }

void Channel::interpolate(double t) {
  if (!look_ahead_.empty() && replan_) plan(path_state_at(t), t);
  replan_ = false;
  MotionState path = path_state_at(t);
  // Pass every block the path has left by t; a plan that ends short of the
  // block end (feed hold, override 0) waits there.
  while (!look_ahead_.empty()) {
    const double length = look_ahead_.front().segment.length();
    const bool plan_ended = t - plan_start_ >= plan_.duration();
    if (path.p < length && !(plan_ended && path.p >= length - 1e-9 * (1 + length))) break;
    const std::vector<double> end_point = look_ahead_.front().segment.end();
    finish_front();
    if (look_ahead_.empty()) {
      // Leave the last block exactly on its programmed end point.
      for (size_t i = 0; i < setpoints_.size(); ++i) setpoints_[i] = {end_point[i], 0, 0};
      if (backward_)
        raise(event_at_block(Severity::warning, "backward motion reached the start of the stored contour "
                                                "(program start, or P-STUP-00033 full); it stands there"));
      break;
    }
    // Go on from where the path left the block: at t, or where a plan that
    // ended on the block end (a limiting transition) ended.
    double t_from = t;
    if (plan_ended) {
      t_from = plan_start_ + plan_.duration();
      path = plan_.end();
    }
    path.p -= length;
    begin_front(path, t_from);
    path = path_state_at(t);
  }
  if (look_ahead_.empty() && backward_) {  // stands where the stored contour begins
    hli_.dist_prog_start = dps_before_front_ * hli_units_per_mm;
    hli_.path_velocity = 0;
    return;
  }
  if (look_ahead_.empty()) {
    // Every block decoded correctly has run; a decode error now stops the channel.
    run_blocks_without_motion(blocks_.size());
    hli_.dist_prog_start = dps_before_front_ * hli_units_per_mm;
    hli_.path_velocity = 0;
    if (!synchronous_.empty()) return;  // the program ends once its last M functions and dwells are done
    if (hli_.channel_state != ChannelState::error)
      hli_.channel_state = decode_failed_ ? ChannelState::error : ChannelState::program_end;
    return;
  }
  if (t - plan_start_ >= plan_.duration()) path.v = path.a = 0;  // held short of the block end
  output(path);
}

void Channel::output(const MotionState& path) {
  const PathSegment& seg = look_ahead_.front().segment;
  const double s = std::clamp(path.p, 0.0, seg.length());
  const std::vector<double> p = seg.position(s), d1 = seg.tangent(s), d2 = seg.curvature(s);
  for (size_t i = 0; i < setpoints_.size(); ++i)
    setpoints_[i] = {p[i], d1[i] * path.v, d1[i] * path.a + d2[i] * path.v * path.v};
  const double covered = dps_counting_ ? seg.covered_distance() * s / seg.length() : 0.0;
  hli_.dist_prog_start = (dps_before_front_ + direction_sign() * covered) * hli_units_per_mm;
  hli_.path_velocity = path.v;
}

}  // namespace hil::cnc
