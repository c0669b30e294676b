// The in-process bus and what the logger writes with it (issue 17, RIG-1,
// RIG-4): messages handed on in the order they were published, to every
// subscriber of the channel; the event log readable by LCM's reader.
#include <arpa/inet.h>
#include <hil/axis_state_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <linux/filter.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "channels.hpp"
#include "event_log_writer.hpp"
#include "in_process_bus.hpp"
#include "inbox.hpp"
#include "udpm_bus.hpp"
#include "wire.hpp"

using namespace hil;

namespace {

std::string text(const lcm::ReceiveBuffer& rbuf) {
  return std::string(static_cast<const char*>(rbuf.data), rbuf.data_size);
}

}  // namespace

TEST_CASE("issue 17 in-process bus: publish order, every subscriber, a publish while handing on queued behind",
          "[bus]") {
  lcm_support::InProcessBus bus;
  std::vector<std::string> seen;
  bus.subscribe(channels::every_channel_but_self_test,
                [&](const lcm::ReceiveBuffer& rbuf, const std::string& ch) { seen.push_back("all " + ch + " " + text(rbuf)); },
                10);
  bus.subscribe("A", [&](const lcm::ReceiveBuffer& rbuf, const std::string&) {
    seen.push_back("a " + text(rbuf));
    bus.publish("B", "answer", 6);  // as a node answers from its handler
  }, 10);
  const int b = bus.subscribe("B", [&](const lcm::ReceiveBuffer& rbuf, const std::string&) { seen.push_back("b " + text(rbuf)); }, 10);
  bus.publish("A", "one", 3);
  bus.publish("LCM_SELF_TEST", "x", 1);
  bus.publish("A", "two", 3);
  CHECK_FALSE(bus.empty());
  bus.drain();
  CHECK(bus.empty());
  CHECK(seen == std::vector<std::string>{"all A one", "a one", "all A two", "a two", "all B answer", "b answer",
                                         "all B answer", "b answer"});
  seen.clear();
  bus.unsubscribe(b);
  bus.publish("B", "late", 4);
  CHECK(bus.handle_timeout(0) == 1);
  CHECK(seen == std::vector<std::string>{"all B late"});
  CHECK(bus.handle_timeout(0) == 0);  // nothing queued: nothing can come
}

TEST_CASE("issue 17 identify_header: run and cycle from the fingerprint and the header, as identify decodes them",
          "[bus]") {
  hil::axis_state_t s{};
  s.run_id = 42;
  s.utime = 7000;
  s.cycle = 7;
  s.axis = "Y";
  const std::vector<uint8_t> bytes = test::encoded(s);
  const auto size = static_cast<uint32_t>(bytes.size());
  const auto decoded = lcm_support::identify("AXIS_Y_STATE", bytes.data(), size);
  const auto header = lcm_support::identify_header("AXIS_Y_STATE", bytes.data(), size);
  REQUIRE(decoded);
  REQUIRE(header);
  CHECK(header->run_id == 42);
  CHECK(header->cycle == 7);
  CHECK(header->run_id == decoded->run_id);
  CHECK(header->cycle == decoded->cycle);
  CHECK_FALSE(lcm_support::identify_header("HLI_STATE", bytes.data(), size));  // another type's fingerprint
  CHECK_FALSE(lcm_support::identify_header("AXIS_Y_STATE", bytes.data(), 31));
  CHECK_FALSE(lcm_support::identify_header("ELSEWHERE", bytes.data(), size));
}

TEST_CASE("issue 17 RIG-4 event log writer: LCM's reader reads every event back, numbered from 0", "[bus]") {
  const std::string path = (std::filesystem::temp_directory_path() / "hil_event_log_writer_test.lcmlog").string();
  const std::vector<std::string> payloads{"", "x", std::string(70000, 'y')};
  {
    logger::EventLogWriter writer(path);
    for (size_t i = 0; i < payloads.size(); ++i)
      writer.write("CHANNEL_" + std::to_string(i), payloads[i].data(), static_cast<uint32_t>(payloads[i].size()),
                   1000 + static_cast<int64_t>(i));
  }
  lcm::LogFile log(path, "r");
  REQUIRE(log.good());
  for (size_t i = 0; i < payloads.size(); ++i) {
    const lcm::LogEvent* e = log.readNextEvent();
    REQUIRE(e);
    CHECK(e->eventnum == static_cast<int64_t>(i));
    CHECK(e->timestamp == 1000 + static_cast<int64_t>(i));
    CHECK(e->channel == "CHANNEL_" + std::to_string(i));
    CHECK(std::string(static_cast<const char*>(e->data), e->datalen) == payloads[i]);
  }
  CHECK(log.readNextEvent() == nullptr);
  std::remove(path.c_str());
  CHECK_THROWS(logger::EventLogWriter("/nonexistent/dir/x.lcmlog"));
}

namespace {

// An LCM short datagram (LCM 1.3.1 udpm_util.h): magic "LC02", sequence
// number, channel, NUL, payload.
std::string lcm_datagram(const std::string& channel, const std::string& payload) {
  return std::string("LC02") + std::string(4, '\0') + channel + '\0' + payload;
}

}  // namespace

TEST_CASE("issue 17 udpm bus: the kernel filter lets in LCM datagrams of the subscribed channels only", "[bus]") {
  const std::vector<lcm_support::FilterInstruction> program =
      lcm_support::channel_filter({"AXIS_X_CMD", "HIL_PARTICIPANT", "A"});
  std::vector<sock_filter> code;
  for (const auto& i : program) code.push_back({i.code, i.jt, i.jf, i.k});
  const sock_fprog fprog{static_cast<unsigned short>(code.size()), code.data()};

  const int receiver = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0), sender = socket(AF_INET, SOCK_DGRAM, 0);
  REQUIRE(receiver >= 0);
  REQUIRE(sender >= 0);
  sockaddr_in at{};
  at.sin_family = AF_INET;
  at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(bind(receiver, reinterpret_cast<sockaddr*>(&at), sizeof at) == 0);
  socklen_t length = sizeof at;
  REQUIRE(getsockname(receiver, reinterpret_cast<sockaddr*>(&at), &length) == 0);
  REQUIRE(setsockopt(receiver, SOL_SOCKET, SO_ATTACH_FILTER, &fprog, sizeof fprog) == 0);

  const std::vector<std::string> sent{
      lcm_datagram("AXIS_X_CMD", "setpoint"),   // in
      lcm_datagram("AXIS_Y_CMD", "setpoint"),   // another axis: out
      lcm_datagram("AXIS_X_CMDS", "x"),         // a longer name: out
      lcm_datagram("AXIS_X_CM", "x"),           // a shorter one: out
      lcm_datagram("HIL_PARTICIPANT", "ready"),  // in
      lcm_datagram("A", "one byte name"),       // in
      std::string("LC03") + std::string(16, '\0') + "AXIS_X_CMD",  // a fragment: out
      "AXIS_X_CMD",                             // no LCM datagram: out
  };
  for (const std::string& d : sent)
    REQUIRE(sendto(sender, d.data(), d.size(), 0, reinterpret_cast<sockaddr*>(&at), sizeof at) ==
            static_cast<ssize_t>(d.size()));
  std::vector<std::string> received;
  char buffer[256];
  for (ssize_t n; (n = recv(receiver, buffer, sizeof buffer, 0)) > 0;) received.emplace_back(buffer, n);
  CHECK(received == std::vector<std::string>{sent[0], sent[4], sent[5]});
  close(receiver);
  close(sender);
  CHECK(lcm_support::channel_filter({std::string(64, 'x')}).empty());  // longer than LCM allows
}
