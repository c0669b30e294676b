// hil_inject: the integration tests' intruder (RIG-9). Joins a running rig,
// learns its run id from the manifest, waits for a cycle and then sends what
// the rig must refuse and survive: forged answers of this run with a cycle
// far ahead, another run's answers, a message of the wrong type, datagrams
// LCM 1.3.1 cannot frame (a channel name without NUL, through a raw UDP
// socket), and it can kill or pause a node at that cycle (its pid from a
// file). Without the run's secret it is an outsider: all it sends of the
// run is refused as unauthenticated (RIG-12); with it (--key-file) a faulty
// participant of the run, whose messages the receivers' own rules refuse.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <thread>

#include "bus.hpp"
#include "channels.hpp"
#include "command_line.hpp"
#include "run_secret.hpp"

namespace {

struct Rig {
  int64_t run_id = 0;
  int64_t cycle = -1;
};

// One datagram: LCM's short-message header, then a channel name that runs
// to the end with no NUL (19 bytes for HLI_CONTROL).
void send_unframed(const std::string& url, const std::string& channel) {
  std::smatch m;
  if (!std::regex_search(url, m, std::regex("udpm://([0-9.]+):([0-9]+)"))) throw std::runtime_error("bad url " + url);
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(static_cast<uint16_t>(std::stoi(m[2])));
  ::inet_pton(AF_INET, std::string(m[1]).c_str(), &to.sin_addr);
  unsigned char ttl = 0;
  ::setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
  std::string datagram = "LC02";  // LCM2_MAGIC_SHORT
  datagram += std::string("\0\0\0\1", 4);  // sequence number
  datagram += channel;              // no NUL
  if (::sendto(fd, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to) < 0)
    throw std::runtime_error(std::string("sendto: ") + std::strerror(errno));
  ::close(fd);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hil_inject: sends what a rig must refuse, at a cycle of its run"};
  std::string url, pid_file;
  int64_t at_cycle = 100;
  std::vector<std::string> forge_state, foreign_state, wrong_type, unsigned_state;
  std::string key_file;
  bool forge_control = false, forge_run_end = false, forge_pass = false;
  int forge_alive = 0;
  int unframed = 0;
  app.add_option("--url", url, "the rig's LCM URL")->required();
  app.add_option("--at-cycle", at_cycle, "act once the rig's HLI_STATE reaches this cycle");
  app.add_option("--forge-state", forge_state, "AXIS_<A>_STATE of this run, a million cycles ahead");
  app.add_flag("--forge-control", forge_control, "HLI_CONTROL of this run, a million cycles ahead, feed hold on");
  app.add_option("--foreign-state", foreign_state, "AXIS_<A>_STATE of another run, for the next cycle");
  app.add_option("--wrong-type", wrong_type, "an hli_control_t of this run on AXIS_<A>_STATE");
  app.add_option("--unsigned-state", unsigned_state,
                 "AXIS_<A>_STATE of this run for the next cycle with a drive error, never signed (an outsider)");
  app.add_flag("--forge-run-end", forge_run_end, "the cnc's RUN_END of this run at this cycle");
  app.add_option("--forge-alive", forge_alive, "this many 'logger' ALIVE heartbeats of this run, 100000 cycles ahead, 50 ms apart (after a kill)");
  app.add_flag("--forge-pass", forge_pass, "a plc_sim PASS verdict event of this run");
  app.add_option("--key-file", key_file, "the run's secret, read when acting: what it forges is signed (an insider)");
  app.add_option("--unframed", unframed, "this many 19-byte datagrams on HLI_CONTROL with no NUL");
  app.add_option("--kill-pid-file", pid_file, "SIGKILL the process whose pid this file holds");
  double pause_s = 0;
  app.add_option("--pause-s", pause_s, "instead of a kill: SIGSTOP, and SIGCONT this many seconds later")
      ->check(CLI::Range(0.0, 60.0));
  HIL_PARSE_COMMAND_LINE(app, argc, argv);

  lcm::LCM lcm(url);
  if (!lcm.good()) return 2;
  Rig rig;
  lcm.subscribeFunction(
      hil::channels::manifest,
      +[](const lcm::ReceiveBuffer*, const std::string&, const hil::run_manifest_t* m, Rig* r) {
        if (r->run_id == 0) r->run_id = m->run_id;
      },
      &rig);
  lcm.subscribeFunction(
         hil::channels::hli_state,
         +[](const lcm::ReceiveBuffer*, const std::string&, const hil::hli_state_t* m, Rig* r) {
           if (m->run_id == r->run_id) r->cycle = std::max(r->cycle, m->cycle);
         },
         &rig)
      ->setQueueCapacity(1000000);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (rig.cycle < at_cycle) {
    if (std::chrono::steady_clock::now() > give_up) {
      std::cerr << "hil_inject: the rig did not reach cycle " << at_cycle << '\n';
      return 1;
    }
    lcm.handleTimeout(100);
  }
  const int64_t k = rig.cycle;
  std::optional<hil::lcm_support::RunSecret> secret;
  if (!key_file.empty()) secret = hil::lcm_support::RunSecret::read(key_file);
  // Signed with the run's secret if it has it.
  auto send = [&](const std::string& channel, const auto& message) {
    std::vector<uint8_t> bytes = hil::lcm_support::encode(message);
    if (secret) secret->sign(channel, bytes.data(), bytes.size());
    lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
  };
  for (const auto& axis : forge_state) {
    hil::axis_state_t s{};
    s.run_id = rig.run_id;
    s.cycle = k + 1000000;
    s.axis = axis;
    send(hil::channels::axis_state(axis), s);
  }
  if (forge_control) {
    hil::hli_control_t c{};
    c.run_id = rig.run_id;
    c.cycle = k + 1000000;
    c.feedhold.command_w = c.feedhold.enable_w = true;
    send(hil::channels::hli_control, c);
  }
  for (const auto& axis : foreign_state) {
    hil::axis_state_t s{};
    s.run_id = rig.run_id + 1;
    s.cycle = k + 1;
    s.axis = axis;
    s.errors = hil::axis_state_t::MONITOR_ACCELERATION;  // a fake drive error, if it were taken
    lcm.publish(hil::channels::axis_state(axis), &s);
  }
  for (const auto& axis : wrong_type) {
    hil::hli_control_t c{};
    c.run_id = rig.run_id;
    c.cycle = k + 1;
    send(hil::channels::axis_state(axis), c);
  }
  for (const auto& axis : unsigned_state) {
    hil::axis_state_t s{};
    s.run_id = rig.run_id;
    s.cycle = k + 1;
    s.axis = axis;
    s.errors = hil::axis_state_t::MONITOR_ACCELERATION;  // a fake drive error, if it were taken
    lcm.publish(hil::channels::axis_state(axis), &s);
  }
  if (forge_run_end) {
    hil::participant_t end{};
    end.run_id = rig.run_id;
    end.cycle = k;
    end.name = "cnc";
    end.phase = hil::participant_t::PHASE_RUN_END;
    send(hil::channels::participant, end);
  }
  if (forge_pass) {
    hil::event_t e{};
    e.run_id = rig.run_id;
    e.cycle = k;
    e.verdict = hil::event_t::VERDICT_PASS;
    e.source = "plc_sim";
    e.message = "PASS at channel_state=PROGRAM_END: all checks hold";
    send(hil::channels::event, e);
  }
  for (int i = 0; i < unframed; ++i) send_unframed(url, hil::channels::hli_control);
  if (!pid_file.empty()) {
    pid_t pid = 0;
    std::ifstream(pid_file) >> pid;
    if (pid <= 0 || ::kill(pid, pause_s > 0 ? SIGSTOP : SIGKILL) != 0) {
      std::cerr << "hil_inject: cannot signal pid " << pid << " from " << pid_file << '\n';
      return 1;
    }
    if (pause_s > 0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(pause_s));
      ::kill(pid, SIGCONT);
    }
  }
  // After a kill: heartbeats that would hide a killed logger, 50 ms apart.
  for (int i = 0; i < forge_alive; ++i) {
    hil::participant_t alive{};
    alive.run_id = rig.run_id;
    alive.cycle = k + 100000;
    alive.name = "logger";
    alive.phase = hil::participant_t::PHASE_ALIVE;
    send(hil::channels::participant, alive);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::cout << "hil_inject: acted at cycle " << k << " of run " << rig.run_id << '\n';
  return 0;
}
