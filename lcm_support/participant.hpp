#pragma once
// The lock-step handshake every node but the CNC takes part in (RIG-6):
// announce READY until this run's manifest shows it has begun (at once
// again when the CNC announces that it is up: it may have missed the
// first); leave when this run's CNC announces its end. Announcements and manifests of other
// runs are refused (counted in the inbox's ledger).
#include <hil/run_manifest_t.hpp>

#include <chrono>
#include <string>

#include "inbox.hpp"

namespace hil::lcm_support {

class Participant {
 public:
  Participant(Inbox& inbox, std::string name);

  // Once; wait_for_start repeats it.
  void announce_ready();
  // Announces READY until the CNC's manifest arrives; false after `timeout`.
  bool wait_for_start(std::chrono::milliseconds timeout);
  // Handles messages until the CNC's RUN_END; false if `silence` passes
  // without a message of this run.
  bool serve_until_end(std::chrono::milliseconds silence);
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
  hil::run_manifest_t manifest_;
};


}  // namespace hil::lcm_support
