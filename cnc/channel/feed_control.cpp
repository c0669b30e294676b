#include "feed_control.hpp"

#include <algorithm>
#include <string>

namespace hil::cnc {

bool FeedControl::apply(const HliControl& control, HliState& hli, ChannelEvents& events) {
  hli.feedhold.request_r = control.feedhold.command_w && control.feedhold.enable_w;
  hli.override.request_r = control.override.enable_w;
  int32_t value = control.override.enable_w ? control.override.command_w : override_full;
  if ((value < 0 || value > highest_) && value != previous_override_command_) {
    Event clamped;
    clamped.severity = Severity::warning;
    clamped.value = value / 10.0;
    clamped.limit = value < 0 ? 0 : highest_ / 10.0;
    clamped.message = "override " + std::to_string(value / 10.0) + " % is outside 0 .. " +
                      std::to_string(highest_ / 10) + " % (override_max_percent); using " +
                      std::to_string(clamped.limit) + " %";
    events.raise(clamped);
  }
  previous_override_command_ = value;
  value = std::clamp(value, 0, highest_);
  const bool changed = hli.feedhold.request_r != hli.feedhold.state_r || value != hli.override.state_r;
  hli.feedhold.state_r = hli.feedhold.request_r;
  hli.override.state_r = value;
  return changed;
}

}  // namespace hil::cnc
