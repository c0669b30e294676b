#pragma once
// What a receiver did not take (RIG-9), counted per channel: messages of
// another run, answers to a cycle nobody waits for, bytes that are not the
// channel's type. No LCM in here: the nodes, the logger and the log reader
// all count with it, and the verdict reads it.
#include <cstdint>
#include <map>
#include <string>

namespace hil::traffic {

enum class Refusal {
  foreign_run,  // another run's message (another rig on the port, a replay)
  wrong_cycle,  // this run's, but not the answer to the cycle waited for
  undecodable,      // not the channel's type, truncated, or a datagram LCM could not frame
  unauthenticated,  // this run's id but not the run's MAC (RIG-12): not from one of its processes
  oversized,        // a fragment of a message beyond what the node reassembles (memory cap)
};

struct Refused {
  int64_t foreign_run = 0;
  int64_t wrong_cycle = 0;
  int64_t undecodable = 0;
  int64_t unauthenticated = 0;
  int64_t oversized = 0;

  int64_t total() const { return foreign_run + wrong_cycle + undecodable + unauthenticated + oversized; }
  // A run passes with another run's traffic told apart, and forged or
  // oversized traffic refused (what the run's own processes sent is then
  // still all there, or the log is incomplete), never with its own traffic
  // unaccounted for or with bytes nobody can read.
  bool fails_run() const { return wrong_cycle + undecodable > 0; }
  Refused& operator+=(const Refused& other);
};

// Where a datagram is counted whose channel name LCM 1.3.1 read past its end.
inline const std::string malformed_datagram = "(malformed datagram)";

class Ledger {
 public:
  void refuse(const std::string& channel, Refusal why);
  void add(const std::string& channel, const Refused& counts);
  void add(const Ledger& other);

  const std::map<std::string, Refused>& by_channel() const { return channels_; }
  bool empty() const { return channels_.empty(); }
  bool fails_run() const;
  // "AXIS_Y_STATE: 1 wrong cycle; HLI_CONTROL: 2 foreign run", or "none".
  std::string describe() const;

 private:
  Refused& row(const std::string& channel);
  std::map<std::string, Refused> channels_;
};

// Channel names beyond this many are counted under one more row, so that a
// flood of invented names cannot grow a ledger without bound.
constexpr size_t max_channels = 64;
inline const std::string other_channels = "(other channels)";

}  // namespace hil::traffic
