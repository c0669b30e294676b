#pragma once
// Backward motion on the path (KRN-5): `backward_motion` is a level. A
// change of it holds the path; standing, the path turns and runs the stored
// contour the other way — the original programmed motion blocks run so
// far, never a short cut, as many as P-STUP-00033 fb_storage_size holds
// (a block takes sizeof(Block) bytes). Commands run once: not backward,
// and not again forward over blocks run before (PathInterpolator). No turn
// on a delete distance to go short cut (DDTG-10, warning 50729).
// Reads: backward_motion.command_w/enable_w.
// Writes: backward_motion.request_r, backward_motion.state_r (moving, or
// set to move, backward).
#include <cstddef>

#include "channel_events.hpp"
#include "hli.hpp"
#include "machine_config.hpp"
#include "path_interpolator.hpp"

namespace hil::cnc {

class BackwardMotion {
 public:
  explicit BackwardMotion(const MachineConfig& machine) : machine_(machine) {}
  // True if the request changed. Without P-STUP-00033 a request only holds
  // the path until withdrawn, with a warning.
  bool apply(const ControlUnitBool& unit, HliState& hli, ChannelEvents& events);
  // The request differs from the direction the path moves in.
  bool change_pending(TravelDirection direction) const {
    return requested_ != (direction == TravelDirection::backward);
  }
  // Each cycle: the path may turn now (it stands, no short cut pending). On
  // a short cut it may not: 50729, once per request.
  bool turn_due(TravelDirection direction, bool standing, bool on_short_cut, bool short_cut_pending,
                ChannelEvents& events);
  // How many motion blocks P-STUP-00033 holds.
  size_t stored_blocks() const;

 private:
  const MachineConfig& machine_;
  bool requested_ = false;
  bool refusal_warned_ = false;  // 50729 raised for the pending direction change
};

}  // namespace hil::cnc
