#include "backward_motion.hpp"

namespace hil::cnc {

bool BackwardMotion::apply(const ControlUnitBool& unit, HliState& hli, ChannelEvents& events) {
  const bool backward = unit.command_w && unit.enable_w;
  if (backward && !requested_ && machine_.fb_storage_size == 0) {
    Event held = events.at_block(Severity::warning,
                                 "backward motion on the path needs P-STUP-00033 fb_storage_size > 0; held until withdrawn");
    held.parameter = "P-STUP-00033";
    events.raise(held);
  }
  const bool changed = backward != requested_;
  requested_ = backward;
  hli.backward_motion.request_r = backward;
  return changed;
}

bool BackwardMotion::turn_due(TravelDirection direction, bool standing, bool on_short_cut, bool short_cut_pending,
                              ChannelEvents& events) {
  if (!change_pending(direction)) {
    refusal_warned_ = false;
    return false;
  }
  if (!on_short_cut) return standing && !short_cut_pending && machine_.fb_storage_size > 0;
  // DDTG-10: not on a short cut; it stands until the request is taken back.
  if (refusal_warned_) return false;
  const bool backward = direction == TravelDirection::backward;
  Event held = events.at_block(Severity::warning, backward ? "forward motion is not possible on a backward delete "
                                                             "distance to go short cut; held until backward motion "
                                                             "is requested again"
                                                           : "backward motion is not possible on a delete distance "
                                                             "to go short cut; held until withdrawn");
  held.id = 50729;
  events.raise(held);
  refusal_warned_ = true;
  return false;
}

size_t BackwardMotion::stored_blocks() const { return static_cast<size_t>(machine_.fb_storage_size) / sizeof(Block); }

}  // namespace hil::cnc
