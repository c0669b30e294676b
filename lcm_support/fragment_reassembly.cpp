#include "fragment_reassembly.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>

namespace hil::lcm_support {
namespace {

constexpr size_t max_channel = 63;  // LCM_MAX_CHANNEL_NAME_LENGTH
// What a partial message and a piece cost the heap beyond their data (list,
// hash and map nodes, the vector, the allocator's headers), roughly: a flood
// of tiny fragments is then held to the cap too.
constexpr size_t partial_overhead = 320, piece_overhead = 96;

uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }
uint16_t be16(const uint8_t* p) { return static_cast<uint16_t>(p[0] << 8 | p[1]); }
uint64_t key(FragmentReassembly::Sender s) { return uint64_t{s.address} << 16 | s.port; }

}  // namespace

FragmentReassembly::FragmentReassembly(Wanted wanted) : FragmentReassembly(std::move(wanted), Limits{}) {}

FragmentReassembly::FragmentReassembly(Wanted wanted, Limits limits) : wanted_(std::move(wanted)), limits_(limits) {}

std::optional<FragmentReassembly::Message> FragmentReassembly::take(const uint8_t* datagram, size_t size, Sender from,
                                                                    int64_t now_us) {
  if (size < lcm_fragment_header || be32(datagram) != lcm_fragment_magic) return std::nullopt;
  drop_stale(now_us);
  const uint32_t seqno = be32(datagram + 4), total = be32(datagram + 8), offset = be32(datagram + 12);
  const uint16_t number = be16(datagram + 16), fragments = be16(datagram + 18);
  const uint8_t* data = datagram + lcm_fragment_header;
  size_t length = size - lcm_fragment_header;
  const uint64_t sender = key(from);

  if (const auto found = by_sender_.find(sender); found != by_sender_.end()) {
    const Order::iterator p = found->second;
    if (p->seqno == seqno && p->size == total) {
      if (number == 0) return std::nullopt;  // fragment 0 again: a duplicate
      return add(p, number, fragments, offset, data, length, now_us);
    }
    // Only the next message's fragment 0 replaces this one (LCM 1.3.1: any
    // fragment of it; a late fragment of an older message then ended it).
    if (number == 0) erase(p);  // the sender went on: this one lost fragments
  }
  if (number != 0) return std::nullopt;  // its fragment 0 was not taken: nothing to add it to (as LCM 1.3.1)

  const auto* nul = static_cast<const uint8_t*>(std::memchr(data, 0, std::min(length, max_channel + 1)));
  if (!nul) return Message{"", {}, false};
  std::string channel(reinterpret_cast<const char*>(data), static_cast<size_t>(nul - data));
  if (!wanted_(channel)) return std::nullopt;
  const size_t name = channel.size() + 1;
  data += name;
  length -= name;
  if (total > limits_.message_bytes) {
    refused_.refuse(channel, traffic::Refusal::oversized);
    return std::nullopt;
  }
  // LCM sends fragment 0 at offset 0, and at most 65487 bytes of name and
  // data a fragment (the largest UDP datagram): a count the size cannot
  // fill, or one it cannot fit in, is no LCM message.
  if (offset != 0 || fragments == 0 || size_t{fragments} > size_t{total} + 1 ||
      size_t{total} + name > size_t{fragments} * lcm_fragment_max_payload) {
    refused_.refuse(channel, traffic::Refusal::undecodable);
    return std::nullopt;
  }
  const Order::iterator p = open(sender, seqno, total, fragments, std::move(channel), now_us);
  if (p == order_.end()) return std::nullopt;
  return add(p, 0, fragments, 0, data, length, now_us);
}

FragmentReassembly::Order::iterator FragmentReassembly::open(uint64_t sender, uint32_t seqno, uint32_t size,
                                                             uint16_t fragments, std::string channel, int64_t now_us) {
  while (!order_.empty() && order_.size() >= limits_.messages) refuse(order_.begin(), traffic::Refusal::oversized);
  if (!make_room(partial_overhead, order_.end())) {
    refused_.refuse(channel, traffic::Refusal::oversized);
    return order_.end();
  }
  Partial partial;
  partial.sender = sender;
  partial.seqno = seqno;
  partial.size = size;
  partial.fragments = fragments;
  partial.channel = std::move(channel);
  partial.last_us = now_us;
  const Order::iterator p = order_.insert(order_.end(), std::move(partial));
  by_sender_[sender] = p;
  charge(*p, partial_overhead);
  return p;
}

std::optional<FragmentReassembly::Message> FragmentReassembly::add(Order::iterator p, uint16_t number,
                                                                   uint16_t fragments, uint32_t offset,
                                                                   const uint8_t* data, size_t length,
                                                                   int64_t now_us) {
  Partial& m = *p;
  // A fragment beyond its message, or that overlaps another: the message
  // cannot be put together (LCM 1.3.1 drops it too).
  const auto contradicts = [&] {
    if (fragments != m.fragments || number >= m.fragments || offset > m.size || length > m.size - offset) return true;
    if (length == 0) return number != 0;  // only fragment 0 may carry its name alone
    const auto next = m.pieces.lower_bound(offset);
    if (next != m.pieces.end() && next->first < offset + length) return true;
    return next != m.pieces.begin() && std::prev(next)->first + std::prev(next)->second.bytes.size() > offset;
  };
  if (const auto same = m.pieces.find(offset);
      same != m.pieces.end() && same->second.number == number && same->second.bytes.size() == length)
    return std::nullopt;  // a duplicate: the first one counts
  if (contradicts()) {
    refuse(p, traffic::Refusal::undecodable, 1);
    return std::nullopt;
  }
  order_.splice(order_.end(), order_, p);  // grown just now: the last to give up
  m.last_us = now_us;
  if (length > 0) {
    const size_t cost = length + piece_overhead;
    if (!make_room(cost, p)) {
      refuse(p, traffic::Refusal::oversized, 1);
      return std::nullopt;
    }
    m.pieces.emplace(offset, Piece{number, std::vector<uint8_t>(data, data + length)});
    charge(m, cost);
    m.data += length;
  }
  ++m.received;
  if (m.received < m.fragments && m.data < m.size) return std::nullopt;
  if (m.received != m.fragments || m.data != m.size) {  // all fragments but not all bytes, or the other way round
    refuse(p, traffic::Refusal::undecodable);
    return std::nullopt;
  }
  // The pieces do not overlap and add up to the size: they tile it, in order.
  Message whole{std::move(m.channel), {}, true};
  whole.bytes.reserve(m.size);
  for (auto& [at, piece] : m.pieces) {
    whole.bytes.insert(whole.bytes.end(), piece.bytes.begin(), piece.bytes.end());
    std::vector<uint8_t>().swap(piece.bytes);  // freed as copied: the message's bytes are not held twice
  }
  erase(p);
  return whole;
}

void FragmentReassembly::drop_stale(int64_t now_us) {
  while (!order_.empty() && now_us - order_.front().last_us > limits_.stale_after_us) erase(order_.begin());
}

// Counts the fragments the message was given (and `also` more) as refused,
// then drops it; its fragments still to come find no buffer.
void FragmentReassembly::refuse(Order::iterator p, traffic::Refusal why, int64_t also) {
  traffic::Refused counts;
  (why == traffic::Refusal::oversized ? counts.oversized : counts.undecodable) = int64_t{p->received} + also;
  refused_.add(p->channel, counts);
  erase(p);
}

// Gives up the least recently grown partial messages but `keep` until `cost`
// more fits within the cap; false if it cannot.
bool FragmentReassembly::make_room(size_t cost, Order::iterator keep) {
  while (held_ + cost > limits_.total_bytes) {
    Order::iterator victim = order_.begin();
    if (victim == keep && victim != order_.end()) ++victim;
    if (victim == order_.end()) return false;
    refuse(victim, traffic::Refusal::oversized);
  }
  return true;
}

void FragmentReassembly::erase(Order::iterator p) {
  held_ -= p->cost;
  by_sender_.erase(p->sender);
  order_.erase(p);
}

void FragmentReassembly::charge(Partial& p, size_t cost) {
  p.cost += cost;
  held_ += cost;
}

}  // namespace hil::lcm_support
