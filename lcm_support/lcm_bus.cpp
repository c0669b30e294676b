// The Bus over LCM itself: publish and subscribe are LCM's, every
// subscription raw (the inbox decodes and counts what it refuses).
#include <map>
#include <stdexcept>

#include "bus.hpp"

namespace hil::lcm_support {
namespace {

class LcmBus : public Bus {
 public:
  explicit LcmBus(const std::string& url) : lcm_(url) {
    if (!lcm_.good()) throw std::runtime_error("cannot open LCM on " + url);
  }
  ~LcmBus() override {
    for (auto& [id, s] : subscriptions_) lcm_.unsubscribe(s.subscription);
  }

  void publish(const std::string& channel, const void* data, uint32_t size) override {
    lcm_.publish(channel, data, size);
  }

  int subscribe(const std::string& channel, Handler handler, int queue_capacity) override {
    const int id = next_id_++;
    auto held = std::make_unique<Handler>(std::move(handler));
    lcm::Subscription* s = lcm_.subscribeFunction(
        channel, +[](const lcm::ReceiveBuffer* rbuf, const std::string& ch, Handler* h) { (*h)(*rbuf, ch); },
        held.get());
    s->setQueueCapacity(queue_capacity);
    subscriptions_[id] = {s, std::move(held)};
    return id;
  }

  void unsubscribe(int id) override {
    const auto it = subscriptions_.find(id);
    if (it == subscriptions_.end()) return;
    lcm_.unsubscribe(it->second.subscription);
    subscriptions_.erase(it);
  }

  int handle_timeout(int timeout_ms) override { return lcm_.handleTimeout(timeout_ms); }

 private:
  struct Held {
    lcm::Subscription* subscription;
    std::unique_ptr<Handler> handler;
  };
  lcm::LCM lcm_;
  std::map<int, Held> subscriptions_;
  int next_id_ = 1;
};

}  // namespace

std::unique_ptr<Bus> lcm_bus(const std::string& url) { return std::make_unique<LcmBus>(url); }

}  // namespace hil::lcm_support
