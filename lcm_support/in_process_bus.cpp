#include "in_process_bus.hpp"

#include <chrono>
#include <thread>

namespace hil::lcm_support {

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
  return subscribers_.add(channel, std::move(handler));
}

void InProcessBus::unsubscribe(int id) { subscribers_.remove(id); }

int InProcessBus::handle_timeout(int timeout_ms) {
  if (queue_.empty()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
    return 0;
  }
  Queued message = std::move(queue_.front());
  queue_.pop_front();
  lcm::ReceiveBuffer rbuf{message.bytes.data(), static_cast<uint32_t>(message.bytes.size()), wall_clock_us()};
  subscribers_.dispatch(rbuf, message.channel);
  spare_.push_back(std::move(message.bytes));
  return 1;
}

void InProcessBus::drain() {
  while (!queue_.empty()) handle_timeout(0);
}

}  // namespace hil::lcm_support
