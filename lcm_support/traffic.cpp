#include "traffic.hpp"

namespace hil::traffic {

Refused& Refused::operator+=(const Refused& other) {
  foreign_run += other.foreign_run;
  wrong_cycle += other.wrong_cycle;
  undecodable += other.undecodable;
  unauthenticated += other.unauthenticated;
  oversized += other.oversized;
  return *this;
}

Refused& Ledger::row(const std::string& channel) {
  const size_t named = channels_.size() - channels_.count(other_channels);
  if (named >= max_channels && !channels_.count(channel)) return channels_[other_channels];
  return channels_[channel];
}

void Ledger::refuse(const std::string& channel, Refusal why) {
  Refused& r = row(channel);
  switch (why) {
    case Refusal::foreign_run: ++r.foreign_run; break;
    case Refusal::wrong_cycle: ++r.wrong_cycle; break;
    case Refusal::undecodable: ++r.undecodable; break;
    case Refusal::unauthenticated: ++r.unauthenticated; break;
    case Refusal::oversized: ++r.oversized; break;
  }
}

void Ledger::add(const std::string& channel, const Refused& counts) {
  if (counts.total() > 0) row(channel) += counts;
}

void Ledger::add(const Ledger& other) {
  for (const auto& [channel, counts] : other.channels_) add(channel, counts);
}

bool Ledger::fails_run() const {
  for (const auto& entry : channels_)
    if (entry.second.fails_run()) return true;
  return false;
}

std::string Ledger::describe() const {
  std::string out;
  for (const auto& [channel, r] : channels_) {
    std::string counts;
    auto part = [&](int64_t n, const char* what) {
      if (n > 0) counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + what;
    };
    part(r.foreign_run, "foreign run");
    part(r.wrong_cycle, "wrong cycle");
    part(r.undecodable, "undecodable");
    part(r.unauthenticated, "unauthenticated");
    part(r.oversized, "oversized");
    out += (out.empty() ? "" : "; ") + channel + ": " + counts;
  }
  return out.empty() ? "none" : out;
}

}  // namespace hil::traffic
