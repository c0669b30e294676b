#include "channel.hpp"

#include <cmath>

#include "decoder.hpp"
#include "position_profile.hpp"

namespace hil::cnc {

Channel::Channel(MachineConfig machine, std::string nc_program)
    : machine_(std::move(machine)), nc_program_(std::move(nc_program)),
      setpoints_(machine_.axes.size()) {
  for (const AxisConfig& axis : machine_.axes) hli_.axis_name.push_back(axis.name);
  hli_.axis_position_r.assign(machine_.axes.size(), 0);
  hli_.stop_conditions_r = stop_condition::ipo_input_empty;
}

std::vector<Event> Channel::take_events() {
  std::vector<Event> out;
  out.swap(events_);
  return out;
}

bool Channel::finished() const {
  return hli_.channel_state == ChannelState::program_end || hli_.channel_state == ChannelState::error;
}

void Channel::raise(Event event) {
  if (event.severity == Severity::error) hli_.last_error_id = event.id;
  events_.push_back(std::move(event));
}

void Channel::step(int64_t cycle, const HliControl& control) {
  cycle_ = cycle;
  hli_.cycle = cycle;
  apply_control(control);
  if (hli_.channel_state == ChannelState::active)
    interpolate(static_cast<double>(cycle - start_cycle_) * machine_.cycle_time_s());
  for (size_t i = 0; i < setpoints_.size(); ++i)
    hli_.axis_position_r[i] = std::llround(setpoints_[i].position * hli_units_per_mm);
  hli_.program_start.state_r = hli_.channel_state == ChannelState::active;
  hli_.stop_conditions_r = 0;
  if (hli_.channel_state == ChannelState::error) hli_.stop_conditions_r |= stop_condition::channel_error;
  if (hli_.channel_state != ChannelState::active) hli_.stop_conditions_r |= stop_condition::ipo_input_empty;
}

// Control units act on the rising edge of command_w while enable_w (KRN-4).
void Channel::apply_control(const HliControl& control) {
  const ControlUnitBool& start = control.program_start;
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

void Channel::start_program() {
  std::vector<double> start(setpoints_.size());
  for (size_t i = 0; i < start.size(); ++i) start[i] = setpoints_[i].position;
  DecodedProgram program = decode_program(nc_program_, machine_, start);
  if (program.error) {
    decode_failed_ = true;
    raise(*program.error);  // reported at once; the blocks before it still run
  }
  double t = 0, dist = 0;
  for (Block& block : program.blocks) {
    PlannedBlock planned;
    planned.t_begin = t;
    planned.dist_before = dist;
    if (block.has_motion) {
      planned.segment.emplace_back(block.motion, machine_);
      const PathSegment& seg = planned.segment.front();
      planned.profile = rest_to_rest(seg.length(), seg.limits());
      t += planned.profile.duration();
      dist += seg.length();
    }
    planned.block = std::move(block);
    planned_.push_back(std::move(planned));
  }
  start_cycle_ = cycle_;
  current_ = 0;
  hli_.channel_state = ChannelState::active;
  interpolate(0);
}

void Channel::interpolate(double t) {
  while (current_ < planned_.size() &&
         t >= planned_[current_].t_begin + planned_[current_].profile.duration()) {
    // Leave the block exactly on its programmed end point.
    const PlannedBlock& done = planned_[current_];
    if (!done.segment.empty()) {
      const std::vector<double>& end = done.segment.front().end();
      for (size_t i = 0; i < setpoints_.size(); ++i) setpoints_[i] = {end[i], 0, 0};
      hli_.dist_prog_start = (done.dist_before + done.segment.front().length()) * hli_units_per_mm;
    }
    hli_.block_nr_r = done.block.block_nr;
    hli_.block_count_r = done.block.nc_line;
    hli_.path_velocity = 0;
    ++current_;
  }
  if (current_ >= planned_.size()) {
    // Every block decoded correctly has run; a decode error now stops the channel.
    hli_.channel_state = decode_failed_ ? ChannelState::error : ChannelState::program_end;
    return;
  }
  const PlannedBlock& block = planned_[current_];
  hli_.block_nr_r = block.block.block_nr;
  hli_.block_count_r = block.block.nc_line;
  const PathSegment& seg = block.segment.front();
  const MotionState path = block.profile.at(t - block.t_begin);
  const double s = std::min(std::max(path.p, 0.0), seg.length());
  const std::vector<double> p = seg.position(s), d1 = seg.tangent(s), d2 = seg.curvature(s);
  for (size_t i = 0; i < setpoints_.size(); ++i)
    setpoints_[i] = {p[i], d1[i] * path.v, d1[i] * path.a + d2[i] * path.v * path.v};
  hli_.dist_prog_start = (block.dist_before + s) * hli_units_per_mm;
  hli_.path_velocity = path.v;
}

}  // namespace hil::cnc
