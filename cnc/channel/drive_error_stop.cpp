#include "drive_error_stop.hpp"

namespace hil::cnc {

bool DriveErrorStop::begin_for(const std::string& reason, const std::string& axis, ChannelState state,
                               ChannelEvents& events) {
  if (state == ChannelState::error || state == ChannelState::program_end) return false;
  Event e = events.at_block(Severity::error, "channel stopped: " + reason + "; program aborted");
  e.axis = axis;
  events.raise(e);
  stopping_ = state == ChannelState::active;
  return true;
}

}  // namespace hil::cnc
