#pragma once
// The lock-step handshake every node but the CNC takes part in (RIG-6):
// announce READY until this run's manifest shows it has begun (at once
// again when the CNC announces that it is up: it may have missed the
// first); leave when this run's CNC announces its end. Announcements and manifests of other
// runs are refused (counted in the inbox's ledger).
#include <hil/run_manifest_t.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

#include "inbox.hpp"

namespace hil::lcm_support {

// How long a node goes on without a sign of the CNC before it takes the CNC
// to be gone, says so and exits 2 (docs/RELIABILITY.md); hil run gives the
// nodes that long, and a margin, to end after the CNC's process has ended.
inline constexpr std::chrono::seconds cnc_silence{10};

class Participant {
 public:
  Participant(Inbox& inbox, std::string name);

  // Once; wait_for_start repeats it.
  void announce_ready();
  // Announces READY until the CNC's manifest arrives; false after `timeout`.
  bool wait_for_start(std::chrono::milliseconds timeout);
  // Handles messages until the CNC's RUN_END; false once the CNC has given
  // no sign of life for `silence`. A sign is a message from the CNC — its
  // announcements, or a cycle the node took from it (`cnc_cycle`, the
  // node's last cycle, advanced) — or a logger heartbeat whose recorded
  // cycle advanced (the CNC's progress, when the scenario's faults drop
  // this node's cycle messages). A heartbeat alone is no sign: it goes on
  // while the logger itself waits out a dead CNC's silence, and kept every
  // node serving twice as long (issue 33).
  bool serve_until_end(std::chrono::milliseconds silence, const std::function<int64_t()>& cnc_cycle);
  // Announces this node's own end with what its inbox refused (and, from
  // plc_sim, how many verdicts it published); the logger waits for it.
  void announce_end(int64_t cycle, int32_t verdicts = 0);
  // The logger's heartbeat, with the last cycle it recorded: the CNC stops
  // the run if it falls silent, and waits while it lags behind.
  void announce_alive(int64_t recorded_cycle);

  bool started() const { return started_; }
  bool ended() const { return ended_; }
  int64_t end_cycle() const { return end_cycle_; }
  const hil::run_manifest_t& manifest() const { return manifest_; }

 private:
  void announce(int8_t phase, int64_t cycle, int32_t verdicts);

  Inbox& inbox_;
  std::string name_;
  bool started_ = false;
  bool cnc_up_ = false;  // the CNC announced READY: announce again now
  bool ended_ = false;
  int64_t end_cycle_ = 0;
  int64_t cnc_signs_ = 0;      // messages from the CNC, and logger heartbeats that advanced
  int64_t logger_cycle_ = -1;  // the recorded cycle of the last such heartbeat
  hil::run_manifest_t manifest_;
};


}  // namespace hil::lcm_support
