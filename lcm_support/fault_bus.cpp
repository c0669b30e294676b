#include "fault_bus.hpp"

#include <signal.h>

#include <algorithm>

#include "inbox.hpp"

namespace hil::lcm_support {

FaultInjectingBus::FaultInjectingBus(Bus& inner, const FaultPlan& plan, std::string participant,
                                     std::function<void()> on_kill)
    : inner_(inner), plan_(plan), participant_(std::move(participant)),
      answer_(participant_ == "cnc" ? "" : answer_channel(participant_)), kill_(plan.kill_cycle(participant_)),
      on_kill_(std::move(on_kill)) {}

std::unique_ptr<Bus> with_faults(std::unique_ptr<Bus> bus, const FaultPlan& plan, const std::string& participant) {
  if (plan.empty()) return bus;
  auto decorated = std::make_unique<FaultInjectingBus>(*bus, plan, participant, [] { ::raise(SIGKILL); });
  decorated->owned_ = std::move(bus);
  return decorated;
}

void damage(std::vector<uint8_t>& bytes) {
  for (size_t i = 0; i < bytes.size() && i < 8; ++i) bytes[i] = static_cast<uint8_t>(~bytes[i]);
}

void FaultInjectingBus::send(const std::string& channel, const std::vector<uint8_t>& bytes, bool duplicated) {
  inner_.publish(channel, bytes.data(), static_cast<uint32_t>(bytes.size()));
  if (duplicated) inner_.publish(channel, bytes.data(), static_cast<uint32_t>(bytes.size()));
}

void FaultInjectingBus::publish(const std::string& channel, const void* data, uint32_t size) {
  if (plan_.empty()) return inner_.publish(channel, data, size);
  if (killed_) return;
  const std::optional<Identity> id = identify_header(channel, data, size);
  if (kill_ && id && id->cycle >= *kill_) {  // it dies before it sends anything of that cycle
    killed_ = true;
    held_.clear();
    if (on_kill_) on_kill_();
    return;
  }
  const bool cycle_channel = id && sender_of(channel) == (participant_ == "cnc" ? "cnc" : participant_);
  if (!cycle_channel) return inner_.publish(channel, data, size);
  if (channel == answer_) {  // what was held for this cycle or before goes out first, oldest first
    std::stable_sort(held_.begin(), held_.end(), [](const Held& a, const Held& b) { return a.cycle < b.cycle; });
    for (auto it = held_.begin(); it != held_.end();) {
      if (it->release > id->cycle) {
        ++it;
        continue;
      }
      send(it->channel, it->bytes, it->duplicated);
      it = held_.erase(it);
    }
  }
  const MessageFate fate = plan_.fate(channel, id->cycle);
  if (fate.dropped) return;
  std::vector<uint8_t> bytes(static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + size);
  if (fate.corrupted) damage(bytes);
  if (fate.release_cycle > id->cycle) return held_.push_back({channel, std::move(bytes), id->cycle, fate.release_cycle, fate.duplicated});
  send(channel, bytes, fate.duplicated);
}

}  // namespace hil::lcm_support
