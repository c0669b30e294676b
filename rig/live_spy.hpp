#pragma once
// `hil run --spy` (issue 37, RIG-7): lcm-spy on the run's URL before the run
// starts, so that it sees cycle 0 on; the run then goes paced (--pace,
// default 1) so that there is something to watch. A lock-step demo run ends
// in about a second of wall time: started by hand beside it, lcm-spy
// subscribes after it has ended and shows an empty window.
#include <chrono>
#include <memory>
#include <string>

#include "process.hpp"

namespace hil::rig {

class LiveSpy {
 public:
  // Starts lcm-spy (spy_command) on `url` and waits until it has a socket
  // on `port` (it listens), at most `timeout`. Throws ConfigError if it
  // ends first or never listens, with its last line of output.
  LiveSpy(const std::string& bin_dir, const std::string& url, int port, const std::string& output_file,
          std::chrono::milliseconds timeout = std::chrono::seconds(30));
  // Until the user closes lcm-spy; its exit status.
  int wait_closed();

 private:
  std::unique_ptr<Process> spy_;
  std::string output_file_;
};

// Whether a UDP socket of this machine (this network namespace) is bound to
// `port`: /proc/net/udp and udp6.
bool udp_port_bound(int port);

}  // namespace hil::rig
