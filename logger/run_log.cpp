#include "run_log.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "channels.hpp"
#include "config_error.hpp"
#include "messages.hpp"

namespace hil::logger {
namespace {

template <typename T>
bool decode(const lcm::LogEvent& e, T& msg) {
  return msg.decode(e.data, 0, e.datalen) == e.datalen;
}

}  // namespace

RunLog read_run_log(const std::string& path, std::optional<CheckReport>* report) {
  lcm::LogFile file(path, "r");
  if (!file.good()) throw std::runtime_error("cannot open LCM log " + path);
  RunLog log;
  std::unique_ptr<LimitChecker> checker;
  while (const lcm::LogEvent* e = file.readNextEvent()) {
    ++log.messages_per_channel[e->channel];
    if (e->channel == channels::manifest) {
      hil::run_manifest_t m;
      if (!decode(*e, m)) { ++log.undecodable; continue; }
      log.rig_version = m.rig_version;
      try {
        log.scenario = parse_scenario(YAML::Load(m.scenario_yaml));
        checker = std::make_unique<LimitChecker>(log.scenario->machine);
        log.axes.assign(log.scenario->machine.axes.size(), {});
      } catch (const std::exception& ex) {
        throw std::runtime_error(path + ": manifest does not hold a valid scenario: " + ex.what());
      }
    } else if (e->channel == channels::event) {
      hil::event_t m;
      if (!decode(*e, m)) { ++log.undecodable; continue; }
      LoggedEvent le;
      le.cycle = m.cycle;
      le.source = m.source;
      le.event = lcm_support::from_message(m);
      log.events.push_back(le);
    } else if (e->channel == channels::hli_state) {
      hil::hli_state_t m;
      if (!decode(*e, m)) { ++log.undecodable; continue; }
      log.last_cycle = std::max(log.last_cycle, m.cycle);
      log.hli.cycle.push_back(m.cycle);
      log.hli.path_velocity.push_back(m.path_velocity);
      log.hli.dist_prog_start_mm.push_back(m.dist_prog_start / hli_units_per_mm);
      log.hli.block_nr_r.push_back(m.block_nr_r);
      log.hli.channel_state.push_back(m.channel_state);
    } else if (e->channel == channels::participant) {
      hil::participant_t m;
      if (!decode(*e, m)) { ++log.undecodable; continue; }
      if (m.name == "cnc" && m.phase == hil::participant_t::PHASE_RUN_END) log.run_end_seen = true;
    } else if (checker && !channels::axis_of_command(e->channel).empty()) {
      const int axis = log.scenario->machine.axis_index(channels::axis_of_command(e->channel));
      if (axis < 0) continue;
      hil::axis_setpoint_t m;
      if (!decode(*e, m)) { ++log.undecodable; continue; }
      checker->add_setpoint(axis, m.cycle, m.position);
      AxisTrace& t = log.axes[axis];
      t.cmd_cycle.push_back(m.cycle);
      t.cmd_position.push_back(m.position);
      t.cmd_velocity.push_back(m.velocity);
      t.cmd_acceleration.push_back(m.acceleration);
    } else if (checker && !channels::axis_of_state(e->channel).empty()) {
      const int axis = log.scenario->machine.axis_index(channels::axis_of_state(e->channel));
      if (axis < 0) continue;
      hil::axis_state_t m;
      if (!decode(*e, m)) { ++log.undecodable; continue; }
      checker->add_actual(axis, m.cycle, m.position, m.velocity, m.acceleration, m.following_error);
      AxisTrace& t = log.axes[axis];
      t.act_cycle.push_back(m.cycle);
      t.act_position.push_back(m.position);
      t.act_velocity.push_back(m.velocity);
      t.act_acceleration.push_back(m.acceleration);
      t.following_error.push_back(m.following_error);
    }
  }
  if (log.messages_per_channel.empty() && std::filesystem::file_size(path) > 0)
    throw std::runtime_error(path + " is not an LCM event log (no event found)");
  if (report && checker) *report = checker->finish();
  return log;
}

std::string compare_run_logs(const std::string& a, const std::string& b) {
  auto load = [](const std::string& path) {
    lcm::LogFile file(path, "r");
    if (!file.good()) throw std::runtime_error("cannot open LCM log " + path);
    std::map<std::string, std::vector<std::string>> payloads;
    while (const lcm::LogEvent* e = file.readNextEvent())
      // Participant announcements and LCM's own self test follow wall-clock
      // timing, not the run.
      if (e->channel != channels::participant && e->channel != "LCM_SELF_TEST")
        payloads[e->channel].emplace_back(static_cast<const char*>(e->data), e->datalen);
    return payloads;
  };
  auto pa = load(a), pb = load(b);
  // Events of one cycle come from several nodes in wall-clock order: compare
  // them as a set (each carries its cycle and source).
  std::sort(pa[channels::event].begin(), pa[channels::event].end());
  std::sort(pb[channels::event].begin(), pb[channels::event].end());
  for (const auto& [channel, messages] : pa) {
    const auto other = pb.find(channel);
    if (other == pb.end()) return "channel " + channel + " only in " + a;
    const auto& om = other->second;
    for (size_t i = 0; i < std::min(messages.size(), om.size()); ++i)
      if (messages[i] != om[i]) return "channel " + channel + " differs at message " + std::to_string(i);
    if (messages.size() != om.size())
      return "channel " + channel + ": " + std::to_string(messages.size()) + " vs " +
             std::to_string(om.size()) + " messages";
  }
  for (const auto& entry : pb)
    if (!pa.count(entry.first)) return "channel " + entry.first + " only in " + b;
  return "";
}

}  // namespace hil::logger
