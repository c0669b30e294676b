#pragma once
// The channel's error stop on a drive error (RIG-3): a drive reported a
// monitoring error; the channel stops along the path as fast as the limits
// allow, jerk-limited (the hold's channel_error reason), aborts the program
// and shows ERROR and HLI_SC_CHANNEL_ERROR on the HLI. Reads nothing from
// the PLC; the channel enters ERROR when it begins, and the hold shows it
// in stop_conditions_r.
#include <string>

#include "channel_events.hpp"
#include "hli.hpp"

namespace hil::cnc {

class DriveErrorStop {
 public:
  // A drive error on `axis` in channel state `state`; false if the channel
  // had ended already (else it is to enter ERROR).
  bool begin(const std::string& axis, const std::string& what, ChannelState state, ChannelEvents& events) {
    return begin_for("drive error on axis " + axis + " (" + what + ")", axis, state, events);
  }
  // The same stop for any reason (the axis it concerns, or "").
  bool begin_for(const std::string& reason, const std::string& axis, ChannelState state, ChannelEvents& events);
  // Still moving towards the stop.
  bool stopping() const { return stopping_; }
  void update(bool standing) {
    if (standing) stopping_ = false;
  }

 private:
  bool stopping_ = false;
};

}  // namespace hil::cnc
