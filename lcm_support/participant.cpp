#include "participant.hpp"

#include <unistd.h>

#include <hil/participant_t.hpp>

#include <stdexcept>

#include "channels.hpp"

namespace hil::lcm_support {

Participant::Participant(Inbox& inbox, std::string name) : inbox_(inbox), name_(std::move(name)) {
  inbox_.on<hil::run_manifest_t>(channels::manifest, [this](const hil::run_manifest_t& m, const lcm::ReceiveBuffer&) {
    if (started_) return false;  // the CNC sends one
    manifest_ = m;
    started_ = true;
    return true;
  });
  inbox_.on<hil::participant_t>(channels::participant, [this](const hil::participant_t& m, const lcm::ReceiveBuffer&) {
    if (m.name == "cnc") ++cnc_signs_;
    if (m.name == "logger" && m.phase == hil::participant_t::PHASE_ALIVE && m.cycle > logger_cycle_) {
      logger_cycle_ = m.cycle;
      ++cnc_signs_;
    }
    if (m.name == "cnc" && m.phase == hil::participant_t::PHASE_READY) cnc_up_ = true;
    if (m.name == "cnc" && m.phase == hil::participant_t::PHASE_RUN_END) {
      ended_ = true;
      end_cycle_ = m.cycle;
    }
    return true;
  });
}

void Participant::announce(int8_t phase, int64_t cycle, int32_t verdicts) {
  hil::participant_t m;
  m.run_id = inbox_.run_id();
  m.utime = 0;
  m.cycle = cycle;
  m.name = name_;
  m.phase = phase;
  m.verdicts = verdicts;
  if (phase == hil::participant_t::PHASE_RUN_END) m.rejected = to_message(inbox_.ledger());
  m.n_rejected = static_cast<int16_t>(m.rejected.size());
  m.n_lost = 0;
  m.pid = static_cast<int32_t>(::getpid());
  inbox_.bus().publish(channels::participant, m);
}

void Participant::announce_ready() { announce(hil::participant_t::PHASE_READY, 0, 0); }

void Participant::announce_end(int64_t cycle, int32_t verdicts) {
  announce(hil::participant_t::PHASE_RUN_END, cycle, verdicts);
}

void Participant::announce_alive(int64_t recorded_cycle) {
  announce(hil::participant_t::PHASE_ALIVE, recorded_cycle, 0);
}

bool Participant::wait_for_start(std::chrono::milliseconds timeout) {
  using clock = std::chrono::steady_clock;
  const auto give_up = clock::now() + timeout;
  auto next_announce = clock::now();
  while (!started_) {
    const auto now = clock::now();
    if (now > give_up) return false;
    // On a timer, not per message received: answering every READY with a
    // READY would flood the bus.
    if (now >= next_announce || cnc_up_) {
      cnc_up_ = false;
      announce_ready();
      next_announce = now + std::chrono::milliseconds(50);
    }
    if (inbox_.bus().handle_timeout(10) < 0) throw std::runtime_error("LCM receive failed");
  }
  return true;
}

bool Participant::serve_until_end(std::chrono::milliseconds silence, const std::function<int64_t()>& cnc_cycle) {
  using clock = std::chrono::steady_clock;
  auto last = clock::now();
  int64_t signs = cnc_signs_, cycle = cnc_cycle();
  while (!ended_) {
    if (inbox_.bus().handle_timeout(100) < 0) throw std::runtime_error("LCM receive failed");
    if (cnc_signs_ != signs || cnc_cycle() != cycle) {
      signs = cnc_signs_;
      cycle = cnc_cycle();
      last = clock::now();
    } else if (clock::now() - last > silence) {
      return false;
    }
  }
  return true;
}

}  // namespace hil::lcm_support
