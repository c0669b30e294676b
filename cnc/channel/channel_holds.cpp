// What holds the channel's path (the hold's reasons, each from its unit)
// and what holds its program end: one list each.
#include "channel.hpp"

namespace hil::cnc {

PathHold Channel::hold() const {
  PathHold hold;
  hold.set(HoldReason::feedhold, hli_.feedhold.state_r);
  hold.set(HoldReason::short_cut_pending, ddtg_.pending());
  hold.set(HoldReason::channel_error, hli_.channel_state == ChannelState::error);
  hold.set(HoldReason::m_function_ack, actions_.waiting_for_acknowledgement());
  hold.set(HoldReason::dwell, actions_.in_dwell());
  hold.set(HoldReason::direction_change, backward_.change_pending(run_->path.direction()));
  hold.set(HoldReason::insert_command, run_->insert.pending() && hli_.channel_state == ChannelState::active);
  hold.set(HoldReason::programmed_stop, programmed_stop_.stopped());
  hold.set(HoldReason::lift_positioning, run_->lift.holds_path());
  return hold;
}

void Channel::update_hold() {
  run_->path.set_velocity_factor(hold().velocity_factor(run_->lift.override_cap(hli_.override.state_r)));  // LIFT-8
}

// The units that hold the program's end while all its blocks have run.
bool Channel::holds_program_end() const {
  return actions_.waiting()            // its last M functions and dwells
         || programmed_stop_.stopped()  // M00 / M01 (ISC-5)
         || run_->insert.at_mark() || run_->insert.pending()  // an insert stop mark at the end (ISC-3 .. ISC-7)
         || run_->lift.running();            // a lift range runs or waits to (LIFT-1)
}

}  // namespace hil::cnc
