// The udpm bus's sending side against LCM's own receiver (issue 17, RIG-1):
// what a node publishes is held until it next waits, then sent in one
// system call; LCM (as lcm-spy and every LCM reader) must still receive
// every message, in the order published, a long (fragmented) one among
// short ones included, and what a bus holds when it ends. Exit 0 if so.
// Run in a network namespace with a multicast route (scripts/in_netns.sh).
#include <lcm/lcm-cpp.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "udpm_bus.hpp"

int main(int argc, char** argv) {
  // A deep receive buffer: the burst (a 100 kB message among 200) must not overflow it under load.
  const std::string url = argc > 1 ? argv[1] : "udpm://239.255.76.67:7798?ttl=0&recv_buf_size=4194304";
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
