#include "live_spy.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "config_error.hpp"
#include "tools.hpp"

namespace hil::rig {

bool udp_port_bound(int port) {
  for (const char* table : {"/proc/net/udp", "/proc/net/udp6"}) {
    std::ifstream in(table);
    std::string line;
    std::getline(in, line);  // the header
    while (std::getline(in, line)) {
      // "  12: 00000000:1A0B 00000000:0000 07 ..." : the local address' port in hex
      std::istringstream fields(line);
      std::string slot, local;
      fields >> slot >> local;
      const size_t colon = local.rfind(':');
      if (colon == std::string::npos) continue;
      if (std::strtol(local.c_str() + colon + 1, nullptr, 16) == port) return true;
    }
  }
  return false;
}

LiveSpy::LiveSpy(const std::string& bin_dir, const std::string& url, int port, const std::string& output_file,
                 std::chrono::milliseconds timeout)
    : output_file_(output_file) {
  if (udp_port_bound(port))
    throw ConfigError("--spy: udp port " + std::to_string(port) + " is in use already: choose another with --port");
  if (!prepare_java_tools(bin_dir)) throw ConfigError("--spy: no types jar for lcm-spy");
  spy_ = std::make_unique<Process>("lcm-spy", spy_command(url), output_file);
  const auto give_up = std::chrono::steady_clock::now() + timeout;
  while (!udp_port_bound(port)) {
    if (const std::optional<int> status = spy_->poll()) {
      const std::string said = last_line_of(output_file);
      throw ConfigError("--spy: lcm-spy ended (status " + std::to_string(*status) + ") before it listened" +
                        (said.empty() ? "" : ": " + said) + " (its output: " + output_file + ")");
    }
    if (std::chrono::steady_clock::now() > give_up)
      throw ConfigError("--spy: lcm-spy did not listen on port " + std::to_string(port) + " within " +
                        std::to_string(timeout.count() / 1000) + " s (its output: " + output_file + ")");
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

int LiveSpy::wait_closed() {
  for (;;)
    if (const std::optional<int> status = spy_->wait_for(std::chrono::seconds(1))) return *status;
}

}  // namespace hil::rig
