#pragma once
// Feed hold and path override (KRN-3): levels, not edges; they act while
// set, and the path is replanned from where it is.
// Reads: feedhold.command_w/enable_w, override.command_w (0.1 %)/enable_w.
// Writes: feedhold.request_r/state_r, override.request_r/state_r.
#include "channel_events.hpp"
#include "hli.hpp"

namespace hil::cnc {

class FeedControl {
 public:
  explicit FeedControl(int override_max_percent) : highest_(override_max_percent * 10) {}
  // True if the feed hold or the override in force changed. An override
  // outside 0 .. override_max_percent is clamped, with a warning.
  bool apply(const HliControl& control, HliState& hli, ChannelEvents& events);

 private:
  int32_t highest_;  // 0.1 %
  int32_t previous_override_command_ = override_full;
};

}  // namespace hil::cnc
