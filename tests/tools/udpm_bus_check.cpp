// The udpm bus's sending side against LCM's own receiver (issue 17, RIG-1):
// what a node publishes is held until it next waits, then sent in one
// system call; LCM (as lcm-spy and every LCM reader) must still receive
// every message, in the order published, a long (fragmented) one among
// short ones included, and what a bus holds when it ends. Exit 0 if so.
// With `fragment-flood`, the receiving side (RIG-9, issue 33): fragment
// headers announcing 256 MiB on rig channels, each from a socket of its own,
// cost the bus no memory and are counted per channel; a 200 kB message that
// liblcm fragments among them still arrives whole.
// Run in a network namespace with a multicast route (scripts/in_netns.sh).
#include "command_line.hpp"
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "channels.hpp"
#include "fragment_reassembly.hpp"
#include "udpm_bus.hpp"

namespace {

// VmHWM (peak resident memory) of this process, KiB.
long peak_rss_kib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

// Fragment 0 of a message of `size` bytes on `channel` that never follows,
// from a socket of its own (a sender of its own to the receiver).
void send_header(const sockaddr_in& group, uint32_t seqno, uint32_t size, const std::string& channel) {
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  const unsigned char ttl = 0;
  setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
  const uint32_t fragments = (size + 64) / hil::lcm_support::lcm_fragment_max_payload + 1;
  const uint32_t header[4] = {htonl(hil::lcm_support::lcm_fragment_magic), htonl(seqno), htonl(size), 0};
  const uint16_t numbers[2] = {0, htons(static_cast<uint16_t>(fragments))};
  std::vector<uint8_t> d(sizeof header + sizeof numbers);
  std::memcpy(d.data(), header, sizeof header);
  std::memcpy(d.data() + sizeof header, numbers, sizeof numbers);
  d.insert(d.end(), channel.c_str(), channel.c_str() + channel.size() + 1);
  d.resize(d.size() + 1000, 0xAB);
  sendto(fd, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&group), sizeof group);
  close(fd);
}

int fragment_flood(const std::string& url) {
  std::smatch m;
  if (!std::regex_search(url, m, std::regex("udpm://([0-9.]+):([0-9]+)"))) return std::fprintf(stderr, "bad url\n"), 1;
  sockaddr_in group{};
  group.sin_family = AF_INET;
  group.sin_port = htons(static_cast<uint16_t>(std::stoi(m[2])));
  inet_pton(AF_INET, std::string(m[1]).c_str(), &group.sin_addr);

  auto bus = hil::lcm_support::udpm_bus(url);  // every channel, as the logger
  std::string big;
  bus->subscribe(
      hil::channels::every_channel_but_self_test,
      [&](const lcm::ReceiveBuffer& rbuf, const std::string& channel) {
        if (channel == "BIG") big.assign(static_cast<const char*>(rbuf.data), rbuf.data_size);
      },
      1000);
  lcm::LCM sender(url);
  const std::vector<std::string> channels{"HLI_CONTROL", "HLI_STATE", "AXIS_X_STATE", "HIL_PARTICIPANT"};
  const std::string message(200000, 'm');
  const long before = peak_rss_kib();
  for (uint32_t i = 0; i < 80; ++i) {
    send_header(group, i, 256u << 20, channels[i % channels.size()]);
    if (i == 40) sender.publish("BIG", message.data(), static_cast<unsigned>(message.size()));  // liblcm fragments it
  }
  for (auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
       std::chrono::steady_clock::now() < until && (big.empty() || bus->refused().by_channel().size() < channels.size());)
    bus->handle_timeout(50);
  const long grown_mib = (peak_rss_kib() - before) / 1024;
  const auto refused = bus->refused();
  std::printf("80 fragment headers of 256 MiB: peak RSS grew %ld MiB; refused: %s\n", grown_mib,
              refused.describe().c_str());
  int failures = 0;
  if (big != message)
    std::fprintf(stderr, "the 200 kB message did not arrive whole (%zu bytes)\n", big.size()), ++failures;
  if (grown_mib > 64) std::fprintf(stderr, "the bus took %ld MiB for fragment headers\n", grown_mib), ++failures;
  for (const std::string& channel : channels) {
    const auto row = refused.by_channel().find(channel);
    if (row == refused.by_channel().end() || row->second.oversized != 20)
      std::fprintf(stderr, "%s: not 20 oversized\n", channel.c_str()), ++failures;
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"udpm_bus_check: the udpm bus's batched sending against LCM's own receiver (issue 17), or its "
               "receiving side under fragment headers announcing 256 MiB (fragment-flood, RIG-9)"};
  // A deep receive buffer: the burst (a 100 kB message among 200) must not overflow it under load.
  std::string url = "udpm://239.255.76.67:7798?ttl=0&recv_buf_size=4194304", mode;
  app.add_option("url", url, "udpm URL (ttl=0)")->capture_default_str();
  app.add_option("mode", mode, "fragment-flood, or nothing for the sending check")->check(CLI::IsMember({"fragment-flood"}));
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  if (mode == "fragment-flood") return fragment_flood(url);
  lcm::LCM reader(url);
  if (!reader.good()) return std::fprintf(stderr, "cannot open LCM on %s\n", url.c_str()), 1;
  std::vector<std::string> received;
  struct Collect {
    std::vector<std::string>* into;
    void on(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
      into->push_back(channel + ":" + std::string(static_cast<const char*>(rbuf->data), rbuf->data_size));
    }
  } collect{&received};
  reader.subscribe(".*", &Collect::on, &collect)->setQueueCapacity(1000);

  std::vector<std::string> sent;
  {
    auto bus = hil::lcm_support::udpm_bus(url);
    auto publish = [&](const std::string& channel, const std::string& data) {
      bus->publish(channel, data.data(), static_cast<uint32_t>(data.size()));
      sent.push_back(channel + ":" + data);
    };
    for (int cycle = 0; cycle < 50; ++cycle) {
      for (const char* axis : {"X", "Y", "Z"}) publish(std::string("AXIS_") + axis + "_CMD", std::to_string(cycle));
      if (cycle == 20) publish("BIG", std::string(100000, 'b'));  // LCM fragments it
      publish("HLI_STATE", "cycle " + std::to_string(cycle));
      bus->handle_timeout(0);  // the node waits: what it holds goes out
    }
    publish("HIL_PARTICIPANT", "end");  // held when the bus ends: sent then
  }
  while (received.size() < sent.size() && reader.handleTimeout(500) > 0) {
  }
  if (received != sent) {
    std::fprintf(stderr, "sent %zu messages, LCM received %zu", sent.size(), received.size());
    for (size_t i = 0; i < received.size() && i < sent.size(); ++i)
      if (received[i] != sent[i]) {
        std::fprintf(stderr, "; the first difference at %zu: %.40s", i, received[i].c_str());
        break;
      }
    std::fprintf(stderr, "\n");
    return 1;
  }
  std::printf("LCM received all %zu messages in the order published\n", sent.size());
  return 0;
}
