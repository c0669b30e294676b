// RIG-9 (issue 33): LCM's fragmented messages put back together within
// memory caps. A process on the rig's network sent ten LC03 headers each
// announcing 256 MiB on rig channels; the logger allocated and zeroed every
// announced size (161 MB -> 2.5 GB RSS in 3 s) and the CNC lost it.
#include <catch2/catch.hpp>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "fragment_reassembly.hpp"

using hil::lcm_support::FragmentReassembly;
using hil::lcm_support::lcm_fragment_max_payload;

namespace {

using Bytes = std::vector<uint8_t>;
constexpr uint32_t mib = 1 << 20;

void put32(Bytes& d, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) d.push_back(static_cast<uint8_t>(v >> shift));
}

// One LC03 datagram; `channel` only for fragment 0.
Bytes fragment(uint32_t seqno, uint32_t size, uint32_t offset, uint16_t number, uint16_t fragments,
               const std::string& channel, const Bytes& data) {
  Bytes d;
  put32(d, hil::lcm_support::lcm_fragment_magic);
  put32(d, seqno);
  put32(d, size);
  put32(d, offset);
  d.push_back(static_cast<uint8_t>(number >> 8));
  d.push_back(static_cast<uint8_t>(number));
  d.push_back(static_cast<uint8_t>(fragments >> 8));
  d.push_back(static_cast<uint8_t>(fragments));
  if (number == 0) d.insert(d.end(), channel.c_str(), channel.c_str() + channel.size() + 1);
  d.insert(d.end(), data.begin(), data.end());
  return d;
}

// A message cut as LCM 1.3.1's lcm_udpm_publish cuts it.
std::vector<Bytes> lcm_fragments(uint32_t seqno, const std::string& channel, const Bytes& message) {
  const size_t payload = channel.size() + 1 + message.size();
  const auto count = static_cast<uint16_t>((payload + lcm_fragment_max_payload - 1) / lcm_fragment_max_payload);
  std::vector<Bytes> out;
  size_t at = 0;
  for (uint16_t i = 0; i < count; ++i) {
    const size_t room = i == 0 ? lcm_fragment_max_payload - channel.size() - 1 : lcm_fragment_max_payload;
    const size_t n = std::min(room, message.size() - at);
    const auto from = message.begin() + static_cast<long>(at);
    out.push_back(fragment(seqno, static_cast<uint32_t>(message.size()), static_cast<uint32_t>(at), i, count, channel,
                           Bytes(from, from + static_cast<long>(n))));
    at += n;
  }
  return out;
}

Bytes pattern(size_t size) {
  Bytes b(size);
  for (size_t i = 0; i < size; ++i) b[i] = static_cast<uint8_t>(i * 7 + i / 251);
  return b;
}

// The fragments LCM sends a message of `size` bytes in (with a long name).
uint16_t fragments_for(uint32_t size) {
  return static_cast<uint16_t>(
      std::min<uint64_t>(65535, (uint64_t{size} + 64 + lcm_fragment_max_payload - 1) / lcm_fragment_max_payload));
}

// The first fragment of a message that announces `size` and is never sent on.
Bytes header_only(uint32_t seqno, uint32_t size, const std::string& channel, size_t data = 1000) {
  return fragment(seqno, size, 0, 0, fragments_for(size), channel, Bytes(data, 0xAB));
}

const std::vector<std::string> rig_channels{"HLI_CONTROL",  "HLI_STATE",  "AXIS_X_STATE",    "AXIS_Y_STATE",
                                            "AXIS_Z_STATE", "AXIS_X_CMD", "HIL_PARTICIPANT", "HIL_EVENT"};

FragmentReassembly every_channel() {
  return FragmentReassembly([](const std::string& channel) { return channel != "LCM_SELF_TEST"; });
}

std::optional<FragmentReassembly::Message> feed(FragmentReassembly& r, const Bytes& d, uint16_t port,
                                                int64_t now = 1'000'000) {
  return r.take(d.data(), d.size(), {0x0100007f, port}, now);
}

}  // namespace

TEST_CASE("RIG-9 fragment reassembly: 80 headers announcing 256 MiB each hold no memory, counted oversized per channel",
          "[reassembly]") {
  FragmentReassembly r = every_channel();
  for (uint16_t i = 0; i < 80; ++i) {
    const auto port = static_cast<uint16_t>(1000 + i);  // a sender of its own
    CHECK_FALSE(feed(r, header_only(i, 256 * mib, rig_channels[i % rig_channels.size()]), port));
    CHECK(r.bytes_held() == 0);
  }
  CHECK(r.messages_held() == 0);
  for (const std::string& channel : rig_channels) {
    INFO(channel);
    REQUIRE(r.refused().by_channel().count(channel) == 1);
    CHECK(r.refused().by_channel().at(channel).oversized == 10);
    CHECK(r.refused().by_channel().at(channel).total() == 10);
  }
  CHECK_FALSE(r.refused().fails_run());  // refused, and what the run sent is still all there (or the log says not)
}

TEST_CASE("RIG-9 fragment reassembly: a buffer grows with the fragments that arrive, never to the announced size",
          "[reassembly]") {
  FragmentReassembly r = every_channel();
  const uint32_t size = r.limits().message_bytes;  // as large as is taken
  CHECK_FALSE(feed(r, header_only(1, size, "HLI_STATE", 1000), 1));
  CHECK(r.messages_held() == 1);
  CHECK(r.bytes_held() > 1000);
  CHECK(r.bytes_held() < 2000);  // the 1000 bytes sent and overheads, not 32 MiB
  CHECK_FALSE(feed(r, fragment(1, size, lcm_fragment_max_payload, 3, fragments_for(size), "", Bytes(60000, 1)), 1));
  CHECK(r.bytes_held() > 61000);
  CHECK(r.bytes_held() < 62000);
  CHECK(r.refused().empty());
}

TEST_CASE("RIG-9 fragment reassembly: a flood of partial messages stays within the cap, a real 200 KB message among "
          "it is still put together",
          "[reassembly]") {
  FragmentReassembly r = every_channel();
  const Bytes message = pattern(200 * 1000);
  const std::vector<Bytes> fragments = lcm_fragments(77, "HLI_STATE", message);
  REQUIRE(fragments.size() == 4);
  size_t most = 0;
  uint32_t seqno = 1000;
  uint16_t port = 2000;
  auto flood = [&](int n) {
    for (int i = 0; i < n; ++i, ++seqno, ++port) {
      // Alternately beyond the message cap, and just within it with two
      // full fragments of data, each from a sender of its own (its own port).
      const uint32_t size = i % 2 ? 256 * mib : r.limits().message_bytes;
      CHECK_FALSE(feed(r, header_only(seqno, size, rig_channels[seqno % rig_channels.size()], 65000), port));
      if (i % 2 == 0)
        CHECK_FALSE(feed(r, fragment(seqno, size, 65000, 1, fragments_for(size), "", Bytes(65000, 1)), port));
      most = std::max(most, r.bytes_held());
    }
  };
  flood(3000);  // 1500 within the message cap, 186 MiB of data: more than the total cap holds
  std::optional<FragmentReassembly::Message> whole;
  for (const Bytes& f : fragments) {
    CHECK_FALSE(whole);
    whole = feed(r, f, 1);
    flood(600);  // 300 partial messages that fill the cap: more than it holds along with the message
  }
  REQUIRE(whole);
  CHECK(whole->framed);
  CHECK(whole->channel == "HLI_STATE");
  CHECK(whole->bytes == message);
  CHECK(most <= r.limits().total_bytes);
  CHECK(r.messages_held() <= r.limits().messages);
  int64_t oversized = 0;
  for (const auto& [channel, counts] : r.refused().by_channel()) oversized += counts.oversized;
  CHECK(oversized > 2100);  // every header beyond the cap, and the partial messages given up for room
  CHECK_FALSE(r.refused().fails_run());
}

TEST_CASE("RIG-9 fragment reassembly: no buffer for a channel nobody here subscribes to", "[reassembly]") {
  FragmentReassembly r([](const std::string& channel) { return channel == "AXIS_X_CMD"; });
  const Bytes message = pattern(150000);
  for (const Bytes& f : lcm_fragments(5, "AXIS_Y_CMD", message)) {
    CHECK_FALSE(feed(r, f, 1));
    CHECK(r.messages_held() == 0);
    CHECK(r.bytes_held() == 0);
  }
  CHECK_FALSE(feed(r, header_only(6, 256 * mib, "AXIS_Y_CMD"), 2));
  CHECK(r.refused().empty());  // not refused: not asked for, as the kernel filter drops it
  std::optional<FragmentReassembly::Message> whole;
  for (const Bytes& f : lcm_fragments(7, "AXIS_X_CMD", message)) whole = feed(r, f, 3);
  REQUIRE(whole);
  CHECK(whole->bytes == message);
}

TEST_CASE("RIG-9 fragment reassembly: fragments out of order and twice, fragments before fragment 0 have no buffer",
          "[reassembly]") {
  FragmentReassembly r = every_channel();
  const Bytes message = pattern(300000);
  const std::vector<Bytes> f = lcm_fragments(9, "HIL_EVENT", message);
  REQUIRE(f.size() == 5);
  std::vector<std::optional<FragmentReassembly::Message>> out;
  for (const size_t i : {0, 3, 0, 1, 3, 4, 1})  // fragment 0 first (it names the channel), the rest in any order
    out.push_back(feed(r, f[i], 1));
  for (const auto& m : out) CHECK_FALSE(m);
  CHECK(r.messages_held() == 1);
  const auto whole = feed(r, f[2], 1);
  REQUIRE(whole);
  CHECK(whole->bytes == message);
  CHECK(r.messages_held() == 0);
  CHECK(r.bytes_held() == 0);
  CHECK(r.refused().empty());  // a duplicate is the network's, not refused

  for (size_t i = 1; i < f.size(); ++i) CHECK_FALSE(feed(r, f[i], 2));  // fragment 0 last: dropped, as LCM 1.3.1
  CHECK_FALSE(feed(r, f[0], 2));
  CHECK(r.messages_held() == 1);
}

TEST_CASE("RIG-9 fragment reassembly: a fragment beyond its announced size, or overlapping another, ends the message "
          "as undecodable",
          "[reassembly]") {
  FragmentReassembly r = every_channel();
  const std::vector<Bytes> f = lcm_fragments(3, "HLI_CONTROL", pattern(200000));
  const uint16_t count = 4;
  CHECK_FALSE(feed(r, f[0], 1));
  CHECK_FALSE(feed(r, fragment(3, 200000, 199000, 1, count, "", Bytes(5000, 1)), 1));  // ends past 200000
  CHECK(r.messages_held() == 0);
  CHECK(r.bytes_held() == 0);
  CHECK(r.refused().by_channel().at("HLI_CONTROL").undecodable == 2);  // fragment 0 and the bad one
  CHECK_FALSE(feed(r, f[1], 1));  // the rest find no buffer
  CHECK(r.messages_held() == 0);

  CHECK_FALSE(feed(r, fragment(4, 200000, 0, 0, count, "HLI_STATE", Bytes(1000, 1)), 2));
  CHECK_FALSE(feed(r, fragment(4, 200000, 300000, 1, count, "", Bytes(10, 1)), 2));  // offset beyond the size
  CHECK(r.refused().by_channel().at("HLI_STATE").undecodable == 2);

  CHECK_FALSE(feed(r, fragment(5, 200000, 0, 0, count, "HIL_EVENT", Bytes(1000, 1)), 3));
  CHECK_FALSE(feed(r, fragment(5, 200000, 500, 1, count, "", Bytes(1000, 1)), 3));  // over fragment 0's bytes
  CHECK(r.refused().by_channel().at("HIL_EVENT").undecodable == 2);
  CHECK_FALSE(feed(r, fragment(7, 200000, 0, 0, count, "HIL_EVENT", Bytes(1000, 1)), 3));
  CHECK_FALSE(feed(r, fragment(7, 200000, 5000, 2, count, "", Bytes(1000, 1)), 3));
  CHECK_FALSE(feed(r, fragment(7, 200000, 4500, 1, count, "", Bytes(1000, 1)), 3));  // into fragment 2's bytes
  CHECK(r.refused().by_channel().at("HIL_EVENT").undecodable == 5);

  CHECK_FALSE(feed(r, fragment(6, 2000, 0, 0, 2, "HIL_PARTICIPANT", Bytes(1000, 1)), 4));
  CHECK_FALSE(feed(r, fragment(6, 2000, 1000, 1, 3, "", Bytes(1000, 1)), 4));  // another fragment count
  CHECK(r.refused().by_channel().at("HIL_PARTICIPANT").undecodable == 2);
  CHECK(r.bytes_held() == 0);
  CHECK(r.refused().fails_run());  // bytes that cannot be read, as an unframed datagram
}

TEST_CASE("RIG-9 fragment reassembly: zero, too many or too few fragments for the size get no buffer", "[reassembly]") {
  FragmentReassembly r = every_channel();
  CHECK_FALSE(feed(r, fragment(1, 200000, 0, 0, 0, "HLI_STATE", Bytes(1000, 1)), 1));      // zero fragments
  CHECK_FALSE(feed(r, fragment(2, 200000, 0, 1, 0, "", Bytes(1000, 1)), 2));               // number >= count, no first
  CHECK_FALSE(feed(r, fragment(3, 2000, 0, 0, 65535, "HLI_STATE", Bytes(1000, 1)), 3));    // more than bytes
  CHECK_FALSE(feed(r, fragment(4, 30 * mib, 0, 0, 65535, "HLI_STATE", Bytes(1000, 1)), 4));  // 480 B a fragment: fine
  CHECK(r.messages_held() == 1);
  CHECK_FALSE(feed(r, fragment(5, 200000, 0, 0, 1, "HLI_STATE", Bytes(1000, 1)), 5));      // 200 KB in one datagram
  CHECK_FALSE(feed(r, fragment(6, 200000, 7, 0, 4, "HLI_STATE", Bytes(1000, 1)), 6));      // fragment 0 not at 0
  CHECK(r.messages_held() == 1);
  CHECK(r.refused().by_channel().at("HLI_STATE").undecodable == 4);
  // A datagram shorter than the header, or not LC03: nothing.
  const Bytes shorter(19, 0);
  CHECK_FALSE(r.take(shorter.data(), shorter.size(), {1, 1}, 0));
  CHECK(r.refused().by_channel().at("HLI_STATE").total() == 4);
}

TEST_CASE("RIG-9 fragment reassembly: fragment 0 without a channel name is handed on unframed", "[reassembly]") {
  FragmentReassembly r = every_channel();
  const auto m = feed(r, fragment(1, 200000, 0, 0, 4, std::string(70, 'X'), {}), 1);  // its NUL past 64 bytes
  REQUIRE(m);
  CHECK_FALSE(m->framed);
  CHECK(r.messages_held() == 0);
}

TEST_CASE("RIG-9 fragment reassembly: a sender's next message replaces its unfinished one, a message that stopped "
          "growing is dropped",
          "[reassembly]") {
  FragmentReassembly r = every_channel();
  const Bytes first = pattern(150000), second = pattern(140000);
  const std::vector<Bytes> a = lcm_fragments(1, "HLI_STATE", first), b = lcm_fragments(2, "HLI_STATE", second);
  CHECK_FALSE(feed(r, a[0], 1));
  CHECK_FALSE(feed(r, a[1], 1));
  CHECK_FALSE(feed(r, b[0], 1));  // the sender went on: the first lost its last fragment
  CHECK(r.messages_held() == 1);
  CHECK_FALSE(feed(r, a[2], 1));  // no buffer for it any more, and the second goes on
  CHECK_FALSE(feed(r, b[1], 1));
  const auto whole = feed(r, b[2], 1);
  REQUIRE(whole);
  CHECK(whole->bytes == second);
  CHECK(r.refused().empty());  // lost, not refused: the log misses the message and says so

  const int64_t t0 = 5'000'000, stale = r.limits().stale_after_us;
  CHECK_FALSE(feed(r, a[0], 7, t0));
  CHECK_FALSE(feed(r, a[1], 7, t0 + stale));  // still growing
  r.drop_stale(t0 + stale + stale / 2);
  CHECK(r.messages_held() == 1);
  r.drop_stale(t0 + 2 * stale + 1);
  CHECK(r.messages_held() == 0);
  CHECK(r.bytes_held() == 0);
  CHECK_FALSE(feed(r, a[0], 8, t0));
  CHECK_FALSE(feed(r, b[0], 9, t0 + stale + 1));  // any fragment that comes drops what went stale
  CHECK(r.messages_held() == 1);
}

TEST_CASE("RIG-9 fragment reassembly: at most `messages` partial messages, the least recently grown given up",
          "[reassembly]") {
  FragmentReassembly::Limits limits;
  limits.messages = 8;
  FragmentReassembly r([](const std::string&) { return true; }, limits);
  const Bytes message = pattern(100000);
  const std::vector<Bytes> f = lcm_fragments(1, "HLI_STATE", message);
  CHECK_FALSE(feed(r, f[0], 1));
  for (uint16_t i = 0; i < 7; ++i)
    CHECK_FALSE(feed(r, header_only(i, 200000, "HIL_EVENT", 10), static_cast<uint16_t>(100 + i)));
  CHECK(r.messages_held() == 8);
  CHECK_FALSE(feed(r, header_only(99, 200000, "HIL_EVENT", 10), 200));  // the 9th: the HLI_STATE message is the oldest
  CHECK(r.messages_held() == 8);
  CHECK(r.refused().by_channel().at("HLI_STATE").oversized == 1);
  CHECK_FALSE(feed(r, f[1], 1));  // no buffer left for it
  CHECK(r.messages_held() == 8);
}
