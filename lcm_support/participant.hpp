#pragma once
// The lock-step handshake every node but the CNC takes part in (RIG-6):
// announce READY until the CNC's manifest shows the run has begun; leave
// when the CNC announces the run's end.
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <string>

namespace hil::lcm_support {

class Participant {
 public:
  Participant(lcm::LCM& lcm, std::string name);
  ~Participant();

  // Announces READY until the CNC's manifest arrives; false after `timeout`.
  bool wait_for_start(std::chrono::milliseconds timeout);
  // Handles messages until the CNC's RUN_END; false if `silence` passes
  // without any message.
  bool serve_until_end(std::chrono::milliseconds silence);
  // Announces this node's own end (the logger waits for it).
  void announce_end(int64_t cycle);

  bool started() const { return started_; }
  bool ended() const { return ended_; }
  int64_t end_cycle() const { return end_cycle_; }

 private:
  void announce(int8_t phase, int64_t cycle);

  lcm::LCM& lcm_;
  std::string name_;
  bool started_ = false;
  bool ended_ = false;
  int64_t end_cycle_ = 0;
  lcm::Subscription* manifest_sub_ = nullptr;
  lcm::Subscription* participant_sub_ = nullptr;
};

// An LCM instance on `url`, or an exception naming it.
void require_good(const lcm::LCM& lcm, const std::string& url);

}  // namespace hil::lcm_support
