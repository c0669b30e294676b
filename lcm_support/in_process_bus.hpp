#pragma once
// The Bus of an in-process run (`hil run --in-process`): every node in one
// thread, a message handed to its subscribers by a direct call, in the order
// the messages were published. No socket, no thread: what remains of a
// cycle is the nodes' own work. A subscriber's publish during a hand-over is
// queued behind it, as on LCM.
#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

#include "bus.hpp"

namespace hil::lcm_support {

class InProcessBus : public Bus {
 public:
  void publish(const std::string& channel, const void* data, uint32_t size) override;
  int subscribe(const std::string& channel, Handler handler, int queue_capacity) override;
  void unsubscribe(int id) override;
  // Nothing else can publish while the queue is empty: waits out the
  // timeout (as a silent participant would make LCM wait) and returns 0.
  int handle_timeout(int timeout_ms) override;

  bool empty() const { return queue_.empty(); }
  // Hands on every queued message, and those they cause.
  void drain();

 private:
  struct Subscription {
    int id;
    std::string channel;
    Handler handler;
  };
  struct Queued {
    std::string channel;
    std::vector<uint8_t> bytes;
  };
  const std::vector<const Subscription*>& subscribers(const std::string& channel);

  std::vector<std::unique_ptr<Subscription>> subscriptions_;
  std::unordered_map<std::string, std::vector<const Subscription*>> by_channel_;  // made as channels appear
  std::deque<Queued> queue_;
  std::vector<std::vector<uint8_t>> spare_;  // buffers of handed-on messages, for the next ones
  int next_id_ = 1;
  // A subscription made or ended by a handler ends the hand-over of the
  // message at hand (the lists it walks are made anew).
  int64_t generation_ = 0;
};

}  // namespace hil::lcm_support
