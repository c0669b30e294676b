// The `hil_logger` node (RIG-1, RIG-4, RIG-9): records every message of one
// run into a standard LCM event log, with no drops (a deep queue on its
// recording subscription, which leaves out LCM_SELF_TEST:
// channels::every_channel_but_self_test; a large socket buffer in the URL),
// and closes the log only when every participant of the run has announced
// its end — it knows them from hil run (--participants) or from the CNC's
// manifest, not from whom it happened to hear READY. It survives any
// datagram: what is not this run's, or not readable, is counted per channel
// and left out. Its last record (HIL_LOG_END) says it closed the log on
// purpose and what it missed; it writes the resolved scenario
// (HIL_SCENARIO) after the manifest.
#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <hil/scenario_text_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>

#include "channels.hpp"
#include "inbox.hpp"
#include "node_options.hpp"
#include "participant.hpp"
#include "run_identity.hpp"
#include "scenario.hpp"
#include "verdict.hpp"

namespace {

using namespace hil;
using clock_type = std::chrono::steady_clock;

// Datagrams the kernel dropped at this process' UDP sockets (its receive
// buffer was full): the "drops" column of /proc/net/udp for the socket
// inodes among /proc/self/fd. -1 if it cannot be read.
int64_t socket_drops() {
  std::set<std::string> inodes;
  std::error_code ec;
  for (const auto& fd : std::filesystem::directory_iterator("/proc/self/fd", ec)) {
    const std::string target = std::filesystem::read_symlink(fd.path(), ec).string();
    if (target.rfind("socket:[", 0) == 0) inodes.insert(target.substr(8, target.size() - 9));
  }
  std::ifstream udp("/proc/net/udp");
  if (!udp) return -1;
  int64_t drops = 0;
  std::string line;
  std::getline(udp, line);  // the header
  while (std::getline(udp, line)) {
    std::istringstream fields(line);
    std::vector<std::string> f{std::istream_iterator<std::string>(fields), {}};
    if (f.size() >= 13 && inodes.count(f[9])) drops += std::stoll(f.back());
  }
  return drops;
}

class LoggerNode {
 public:
  // run_id 0: the run of the first manifest heard (recording a replay).
  // `scenario`: the resolved scenario file's text and its NC program, or none.
  LoggerNode(lcm::LCM& lcm, const std::string& path, int64_t run_id, std::vector<std::string> participants,
             std::optional<std::pair<std::string, std::string>> scenario)
      : log_(path, "w"), run_id_(run_id), scenario_(std::move(scenario)) {
    if (!log_.good()) throw std::runtime_error("cannot write log " + path);
    for (const std::string& name : participants) attendance_.expect(name);
    told_participants_ = !participants.empty();
    // The first subscription: it must exist before any other (the inbox's
    // come after it), else it is handed messages it never counted.
    lcm.subscribeFunction(
           channels::every_channel_but_self_test,
           +[](const lcm::ReceiveBuffer* rbuf, const std::string& channel, LoggerNode* self) {
             self->receive(*rbuf, channel);
           },
           this)
        ->setQueueCapacity(1000000);
  }

  const logger::Attendance& attendance() const { return attendance_; }
  bool scenario_mismatch() const { return scenario_mismatch_; }
  int64_t recorded() const { return recorded_; }
  // Messages of the run from others than this logger: the run is alive.
  int64_t heard() const { return heard_; }
  // The last cycle of the run's HLI_STATE recorded (-1: none yet).
  int64_t recorded_cycle() const { return recorded_cycle_; }
  int64_t dropped() const { return socket_drops_; }  // by the kernel, known after seal()
  const traffic::Ledger& refused() const { return refused_; }

  // The last record: the logger closed the log, and what it missed.
  void seal() {
    hil::log_summary_t m;
    m.run_id = run_id_;
    m.utime = 0;
    m.cycle = attendance_.end_cycle();
    m.recorded = recorded_;
    m.missing = attendance_.missing();
    for (const auto& name : attendance_.lost()) m.missing.push_back(name);
    m.n_missing = static_cast<int16_t>(m.missing.size());
    m.rejected = lcm_support::to_message(refused_);
    m.n_rejected = static_cast<int16_t>(m.rejected.size());
    m.socket_drops = socket_drops_ = socket_drops();
    write(channels::log_end, m, 0);
    std::fflush(log_.getFilePtr());
  }

 private:
  struct Held {
    std::string channel;
    std::vector<uint8_t> data;
    int64_t recv_utime;
  };

  void receive(const lcm::ReceiveBuffer& rbuf, const std::string& channel) {
    if (!lcm_support::framed(rbuf)) return refused_.refuse(traffic::malformed_datagram, traffic::Refusal::undecodable);
    if (channel == channels::log_end) return;  // another logger's seal (a replay): this one writes its own
    const auto id = lcm_support::identify(channel, rbuf.data, rbuf.data_size);
    if (!id) return refused_.refuse(channel, traffic::Refusal::undecodable);
    if (run_id_ == 0 && channel == channels::manifest) adopt_run(id->run_id);
    if (run_id_ == 0) {  // not yet known: hold it (bounded) until a manifest names the run
      if (held_.size() < 100000) {
        const auto* bytes = static_cast<const uint8_t*>(rbuf.data);
        held_.push_back({channel, std::vector<uint8_t>(bytes, bytes + rbuf.data_size), rbuf.recv_utime});
      }
      return;
    }
    take(channel, *id, rbuf.data, rbuf.data_size, rbuf.recv_utime);
  }

  void adopt_run(int64_t run_id) {
    run_id_ = run_id;
    std::deque<Held> held;
    held.swap(held_);
    for (const Held& h : held)
      if (const auto id = lcm_support::identify(h.channel, h.data.data(), static_cast<uint32_t>(h.data.size())))
        take(h.channel, *id, h.data.data(), static_cast<uint32_t>(h.data.size()), h.recv_utime);
  }

  void take(const std::string& channel, const lcm_support::Identity& id, const void* data, uint32_t size,
            int64_t recv_utime) {
    if (id.run_id != run_id_) return refused_.refuse(channel, traffic::Refusal::foreign_run);
    write_raw(channel, data, size, recv_utime);
    if (channel == channels::participant) {
      hil::participant_t m;
      if (!lcm_support::decode(data, size, m)) return;
      if (m.name != "logger") ++heard_;
      if (m.phase == hil::participant_t::PHASE_RUN_END) attendance_.ended(m.name, m.cycle, m.lost);
      return;
    }
    ++heard_;
    if (channel == channels::hli_state) recorded_cycle_ = std::max(recorded_cycle_, id.cycle);
    if (channel == channels::manifest) {
      hil::run_manifest_t m;
      if (!lcm_support::decode(data, size, m)) return;
      if (!told_participants_)
        for (const auto& name : m.participants) attendance_.expect(name);
      write_scenario(m, recv_utime);
    }
  }

  // The resolved scenario, from the files hil run wrote, if it is the one
  // the CNC runs.
  void write_scenario(const hil::run_manifest_t& manifest, int64_t recv_utime) {
    if (!scenario_) return;
    const auto& [yaml, nc_program] = *scenario_;
    if (scenario_digest(yaml, nc_program) != manifest.scenario_digest ||
        static_cast<int64_t>(yaml.size() + nc_program.size()) != manifest.scenario_bytes) {
      spdlog::error("the scenario file is not the one the CNC runs (digest and size differ from the manifest's)");
      scenario_mismatch_ = true;
      return;
    }
    hil::scenario_text_t m;
    m.run_id = run_id_;
    m.utime = 0;
    m.cycle = 0;
    m.digest = manifest.scenario_digest;
    m.yaml = yaml;
    m.nc_program = nc_program;
    write(channels::scenario, m, recv_utime);
  }

  template <typename Message>
  void write(const std::string& channel, const Message& m, int64_t utime) {
    std::vector<uint8_t> bytes(m.getEncodedSize());
    m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    write_raw(channel, bytes.data(), static_cast<uint32_t>(bytes.size()), utime);
  }

  void write_raw(const std::string& channel, const void* data, uint32_t size, int64_t utime) {
    lcm::LogEvent event;
    event.timestamp = utime;
    event.channel = channel;
    event.datalen = static_cast<int32_t>(size);
    event.data = const_cast<void*>(data);
    if (log_.writeEvent(&event) != 0) throw std::runtime_error("writing the log failed");
    ++recorded_;
  }

  lcm::LogFile log_;
  int64_t run_id_;
  std::optional<std::pair<std::string, std::string>> scenario_;
  logger::Attendance attendance_;
  bool told_participants_ = false;  // by hil run; else the manifest's
  int64_t recorded_ = 0, heard_ = 0;
  int64_t recorded_cycle_ = -1;
  int64_t socket_drops_ = -1;
  bool scenario_mismatch_ = false;
  traffic::Ledger refused_;
  std::deque<Held> held_;
};

std::string names(const std::vector<std::string>& list) {
  std::string out;
  for (const auto& name : list) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hil_logger: records every channel of a rig run into an LCM event log"};
  std::string url, path, scenario_file;
  int64_t run_id = 0;
  std::vector<std::string> participants;
  double linger_s = 3.0;
  app.add_option("--url", url, "LCM URL of the rig")->required();
  app.add_option("--out", path, "log file to write")->required();
  app.add_option("--run-id", run_id, "the run to record (default: the run of the first manifest heard)");
  app.add_option("--participants", participants,
                 "every node whose RUN_END closes the log (default: the manifest's participants and the cnc)");
  app.add_option("--scenario", scenario_file, "the resolved scenario file: written into the log after the manifest")
      ->check(CLI::ExistingFile);
  app.add_option("--linger-s", linger_s, "after the CNC's RUN_END, wait at most this long for the others");
  CLI11_PARSE(app, argc, argv);
  return hil::lcm_support::guarded_main("logger", [&] {
    lcm::LCM lcm(url);
    hil::lcm_support::require_good(lcm, url);
    std::optional<std::pair<std::string, std::string>> scenario;
    if (!scenario_file.empty())
      scenario.emplace(hil::read_text(scenario_file), hil::load_scenario_file(scenario_file).nc_program);
    LoggerNode node(lcm, path, run_id, participants, std::move(scenario));
    // With a run id the logger is a participant: READY, then a heartbeat.
    hil::lcm_support::Inbox inbox(lcm, run_id);
    std::optional<hil::lcm_support::Participant> participant;
    if (run_id > 0) {
      participant.emplace(lcm, inbox, "logger");
      if (!participant->wait_for_start(std::chrono::seconds(30))) {
        spdlog::error("the CNC did not start a run within 30 s");
        node.seal();
        return 2;
      }
    }
    auto last_message = clock_type::now(), next_alive = clock_type::now();
    int64_t announced_cycle = -1;
    int64_t heard = node.heard();  // neither another rig's traffic nor its own heartbeat is a sign of the run
    clock_type::time_point cnc_end{};
    const logger::Attendance& attendance = node.attendance();
    while (!attendance.complete()) {
      const auto now = clock_type::now();
      // On time, and as the recording progresses: the CNC's flow control.
      if (participant && (now >= next_alive || node.recorded_cycle() >= announced_cycle + 32)) {
        announced_cycle = node.recorded_cycle();
        participant->announce_alive(announced_cycle);
        next_alive = now + std::chrono::milliseconds(100);
      }
      if (lcm.handleTimeout(50) < 0) throw std::runtime_error("LCM receive failed");
      if (node.heard() != heard) {
        heard = node.heard();
        last_message = now;
      }
      if (attendance.cnc_ended() && cnc_end == clock_type::time_point{}) cnc_end = now;
      if (attendance.cnc_ended() && now - cnc_end > std::chrono::duration<double>(linger_s)) break;
      if (!attendance.cnc_ended() && now - last_message > std::chrono::seconds(10)) {
        spdlog::error("no message of the run for 10 s and no RUN_END from the CNC: log closed early");
        node.seal();
        return 2;
      }
    }
    node.seal();
    spdlog::info("{} messages recorded to {}; the kernel dropped {} datagram(s) at its socket", node.recorded(), path,
                 node.dropped());
    if (!node.refused().empty()) spdlog::warn("not recorded: {}", node.refused().describe());
    const std::vector<std::string> missing = attendance.missing();
    if (!missing.empty()) spdlog::error("no RUN_END within {} s of the CNC's from: {}", linger_s, names(missing));
    if (!attendance.lost().empty())
      spdlog::error("lost during the run (the CNC says): {}", names({attendance.lost().begin(), attendance.lost().end()}));
    return missing.empty() && attendance.lost().empty() && !node.scenario_mismatch() ? 0 : 3;
  });
}
