#include "drive_error_stop.hpp"

namespace hil::cnc {

bool DriveErrorStop::begin(const std::string& axis, const std::string& what, ChannelState& state,
                           ChannelEvents& events) {
  if (state == ChannelState::error || state == ChannelState::program_end) return false;
  Event e = events.at_block(Severity::error,
                            "channel stopped: drive error on axis " + axis + " (" + what + "); program aborted");
  e.axis = axis;
  events.raise(e);
  stopping_ = state == ChannelState::active;
  state = ChannelState::error;
  return true;
}

}  // namespace hil::cnc
