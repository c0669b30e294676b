#pragma once
// A run's log in simulated time (issue 37, RIG-7): every message of a cycle
// stamped at that cycle's time (the manifest's cycle time), so that a log
// player's speed 1 is the machine's pace. A lock-step run records as fast as
// it computes (8.4 s simulated in 1.2 s wall): played as recorded, "speed
// 0.5" would still be 3.5 x the machine's pace.
#include <cstdint>
#include <string>

namespace hil::logger {

struct RetimedLog {
  int64_t messages = 0;
  double simulated_s = 0;  // the first cycle's time to the last's
  double recorded_s = 0;   // the first record's timestamp to the last's
  bool retimed = false;    // false: no manifest names the cycle time; copied as recorded
};

// Writes `out` from `in`: a message with a cycle (lock-step channels,
// events, statistics) at first timestamp + cycle x cycle time; the others
// (handshake, manifest, seal) at the latest time before them, so time never
// runs back. Throws std::runtime_error if `in` cannot be read or `out` written.
RetimedLog retime_to_simulated(const std::string& in, const std::string& out);

}  // namespace hil::logger
