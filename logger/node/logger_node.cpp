#include "logger_node.hpp"

#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/scenario_text_t.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>

#include "channels.hpp"
#include "run_identity.hpp"

namespace hil::logger {
namespace {

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

std::string names(const std::vector<std::string>& list) {
  std::string out;
  for (const auto& name : list) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

LoggerNode::LoggerNode(lcm_support::Bus& bus, const std::string& path, int64_t run_id,
                       std::vector<std::string> participants,
                       std::optional<std::pair<std::string, std::string>> scenario, bool decode_check)
    : bus_(bus), log_(path), decode_check_(decode_check), run_id_(run_id), scenario_(std::move(scenario)) {
  for (const std::string& name : participants) attendance_.expect(name);
  told_participants_ = !participants.empty();
  if (scenario_) faults_ = scenario_from_text(scenario_->first, scenario_->second).faults;
  // The first subscription: it must exist before any other (the inbox's
  // come after it), else it is handed messages it never counted.
  bus.subscribe(
      channels::every_channel_but_self_test,
      [this](const lcm::ReceiveBuffer& rbuf, const std::string& channel) { receive(rbuf, channel); }, 1000000);
}

void LoggerNode::seal() {
  hil::log_summary_t m;
  m.run_id = run_id_;
  // Stamped when sealed, never before the last record: a log player and
  // the CSV's log_t_s see the seal at the end (issue 37; it was 0).
  const int64_t now_us =
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  m.utime = std::max(now_us, last_utime_);
  m.cycle = attendance_.end_cycle();
  m.recorded = recorded_;
  m.missing = attendance_.missing();
  for (const auto& name : attendance_.lost()) m.missing.push_back(name);
  m.n_missing = static_cast<int16_t>(m.missing.size());
  m.rejected = lcm_support::to_message(refused());
  m.n_rejected = static_cast<int16_t>(m.rejected.size());
  m.socket_drops = socket_drops_ = socket_drops();
  write(channels::log_end, m, m.utime);
  log_.flush();
}

void LoggerNode::receive(const lcm::ReceiveBuffer& rbuf, const std::string& channel) {
  if (!lcm_support::framed(rbuf)) return refused_.refuse(traffic::malformed_datagram, traffic::Refusal::undecodable);
  if (channel == channels::log_end) return;  // another logger's seal (a replay): this one writes its own
  const auto id = decode_check_ ? lcm_support::identify(channel, rbuf.data, rbuf.data_size)
                                : lcm_support::identify_header(channel, rbuf.data, rbuf.data_size);
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

void LoggerNode::adopt_run(int64_t run_id) {
  run_id_ = run_id;
  std::deque<Held> held;
  held.swap(held_);
  for (const Held& h : held)
    if (const auto id = lcm_support::identify(h.channel, h.data.data(), static_cast<uint32_t>(h.data.size())))
      take(h.channel, *id, h.data.data(), static_cast<uint32_t>(h.data.size()), h.recv_utime);
}

void LoggerNode::take(const std::string& channel, const lcm_support::Identity& id, const void* data, uint32_t size,
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
  if (channel == channels::hli_state && id.cycle > recorded_cycle_) {
    recorded_cycle_ = id.cycle;
    if (progress_) progress_(recorded_cycle_);
  }
  if (channel == channels::manifest) {
    hil::run_manifest_t m;
    if (!lcm_support::decode(data, size, m)) return;
    if (!told_participants_)
      for (const auto& name : m.participants) attendance_.expect(name);
    write_scenario(m, recv_utime);
  }
}

void LoggerNode::write_scenario(const hil::run_manifest_t& manifest, int64_t recv_utime) {
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
void LoggerNode::write(const std::string& channel, const Message& m, int64_t utime) {
  const std::vector<uint8_t> bytes = lcm_support::encode(m);
  write_raw(channel, bytes.data(), static_cast<uint32_t>(bytes.size()), utime);
}

void LoggerNode::write_raw(const std::string& channel, const void* data, uint32_t size, int64_t utime) {
  log_.write(channel, data, size, utime);
  last_utime_ = std::max(last_utime_, utime);
  ++recorded_;
}

int LoggerNode::finish(const std::string& path, double linger_s) const {
  spdlog::info("{} messages recorded to {}; the kernel dropped {} datagram(s) at its socket", recorded_, path,
               socket_drops_);
  if (!refused_.empty()) spdlog::warn("not recorded: {}", refused_.describe());
  const std::vector<std::string> missing = attendance_.missing();
  if (!missing.empty()) spdlog::error("no RUN_END within {} s of the CNC's from: {}", linger_s, names(missing));
  std::vector<std::string> lost;  // but those the scenario's faults act on (RIG-8)
  for (const auto& name : attendance_.lost())
    if (!faults_.touches(name)) lost.push_back(name);
  if (!attendance_.lost().empty())
    spdlog::log(lost.empty() ? spdlog::level::info : spdlog::level::err, "lost during the run (the CNC says): {}{}",
                names({attendance_.lost().begin(), attendance_.lost().end()}), lost.empty() ? " (faults planned)" : "");
  return missing.empty() && lost.empty() && !scenario_mismatch_ ? 0 : 3;
}

}  // namespace hil::logger
