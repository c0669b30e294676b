// RIG-9: the logger's subscription loses no message of a run's first cycles.
// Each attempt opens LCM and subscribes as hil_logger does while another
// instance sends LCM_SELF_TEST (as nodes starting beside it do), then sends
// DATA messages 0..n-1 and counts those handled. With LCM 1.3.1 a ".*"
// subscription loses some whenever a self-test message was still queued for
// LCM's own self-test subscription when it ended. Prints the losses with the
// logger's subscription (channels::every_channel_but_self_test) and with
// ".*"; exits 1 if the logger's lost any.
#include "command_line.hpp"
#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "channels.hpp"

namespace {

// DATA messages handled of `n` sent after subscribing `pattern`.
int handled(const std::string& url, const std::string& pattern, int n) {
  lcm::LCM other(url);
  std::atomic<bool> starting{true};
  std::thread self_tests([&] {
    while (starting) {
      other.publish(hil::channels::lcm_self_test, "x", 1);
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  lcm::LCM lcm(url);
  int got = 0;
  lcm.subscribeFunction(
         pattern,
         +[](const lcm::ReceiveBuffer*, const std::string& channel, int* got) {
           if (channel == "DATA") ++*got;
         },
         &got)
      ->setQueueCapacity(1000000);
  starting = false;
  self_tests.join();
  for (int i = 0; i < n; ++i) other.publish("DATA", &i, sizeof i);
  while (lcm.handleTimeout(300) > 0) {
  }
  return got;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lcm_queue_check: the logger's subscription against LCM 1.3.1's queue accounting: no message lost "
               "while nodes start beside it (RIG-9, docs/RELIABILITY.md)"};
  std::string url;
  int attempts = 0;
  app.add_option("url", url, "udpm URL (ttl=0)")->required();
  app.add_option("attempts", attempts, "rounds of 200 messages")->required()->check(CLI::PositiveNumber);
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  const int n = 200;
  int lost = 0, lost_any = 0, attempts_losing = 0, attempts_losing_any = 0;
  for (int a = 0; a < attempts; ++a) {
    const int l = n - handled(url, hil::channels::every_channel_but_self_test, n);
    const int l_any = n - handled(url, ".*", n);
    lost += l;
    lost_any += l_any;
    attempts_losing += l > 0;
    attempts_losing_any += l_any > 0;
  }
  std::printf("%s: %d of %d messages lost, in %d of %d attempts\n", hil::channels::every_channel_but_self_test.c_str(), lost,
              attempts * n, attempts_losing, attempts);
  std::printf(".*: %d of %d messages lost, in %d of %d attempts\n", lost_any, attempts * n, attempts_losing_any,
              attempts);
  return lost == 0 ? 0 : 1;
}
