#pragma once
// The rig's LCM channel names (docs/ARCHITECTURE.md).
#include <string>

namespace hil::channels {

inline const std::string hli_control = "HLI_CONTROL";
inline const std::string hli_state = "HLI_STATE";
inline const std::string event = "HIL_EVENT";
inline const std::string manifest = "HIL_MANIFEST";
inline const std::string participant = "HIL_PARTICIPANT";
// Real-time mode only: the CNC's tick jitter and answer counts (rt_stats_t).
inline const std::string rt_stats = "HIL_RT_STATS";
// Written into the log by hil_logger, never sent in a live run.
inline const std::string scenario = "HIL_SCENARIO";
inline const std::string log_end = "HIL_LOG_END";
// LCM's own: every udpm instance sends one when it opens. Not the rig's; ignored.
inline const std::string lcm_self_test = "LCM_SELF_TEST";
// Every channel but LCM_SELF_TEST, as an LCM subscription (a regular
// expression; LCM anchors it). Not ".*": LCM 1.3.1 counts a queued message
// against the subscriptions of its channel when it arrives and takes it off
// the counts of the subscriptions there are when it is handled. A self-test
// message queued for LCM's own short-lived self-test subscription and handled
// after it is gone is taken off a ".*" subscription that never counted it;
// that subscription then drops the next message it is left holding alone,
// silently (docs/RELIABILITY.md, "The first cycles").
inline const std::string every_channel_but_self_test = "(?!LCM_SELF_TEST$).*";

inline std::string axis_command(const std::string& axis) { return "AXIS_" + axis + "_CMD"; }
inline std::string axis_state(const std::string& axis) { return "AXIS_" + axis + "_STATE"; }

// Whether a channel is named "AXIS_<axis><suffix>" (no allocation: the
// logger asks for every message).
inline bool names_an_axis(const std::string& channel, const char* suffix) {
  constexpr size_t prefix = 5;  // "AXIS_"
  const size_t suffix_size = std::char_traits<char>::length(suffix);
  return channel.size() > prefix + suffix_size && channel.compare(0, prefix, "AXIS_") == 0 &&
         channel.compare(channel.size() - suffix_size, suffix_size, suffix) == 0;
}

// The axis of a channel named "AXIS_<axis><suffix>"; "" for any other.
inline std::string axis_of(const std::string& channel, const char* suffix) {
  if (!names_an_axis(channel, suffix)) return "";
  const size_t suffix_size = std::char_traits<char>::length(suffix);
  return channel.substr(5, channel.size() - 5 - suffix_size);
}
inline std::string axis_of_command(const std::string& channel) { return axis_of(channel, "_CMD"); }
inline std::string axis_of_state(const std::string& channel) { return axis_of(channel, "_STATE"); }

}  // namespace hil::channels
