#pragma once
// LCM's fragmented messages put back together (RIG-9, issue 33), without
// sockets or LCM: the udpm bus feeds it every LC03 datagram and gets whole
// messages out. A datagram on the rig's network can announce any size up to
// LCM's 256 MiB; what it costs a receiver here is only what was sent and
// never more than the caps:
// - a buffer grows with the fragments that arrive, the announced size is
//   never allocated up front;
// - a message announced beyond `Limits::message_bytes` gets no buffer;
// - all partial messages together stay within `Limits::total_bytes`
//   (overheads counted), the least recently grown given up first;
// - a channel nobody subscribes to gets no buffer (fragment 0 names it);
// - a sender has one message in progress (LCM sends a message's fragments
//   back to back): its next message replaces an unfinished one, and a
//   message that stopped growing is dropped after `Limits::stale_after_us`.
// What it refuses is counted per channel: `oversized` (beyond the caps),
// `undecodable` (fragments that contradict their message's header).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "traffic.hpp"

namespace hil::lcm_support {

// LCM 1.3.1's fragment datagram (lcm/udpm_util.h): "LC03", sequence number,
// message size, this fragment's offset in the message, its number, the
// number of fragments, all big-endian; then for fragment 0 the channel name
// and its NUL, then data.
constexpr uint32_t lcm_fragment_magic = 0x4c433033;
constexpr size_t lcm_fragment_header = 20;
constexpr size_t lcm_fragment_max_payload = 65487;  // LCM_FRAGMENT_MAX_PAYLOAD: name, NUL and data

class FragmentReassembly {
 public:
  struct Limits {
    // The largest message the rig sends in fragments is a replayed
    // HIL_SCENARIO (`hil replay`): the scenario and its NC program, 21 MB
    // for the million-line program of integration.big_program. A live run
    // sends none (its largest message, a RUN_END with a full ledger, is
    // about 7 KB, one datagram). So: room for that one, and for two at once.
    size_t message_bytes = size_t{32} << 20;
    size_t total_bytes = size_t{64} << 20;
    size_t messages = 1000;  // partial messages at once (as LCM 1.3.1's MAX_NUM_FRAG_BUFS)
    int64_t stale_after_us = 2'000'000;
  };
  // Where a datagram came from (IPv4 address and port, as received).
  struct Sender {
    uint32_t address = 0;
    uint16_t port = 0;
  };
  struct Message {
    std::string channel;
    std::vector<uint8_t> bytes;
    bool framed = true;  // false: fragment 0 whose channel name has no NUL within 64 bytes
  };
  // Whether a channel has a subscriber (only then is it reassembled).
  using Wanted = std::function<bool(const std::string& channel)>;

  explicit FragmentReassembly(Wanted wanted);
  FragmentReassembly(Wanted wanted, Limits limits);

  // One LC03 datagram, header included, received at `now_us`: the message it
  // completes, if any.
  std::optional<Message> take(const uint8_t* datagram, size_t size, Sender from, int64_t now_us);
  // Drops the partial messages that stopped growing (take does it too).
  void drop_stale(int64_t now_us);

  // The memory the partial messages hold, overheads included (<= total_bytes).
  size_t bytes_held() const { return held_; }
  size_t messages_held() const { return order_.size(); }
  const traffic::Ledger& refused() const { return refused_; }
  const Limits& limits() const { return limits_; }

 private:
  struct Piece {
    uint16_t number;
    std::vector<uint8_t> bytes;
  };
  struct Partial {
    uint64_t sender;
    uint32_t seqno, size;
    uint16_t fragments;
    std::string channel;
    std::optional<traffic::Refusal> refused;  // given up: its later fragments are counted so
    std::map<uint32_t, Piece> pieces;         // by offset
    uint16_t received = 0;                    // fragments taken, fragment 0 included
    size_t data = 0;                          // their data bytes
    size_t cost = 0;                          // what it holds, overheads included
    int64_t last_us = 0;
  };
  using Order = std::list<Partial>;  // least recently grown first

  Order::iterator open(uint64_t sender, uint32_t seqno, uint32_t size, uint16_t fragments, std::string channel,
                       int64_t now_us);
  std::optional<Message> add(Order::iterator p, uint16_t number, uint16_t fragments, uint32_t offset,
                             const uint8_t* data, size_t length, int64_t now_us);
  void refuse(Order::iterator p, traffic::Refusal why, int64_t also = 0);
  bool make_room(size_t cost, Order::iterator keep);
  void erase(Order::iterator p);
  void charge(Partial& p, size_t cost);

  Wanted wanted_;
  Limits limits_;
  Order order_;
  std::unordered_map<uint64_t, Order::iterator> by_sender_;
  size_t held_ = 0;
  traffic::Ledger refused_;
};

}  // namespace hil::lcm_support
