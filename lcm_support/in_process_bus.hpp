#pragma once
// The Bus of an in-process run (`hil run --in-process`): every node in one
// thread, a message handed to its subscribers by a direct call, in the order
// the messages were published. No socket, no thread: what remains of a
// cycle is the nodes' own work. A subscriber's publish during a hand-over is
// queued behind it, as on LCM.
#include <deque>
#include <string>
#include <vector>

#include "bus.hpp"
#include "subscribers.hpp"

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
  struct Queued {
    std::string channel;
    std::vector<uint8_t> bytes;
  };
  Subscribers subscribers_;
  std::deque<Queued> queue_;
  std::vector<std::vector<uint8_t>> spare_;  // buffers of handed-on messages, for the next ones
};

}  // namespace hil::lcm_support
