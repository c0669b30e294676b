#include "in_process_bus.hpp"

#include <chrono>
#include <thread>

#include "channels.hpp"

namespace hil::lcm_support {
namespace {

int64_t wall_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

void InProcessBus::publish(const std::string& channel, const void* data, uint32_t size) {
  std::vector<uint8_t> bytes;
  if (!spare_.empty()) {
    bytes = std::move(spare_.back());
    spare_.pop_back();
  }
  const auto* p = static_cast<const uint8_t*>(data);
  bytes.assign(p, p + size);
  queue_.push_back({channel, std::move(bytes)});
}

int InProcessBus::subscribe(const std::string& channel, Handler handler, int) {
  subscriptions_.push_back(std::make_unique<Subscription>(Subscription{next_id_, channel, std::move(handler)}));
  by_channel_.clear();
  ++generation_;
  return next_id_++;
}

void InProcessBus::unsubscribe(int id) {
  for (auto it = subscriptions_.begin(); it != subscriptions_.end(); ++it)
    if ((*it)->id == id) {
      subscriptions_.erase(it);
      by_channel_.clear();
      ++generation_;
      return;
    }
}

const std::vector<const InProcessBus::Subscription*>& InProcessBus::subscribers(const std::string& channel) {
  const auto known = by_channel_.find(channel);
  if (known != by_channel_.end()) return known->second;
  std::vector<const Subscription*>& list = by_channel_[channel];
  for (const auto& s : subscriptions_)
    if (s->channel == channel || (s->channel == channels::every_channel_but_self_test && channel != channels::lcm_self_test))
      list.push_back(s.get());
  return list;
}

int InProcessBus::handle_timeout(int timeout_ms) {
  if (queue_.empty()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
    return 0;
  }
  Queued message = std::move(queue_.front());
  queue_.pop_front();
  lcm::ReceiveBuffer rbuf{message.bytes.data(), static_cast<uint32_t>(message.bytes.size()), wall_us()};
  const std::vector<const Subscription*>& to = subscribers(message.channel);
  const int64_t generation = generation_;
  for (size_t i = 0; i < to.size() && generation == generation_; ++i) to[i]->handler(rbuf, message.channel);
  spare_.push_back(std::move(message.bytes));
  return 1;
}

void InProcessBus::drain() {
  while (!queue_.empty()) handle_timeout(0);
}

}  // namespace hil::lcm_support
