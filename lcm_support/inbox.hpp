#pragma once
// What a node takes from the bus (RIG-6, RIG-9): every subscription is raw,
// so that bytes which are not the channel's type are counted rather than
// dropped unseen by LCM's typed handlers; a message is taken only if it is
// of this run and its receiver accepts its cycle. Everything else lands in
// the node's traffic::Ledger, reported at its RUN_END.
#include <hil/traffic_count_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bus.hpp"
#include "traffic.hpp"
#include "untrusted_decode.hpp"

namespace hil::lcm_support {

// Whether LCM framed the datagram: LCM 1.3.1 reads a channel name that has
// no NUL past the datagram's end and hands on a negative data_size (as
// uint32_t). Nothing in such a buffer may be used.
inline bool framed(const lcm::ReceiveBuffer& rbuf) { return rbuf.data_size <= LCM_MAX_MESSAGE_SIZE; }

// Bytes from the network: a string or array length that lcm-gen's decoder
// would follow past the buffer is undecodable, not a crash (untrusted_decode.hpp).
template <typename Message>
bool decode(const void* data, uint32_t size, Message& message) {
  return decode_untrusted(data, size, message);
}

// The run id an encoded rig message names (bytes 8 .. 16, after its type's
// fingerprint; every rig type begins with it), none for fewer bytes.
std::optional<int64_t> named_run_id(const void* data, uint32_t size);

// The run and cycle a message on a rig channel names.
struct Identity {
  int64_t run_id = 0;
  int64_t cycle = 0;
};
// Decodes as the rig channel's type; none for bytes that are not, or for a
// channel the rig does not use.
std::optional<Identity> identify(const std::string& channel, const void* data, uint32_t size);
// The same from the type's fingerprint and the header every rig type begins
// with, without decoding the rest: for bytes a node encoded in this process
// (the in-process bus), which no network can have cut or forged.
std::optional<Identity> identify_header(const std::string& channel, const void* data, uint32_t size);

class Inbox {
 public:
  Inbox(Bus& bus, int64_t run_id) : bus_(bus), run_id_(run_id) {}
  Inbox(const Inbox&) = delete;
  Inbox& operator=(const Inbox&) = delete;
  ~Inbox();

  // Calls take(message, rbuf) for each message of this run on `channel`;
  // take returns false for a message whose cycle it does not wait for.
  template <typename Message>
  void on(const std::string& channel, std::function<bool(const Message&, const lcm::ReceiveBuffer&)> take,
          int queue_capacity = 10000) {
    route(channel, queue_capacity, [this, take](const lcm::ReceiveBuffer& rbuf, const std::string& ch) {
      Message m;
      if (!decode(rbuf.data, rbuf.data_size, m)) return ledger_.refuse(ch, traffic::Refusal::undecodable);
      if (m.run_id != run_id_) return ledger_.refuse(ch, traffic::Refusal::foreign_run);
      if (!take(m, rbuf)) ledger_.refuse(ch, traffic::Refusal::wrong_cycle);
    });
  }

  int64_t run_id() const { return run_id_; }
  Bus& bus() { return bus_; }
  // What it refused, and what its bus refused before (Bus::refused).
  traffic::Ledger ledger() const {
    traffic::Ledger all = bus_.refused();
    all.add(ledger_);
    return all;
  }

 private:
  void route(const std::string& channel, int queue_capacity, Bus::Handler handle);

  Bus& bus_;
  int64_t run_id_;
  traffic::Ledger ledger_;
  std::vector<int> subscriptions_;
};

std::vector<hil::traffic_count_t> to_message(const traffic::Ledger& ledger);
traffic::Ledger from_message(const std::vector<hil::traffic_count_t>& counts);

}  // namespace hil::lcm_support
