#include "participant.hpp"

#include <hil/participant_t.hpp>

#include <stdexcept>

#include "channels.hpp"

namespace hil::lcm_support {

void require_good(const lcm::LCM& lcm, const std::string& url) {
  if (!lcm.good()) throw std::runtime_error("cannot open LCM on " + url);
}

Participant::Participant(lcm::LCM& lcm, std::string name) : lcm_(lcm), name_(std::move(name)) {
  manifest_sub_ = lcm_.subscribeFunction(
      channels::manifest,
      +[](const lcm::ReceiveBuffer*, const std::string&, Participant* self) { self->started_ = true; },
      this);
  participant_sub_ = lcm_.subscribeFunction(
      channels::participant,
      +[](const lcm::ReceiveBuffer*, const std::string&, const hil::participant_t* m, Participant* self) {
        if (m->name == "cnc" && m->phase == hil::participant_t::PHASE_RUN_END) {
          self->ended_ = true;
          self->end_cycle_ = m->cycle;
        }
      },
      this);
}

Participant::~Participant() {
  lcm_.unsubscribe(manifest_sub_);
  lcm_.unsubscribe(participant_sub_);
}

void Participant::announce(int8_t phase, int64_t cycle) {
  hil::participant_t m;
  m.utime = 0;
  m.cycle = cycle;
  m.name = name_;
  m.phase = phase;
  lcm_.publish(channels::participant, &m);
}

void Participant::announce_end(int64_t cycle) { announce(hil::participant_t::PHASE_RUN_END, cycle); }

bool Participant::wait_for_start(std::chrono::milliseconds timeout) {
  using clock = std::chrono::steady_clock;
  const auto give_up = clock::now() + timeout;
  auto next_announce = clock::now();
  while (!started_) {
    const auto now = clock::now();
    if (now > give_up) return false;
    // On a timer, not per message received: answering every READY with a
    // READY would flood the bus.
    if (now >= next_announce) {
      announce(hil::participant_t::PHASE_READY, 0);
      next_announce = now + std::chrono::milliseconds(50);
    }
    if (lcm_.handleTimeout(10) < 0) throw std::runtime_error("LCM receive failed");
  }
  return true;
}

bool Participant::serve_until_end(std::chrono::milliseconds silence) {
  while (!ended_) {
    const int handled = lcm_.handleTimeout(static_cast<int>(silence.count()));
    if (handled == 0) return false;
    if (handled < 0) throw std::runtime_error("LCM receive failed");
  }
  return true;
}

}  // namespace hil::lcm_support
