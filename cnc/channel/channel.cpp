#include "channel.hpp"

#include <cmath>
#include <string>


namespace hil::cnc {

Channel::Channel(MachineConfig machine, std::string nc_program)
    : Channel(std::move(machine), program_text(std::move(nc_program))) {}

Channel::Channel(MachineConfig machine, ProgramText nc_program)
    : machine_(std::move(machine)), nc_program_(std::move(nc_program)),
      run_(std::in_place, machine_, static_cast<PathObserver&>(*this)), feed_(machine_.override_max_percent),
      ddtg_(machine_), backward_(machine_), setpoints_(run_->path.setpoints()) {
  for (const AxisConfig& axis : machine_.axes) hli_.axis_name.push_back(axis.name);
  hli_.axis_position_r.assign(machine_.axes.size(), 0);
  hli_.lift_active.assign(machine_.axes.size(), false);
  hli_.lift_suppressed.assign(machine_.axes.size(), false);
  hli_.stop_conditions_r = stop_condition::ipo_input_empty;
  hli_.override.state_r = override_full;
  zero_offsets_ = machine_.zero_offsets;
}

bool Channel::finished() const {
  return hli_.channel_state == ChannelState::program_end ||
         (hli_.channel_state == ChannelState::error && !run_->error_stop.stopping());
}

void Channel::step(int64_t cycle, const HliControl& control) {
  cycle_ = cycle;
  apply_control(control);
  if (moving()) run_path(control, time_s());
  write_state();
}

void Channel::apply_control(const HliControl& control) {
  const bool feed_changed = feed_.apply(control, hli_, events_);
  const bool backward_changed = backward_.apply(control.backward_motion, hli_, events_);
  if (feed_changed || backward_changed) update_hold();
  if (ddtg_.apply(control, hli_.channel_state == ChannelState::active, hli_, events_)) update_hold();
  if (run_->insert.take(control.insert_cmd, hli_)) update_hold();
  if (programmed_stop_.apply(control, hli_)) {  // continue motion (ISC-5)
    if (run_->insert.at_mark()) leave_insert_mark(time_s());
    update_hold();
  }
  apply_reset(control.reset);
  // KRN-8: the skip levels in force for the lines the decoder reads from now on.
  const ControlUnitUns32& ignore = control.program_block_ignore;
  hli_.program_block_ignore.request_r = ignore.enable_w;
  hli_.program_block_ignore.state_r = ignore.enable_w ? ignore.command_w : 0;
  if (run_->program) run_->program->set_block_ignore(hli_.program_block_ignore.state_r);
  apply_zero_offset(control.zero_offset);
  apply_program_start(control);
}

void Channel::apply_zero_offset(const ControlUnitZeroOffset& write) {
  if (!write.enable_w || write.command_w == last_zero_offset_write_) return;
  last_zero_offset_write_ = write.command_w;
  const ZeroOffsetCommand& c = write.command_w;
  const double mm = c.value / hli_units_per_mm;
  if (c.group < 1 || c.group > zero_offsets_.size() || c.axis_nr < 1 || c.axis_nr > machine_.axes.size() ||
      !(std::abs(mm) <= 1e6)) {
    Event refused;
    refused.severity = Severity::warning;
    refused.message = "zero offset write refused: group " + std::to_string(c.group) + " (1..6 = G54..G59), axis_nr " +
                      std::to_string(c.axis_nr) + " (1.." + std::to_string(machine_.axes.size()) + "), value " +
                      std::to_string(c.value) + " x 0.1 um (|value| <= 1 km)";
    events_.raise(refused);
    return;
  }
  zero_offsets_[c.group - 1][c.axis_nr - 1] = mm;
  if (run_->program) run_->program->set_zero_offsets(zero_offsets_);
}

// KRN-4: control units act on the rising edge of command_w while enable_w.
void Channel::apply_program_start(const HliControl& control) {
  const ControlUnitBool& start = control.program_start;
  hli_.program_start.request_r = start.command_w && start.enable_w;
  hli_.block_search.request_r = control.block_search.enable_w;
  if (!program_start_(start.command_w) || !start.enable_w) return;
  if (hli_.channel_state != ChannelState::ready) {
    Event ignored;
    ignored.severity = Severity::warning;
    ignored.message = std::string("program start ignored: channel is ") + to_string(hli_.channel_state);
    events_.raise(ignored);
    return;
  }
  start_program(control.block_search);
}

// The path stands: the program is aborted there, every unit of its run
// starts anew; the PLC's levels (feed hold, override) stay.
void Channel::apply_reset(const ControlUnitBool& reset) {
  hli_.reset.request_r = reset.command_w && reset.enable_w;
  hli_.reset.state_r = false;
  if (!reset_(reset.command_w) || !reset.enable_w) return;
  if (hli_.channel_state == ChannelState::active || run_->error_stop.stopping()) {
    if (!run_->path.standing(time_s()) || run_->error_stop.stopping() || run_->lift.positioning()) {
      Event ignored = events_.at_block(Severity::warning, "reset ignored: the path moves (stop it first, feed hold)");
      events_.raise(ignored);
      return;
    }
  }
  // The path stands, but an Advanced Lifting axis still moves in time (LIFT-2):
  // a reset there would stop it dead, beyond its acceleration and jerk.
  // Round-off (1e-14 mm/s) is no motion: stopping 1 um/s in a cycle (1e-3 mm/s) is far within any limit.
  for (const AxisSetpoint& axis : setpoints_)
    if (std::abs(axis.velocity) > 1e-3 || std::abs(axis.acceleration) > 1e-3) {
      Event ignored = events_.at_block(Severity::warning, "reset ignored: an axis moves (the lift axis lifts or lands)");
      events_.raise(ignored);
      return;
    }
  begin_program_run();
  hli_.reset.state_r = true;
}

void Channel::begin_program_run() {
  const std::vector<AxisSetpoint> standing = setpoints_;
  run_.emplace(machine_, static_cast<PathObserver&>(*this));  // the aborted run's stream with it
  for (size_t i = 0; i < standing.size(); ++i) run_->path.place_axis(i, standing[i].position);
  setpoints_ = run_->path.setpoints();
  ddtg_.abort();
  actions_.abort();
  programmed_stop_.abort();
  enter(ChannelState::ready);
  hli_.block_search.state_r = BlockSearchState();
  hli_.dist_prog_start = 0;
  hli_.path_velocity = 0;
  hli_.m_function_request_r = hli_.h_function_request_r = hli_.s_function_request_r = hli_.t_function_request_r =
      false;
  update_hold();
}

void Channel::start_program(const ControlUnitBlockSearch& search) {
  std::vector<double> start_position;  // a lift axis parked by the last program's lift included
  for (const AxisSetpoint& setpoint : setpoints_) start_position.push_back(setpoint.position);
  run_->lift.begin_program();
  run_->program = std::make_unique<ProgramStream>(nc_program_, machine_, start_position,
                                                  [this](LiftRange range) { run_->lift.add_range(std::move(range)); });
  run_->program->set_block_ignore(hli_.program_block_ignore.state_r);
  run_->program->set_zero_offsets(zero_offsets_);
  hli_.block_search.state_r = BlockSearchState();
  if (search.enable_w && !search_continuation(search)) {
    take_stream_events();
    run_->decode_failed = false;  // the program did not start: the channel stays READY
    run_->program.reset();
    return;
  }
  run_->path.load(run_->program->blocks(), backward_.stored_blocks());
  run_->backward_refused = false;
  start_cycle_ = cycle_;
  enter(ChannelState::active);
  // Commanded before the start (ISC-6).
  if (run_->insert.pending()) run_->insert.set_pending(run_->path, 0, distance_mm(), events_);
  run_->path.go_on_from_standstill(0);
  update_hold();
  interpolate(0);
}

// Decoding goes on as the path needs blocks: an error is reported when the
// stream meets it (the blocks before it still run), not at program start.
void Channel::take_stream_events() {
  if (!run_->program) return;
  if (std::optional<Event> error = run_->program->take_error()) {
    run_->decode_failed = true;
    events_.raise(std::move(*error));
  }
  for (Event& warning : run_->program->take_warnings()) events_.raise(std::move(warning));
}

void Channel::run_path(const HliControl& control, double t) {
  if (actions_.run(control, t, hli_)) update_hold();
  run_->distance.actions_done(actions_.done());  // DPS-2: a #DISTANCE PROG START after them
  // M<n> of an insert stop mark acknowledged (ISC-5).
  if (run_->insert.at_mark() && !programmed_stop_.stopped() && !actions_.waiting()) leave_insert_mark(t);
  interpolate(t);
  const bool standing = run_->path.standing(t);
  // The error stop ends when the path and an Advanced Lifting axis braking on its own stand (LIFT-2).
  if (run_->error_stop.stopping()) run_->error_stop.update(standing && !run_->lift.positioning());
  on_standstill(t, standing);
}

// What acts where the path stands, in this order: an insert command is set
// where the path stands before a short cut leaves that place (ISC-6,
// DDTG-4), and a turn comes last (KRN-5: it waits for the path to stand,
// and for a short cut asked for to be done). Each acts on the standstill
// the cycle began with; the turn asks anew, after the others may have
// moved the path on.
void Channel::on_standstill(double t, bool standing) {
  const auto active = [this] { return hli_.channel_state == ChannelState::active; };
  if (standing && active() && run_->insert.pending()) set_insert_command(t);
  if (standing && active() && ddtg_.pending()) start_short_cut(t);
  if (active()) change_direction(t, run_->path.standing(t));
}

bool Channel::search_continuation(const ControlUnitBlockSearch& search) {
  BlockSearchState& state = hli_.block_search.state_r;
  BlockSearchRequest request;
  request.type = static_cast<int>(search.command_w.type);
  request.block_nr = search.command_w.block_nr;
  request.distance_mm = search.command_w.distance / hli_units_per_mm;
  size_t continuation = 0;
  BlockSearchOutcome outcome = run_->program->search(request, continuation);
  take_stream_events();  // a decode error before the searched block comes first
  if (!outcome.continuation) {
    if (outcome.error) events_.raise(*outcome.error);
    state.state = block_search_state::error;
    return false;
  }
  const Continuation& c = *outcome.continuation;
  if (c.warning) events_.raise(*c.warning);
  state.state = block_search_state::repositioning;
  state.continuation_moved = c.warning.has_value();
  state.continuation_block_nr = static_cast<uint32_t>(c.block_nr);
  state.continuation_nc_line = c.nc_line;
  state.continuation_distance = c.distance_mm * hli_units_per_mm;
  run_->continuation_block = continuation;
  run_->distance.preset(c.distance_mm, c.distance_counting);
  return true;
}

double Channel::distance_mm() const { return run_->distance.value_mm(run_->path.front_covered()); }

// ISC-6: the path stands (stopped briefly if it moved): the mark is set,
// and the path goes on to it; one at the current distance is reached now.
void Channel::set_insert_command(double t) {
  if (run_->insert.set_pending(run_->path, t, distance_mm(), events_)) run_->path.go_on_from_standstill(t);
  update_hold();
  if (run_->insert.reached(run_->path, t)) reach_insert_mark(t);
}

// ISC-5, ISC-7: the mark's M function.
void Channel::reach_insert_mark(double t) {
  run_->insert.begin_stop();
  const InsertCommand& c = run_->insert.command();
  if (c.m_function_nr <= 1) {
    if (!programmed_stop_.begin(c.m_function_nr)) {  // M01 while m01_stop_enable is not set: on
      leave_insert_mark(t);
      return;
    }
  } else {
    actions_.queue_m_function(c.m_function_nr, c.add_nr);
  }
  update_hold();
}

void Channel::leave_insert_mark(double t) {
  if (run_->insert.leave(run_->path, t, distance_mm())) run_->path.go_on_from_standstill(t);
  update_hold();
}

void Channel::interpolate(double t) {
  const PathProgress progress = run_->path.interpolate(t);
  take_stream_events();
  if (progress == PathProgress::all_blocks_run || progress == PathProgress::invalid_block) run_->lift.all_blocks_run();
  setpoints_ = run_->path.setpoints();
  if (run_->lift.update(run_->path, t, hli_.override.state_r, setpoints_)) update_hold();
  if (run_->lift.take_missed_landing()) {
    events_.raise(events_.at_block(Severity::error, "lift function: the path left the lift range before the lift "
                                                    "axis had landed on POS"));
    enter(ChannelState::error);
  }
  hli_.dist_prog_start = run_->distance.value_mm(run_->path.front_covered()) * hli_units_per_mm;
  hli_.path_velocity = run_->path.path_velocity();
  if (progress == PathProgress::invalid_block) {
    const Block& block = run_->path.blocks()[*run_->path.invalid_block()];
    Event e = events_.at_block(Severity::error, "the motion of line " + std::to_string(block.nc_line) +
                                                    " has a length or limit that is not a finite number; "
                                                    "the path stops before it; program aborted");
    e.nc_line = block.nc_line;
    e.block_nr = block.block_nr;
    events_.raise(e);
    enter(ChannelState::error);
  }
  if (progress == PathProgress::setpoint_not_finite) {
    events_.raise(events_.at_block(Severity::error, "the interpolator computed a setpoint that is not a finite number; "
                                                    "the axes hold the last valid setpoint; program aborted"));
    enter(ChannelState::error);
  }
  if (progress == PathProgress::reached_contour_start)
    events_.raise(events_.at_block(Severity::warning, "backward motion reached the start of the stored contour "
                                                      "(program start, or P-STUP-00033 full); it stands there"));
  if (hli_.channel_state == ChannelState::active && run_->insert.reached(run_->path, t)) reach_insert_mark(t);
  // The program ends once its last M functions and dwells are done, and no
  // stop (M00, M01, an insert stop mark at the end) holds it; a decode
  // error stops the channel after every block decoded correctly.
  if (progress == PathProgress::all_blocks_run && !holds_program_end() && hli_.channel_state != ChannelState::error)
    enter(run_->decode_failed ? ChannelState::error : ChannelState::program_end);
  if (hli_.channel_state == ChannelState::program_end || hli_.channel_state == ChannelState::error)
    run_->insert.program_end();
}

// The one place channel_state changes.
void Channel::enter(ChannelState state) { hli_.channel_state = state; }

void Channel::start_short_cut(double t) {
  run_->lift.land_now(run_->path);  // in a lift range: the lift axis lands first, the path waits
  run_->insert.before_short_cut(run_->path, t, distance_mm());
  const DeleteDistanceToGo::Outcome outcome = ddtg_.start_short_cut(run_->path, t, events_);
  update_hold();
  switch (outcome) {
    case DeleteDistanceToGo::Outcome::short_cut: run_->path.go_on_from_standstill(t); break;
    case DeleteDistanceToGo::Outcome::no_target: break;
    case DeleteDistanceToGo::Outcome::aborted: enter(ChannelState::error); break;
  }
}

void Channel::change_direction(double t, bool standing) {
  if (!backward_.turn_due(run_->path.direction(), standing, ddtg_.on_short_cut(), ddtg_.pending(), events_)) return;
  if (run_->path.direction() == TravelDirection::forward && !run_->path.empty() &&
      run_->lift.forbids_backward(run_->path.front_index())) {
    if (!run_->backward_refused)
      events_.raise(events_.at_block(Severity::warning, "backward motion is not available at or after a lift range "
                                                        "(LIFT-1): the path stands until backward motion is withdrawn"));
    run_->backward_refused = true;
    return;
  }
  run_->insert.before_turn(run_->path, t, distance_mm());  // ISC-9
  if (!run_->path.turn(t, backward_.stored_blocks())) return;
  update_hold();
  if (run_->path.empty() && run_->path.direction() == TravelDirection::backward)
    events_.raise(events_.at_block(Severity::warning, "backward motion: the stored contour begins here; it stands"));
  run_->path.go_on_from_standstill(t);
}

void Channel::drive_error(const std::string& axis, const std::string& what) {
  if (run_->error_stop.begin(axis, what, hli_.channel_state, events_)) {
    enter(ChannelState::error);
    run_->lift.stop_now();
    update_hold();
  }
}

void Channel::error_stop(const std::string& reason) {
  if (run_->error_stop.begin_for(reason, "", hli_.channel_state, events_)) {
    enter(ChannelState::error);
    run_->lift.stop_now();
    update_hold();
  }
}

void Channel::reach_block(const Block& block, size_t index, bool run_commands) {
  events_.set_block(block);
  if (run_->continuation_block && index >= *run_->continuation_block) run_->continuation_reached = true;  // DPS-3
  if (!run_commands) return;
  run_->lift.reach_block(index, hli_.override.state_r);
  update_hold();
  const uint64_t actions_before = actions_.queued();  // of the blocks before this one
  if (actions_.queue(block)) update_hold();
  if (block.distance_prog_start) run_->distance.command(*block.distance_prog_start, actions_before, actions_.done());
  if (block.programmed_stop && programmed_stop_.begin(*block.programmed_stop)) update_hold();  // M00 / M01
  if (block.insert_cmd) {  // ISC-8: set where the path stands, at this line
    run_->insert.program_command(*block.insert_cmd);
    update_hold();
  }
}

void Channel::write_state() {
  hli_.cycle = cycle_;
  hli_.block_nr_r = events_.block_nr();
  hli_.block_count_r = events_.block_count();
  hli_.last_error_id = events_.last_error_id();
  hli_.backward_motion.state_r = run_->path.direction() == TravelDirection::backward;
  ddtg_.write(hli_);
  run_->insert.write(hli_, run_->path);
  for (size_t i = 0; i < machine_.axes.size(); ++i)  // a modulo axis within its range (KRN-7)
    hli_.axis_position_r[i] = std::llround(machine_.axes[i].in_modulo_range(setpoints()[i].position) * hli_units_per_mm);
  for (size_t i = 0; i < machine_.axes.size(); ++i) {  // LIFT-7
    hli_.lift_active[i] = run_->lift.active(i);
    hli_.lift_suppressed[i] = run_->lift.suppressed(i);
  }
  hli_.program_start.state_r = hli_.channel_state == ChannelState::active;
  // DPS-3: repositioned once on the continuation's block with the collected M functions acknowledged.
  if (run_->continuation_reached && !actions_.waiting()) {
    hli_.block_search.state_r.state = block_search_state::continued;
    run_->continuation_block.reset();
    run_->continuation_reached = false;
  }
  hli_.stop_conditions_r =
      hold().stop_conditions() | programmed_stop_.stop_conditions() | run_->insert.stop_conditions();
  if (hli_.override.state_r == 0) hli_.stop_conditions_r |= stop_condition::override_zero;
  if (hli_.channel_state != ChannelState::active) hli_.stop_conditions_r |= stop_condition::ipo_input_empty;
}

}  // namespace hil::cnc
