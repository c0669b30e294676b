#pragma once
// What a node sends and receives through (RIG-1): raw bytes on named
// channels, encoded as LCM types. Two kinds: LCM itself (udpm between
// processes, lcm_bus) and the in-process bus (in_process_bus.hpp: every node
// in one process, the same messages handed on by direct calls). The nodes
// know only this interface, so both runs produce the same messages.
#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "traffic.hpp"

namespace hil::lcm_support {

template <typename Message, typename = void>
struct has_mac : std::false_type {};
template <typename Message>
struct has_mac<Message, std::void_t<decltype(std::declval<Message>().mac)>> : std::true_type {};

// An LCM message's bytes, as LCM sends them. A rig channel's type ends
// with its MAC (RIG-12): encoded as 0, whatever the field holds, until the
// bus of a run's process signs it (authenticated_bus.hpp).
template <typename Message>
std::vector<uint8_t> encode(const Message& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  if constexpr (has_mac<Message>::value) std::fill(bytes.end() - sizeof(int64_t), bytes.end(), uint8_t{0});
  return bytes;
}

class Bus {
 public:
  // The message and the channel it came on; rbuf.recv_utime is the wall
  // clock when it was received.
  using Handler = std::function<void(const lcm::ReceiveBuffer& rbuf, const std::string& channel)>;

  virtual ~Bus() = default;
  virtual void publish(const std::string& channel, const void* data, uint32_t size) = 0;
  // `channel` is a channel name, or channels::every_channel_but_self_test.
  // Returns an id for unsubscribe.
  virtual int subscribe(const std::string& channel, Handler handler, int queue_capacity) = 0;
  virtual void unsubscribe(int id) = 0;
  // Hands on what has arrived, waiting at most `timeout_ms` for it: > 0 if
  // a message was handled, 0 if none came, < 0 if receiving failed.
  virtual int handle_timeout(int timeout_ms) = 0;
  // What the bus itself refused before any subscriber saw it (RIG-9,
  // RIG-12: unauthenticated messages, fragments beyond its reassembly
  // memory), per channel; a node adds it to what it reports at its RUN_END.
  virtual traffic::Ledger refused() const { return {}; }

  template <typename Message>
  void publish(const std::string& channel, const Message& message) {
    const std::vector<uint8_t> bytes = encode(message);
    publish(channel, bytes.data(), static_cast<uint32_t>(bytes.size()));
  }
};

// What a Bus stamps a received message with (LCM's recv_utime).
inline int64_t wall_clock_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// LCM on `url` (udpm://, file://, memq://); throws naming the URL if LCM
// cannot open it.
std::unique_ptr<Bus> lcm_bus(const std::string& url);

}  // namespace hil::lcm_support
