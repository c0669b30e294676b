#pragma once
// The Bus over LCM's udpm multicast with the receive path in the node's own
// thread (issue 17). Messages go out through liblcm (lcm_publish: LCM's
// datagrams, seen by lcm-spy and every LCM reader); they come in on a socket
// of this bus joined to the same group and port, read where the node waits,
// not by LCM 1.3.1's read thread that hands each message on through a pipe
// (two wake-ups a message). A kernel socket filter lets in only the channels
// subscribed by name, so that a node is not woken for the messages of
// others. Reads LCM's short and fragmented datagrams (fragment_reassembly:
// only what arrived is held, within caps; refused() counts what is not).
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bus.hpp"

namespace hil::lcm_support {

struct UdpmReceive {
  // Wait this long after the socket ran dry before reading again, to read
  // many datagrams per wake-up (the logger: behind, but off the CPU the
  // lock-step nodes need). 0: read as each arrives.
  std::chrono::microseconds batch{0};
};

// `url`: udpm://GROUP:PORT?ttl=..&recv_buf_size=..; throws naming what fails.
std::unique_ptr<Bus> udpm_bus(const std::string& url, UdpmReceive receive = {});

// A rig node's bus on `url`: udpm_bus for udpm://, LCM itself for any
// other URL (file://, memq://).
std::unique_ptr<Bus> node_bus(const std::string& url, UdpmReceive receive = {});

// A classic BPF program (for SO_ATTACH_FILTER on a UDP socket: offsets from
// the UDP header) that accepts LCM short datagrams on the given channels and
// drops every other datagram. Empty if a name is too long for it.
struct FilterInstruction {
  uint16_t code;
  uint8_t jt, jf;
  uint32_t k;
};
std::vector<FilterInstruction> channel_filter(const std::vector<std::string>& channels);

}  // namespace hil::lcm_support
