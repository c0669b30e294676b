#include "run_log.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/rt_stats_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <hil/scenario_text_t.hpp>

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>

#include "channels.hpp"
#include "config_error.hpp"
#include "csv_export.hpp"
#include "event_log_reader.hpp"
#include "inbox.hpp"
#include "messages.hpp"
#include "run_identity.hpp"
#include "run_secret.hpp"
#include "untrusted_decode.hpp"

namespace hil::logger {
namespace {

// Where the run id ends in an encoded rig message: after the fingerprint.
constexpr size_t run_id_end = 16;

template <typename T>
bool decode(const LogRecord& e, T& msg) {
  return lcm_support::decode_untrusted(e.data.data(), e.data.size(), msg);
}

// A node's RUN_END adds to what it refused; the log's own count ("log") and
// the logger's seal ("logger") are no node's to replace.
void add_refused(traffic::Ledger& to, const traffic::Ledger& from) {
  for (const auto& [channel, counts] : from.by_channel()) to.add(channel, counts);
}

}  // namespace

RunLog read_run_log(const std::string& path, std::optional<CheckReport>* report) {
  EventLogReader file(path);
  RunLog log;
  LogFacts& f = log.facts;
  traffic::Ledger& in_log = f.refused["log"];
  std::unique_ptr<LimitChecker> checker;
  std::optional<int64_t> run;  // the run of the first manifest
  while (const LogRecord* e = file.next()) {
    const std::string& ch = e->channel;
    ++log.messages_per_channel[ch];
    if (f.sealed) ++f.records_after_seal;
    else if (ch != channels::log_end) ++f.records_before_seal;
    // Decodes; true if the message is this run's (counted if not).
    auto of_run = [&](auto& m) {
      if (!decode(*e, m)) {
        in_log.refuse(ch, traffic::Refusal::undecodable);
        return false;
      }
      if (!run) return false;  // before the manifest: the READY handshake
      if (m.run_id != *run) in_log.refuse(ch, traffic::Refusal::foreign_run);
      return m.run_id == *run;
    };
    auto lock_step = [&](int64_t cycle) {
      if (const auto c = f.lock_step.find(ch); c != f.lock_step.end()) c->second.push_back(cycle);
    };
    if (ch == channels::manifest) {
      hil::run_manifest_t m;
      if (run) {
        of_run(m);  // a second manifest tells nothing new
        continue;
      }
      if (!decode(*e, m)) {
        in_log.refuse(ch, traffic::Refusal::undecodable);
        continue;
      }
      run = m.run_id;
      f.run_id = m.run_id;
      f.manifest = true;
      log.rig_version = m.rig_version;
      for (const auto& name : m.participants)
        if (name != "logger") f.participants.push_back(name);
      f.participants.push_back("cnc");
    } else if (ch == channels::scenario) {
      hil::scenario_text_t m;
      if (!of_run(m) || log.scenario) continue;
      try {
        log.scenario = scenario_from_text(m.yaml, m.nc_program);
      } catch (const std::exception& ex) {
        f.unreadable.push_back(std::string("HIL_SCENARIO does not hold a valid scenario: ") + ex.what());
        continue;
      }
      f.scenario = true;
      f.realtime = log.scenario->realtime;
      const MachineConfig& machine = log.scenario->machine;
      checker = std::make_unique<LimitChecker>(machine);
      log.axes.assign(machine.axes.size(), {});
      for (const AxisConfig& axis : machine.axes) {
        f.lock_step[channels::axis_command(axis.name)];
        f.lock_step[channels::axis_state(axis.name)];
      }
      f.lock_step[channels::hli_state];
      f.lock_step[channels::hli_control];
      f.expectations = static_cast<int>(log.scenario->expectations.size() + log.scenario->expected_events.size());
      f.faults = log.scenario->faults;
    } else if (ch == channels::rt_stats) {
      hil::rt_stats_t m;
      if (!of_run(m)) continue;
      RealTimeFigures r;
      r.messages = (log.real_time ? log.real_time->messages : 0) + 1;
      r.cycle = m.cycle;
      r.final = m.is_final;
      r.cycle_us = m.cycle_us;
      r.scheduling = m.scheduling;
      r.ticks = m.ticks;
      r.overruns = m.overruns;
      r.jitter_p50_us = m.jitter_p50_us;
      r.jitter_p99_us = m.jitter_p99_us;
      r.jitter_max_us = m.jitter_max_us;
      for (size_t i = 0; i < static_cast<size_t>(std::max<int16_t>(m.n_participants, 0)); ++i)
        r.participants.push_back({m.name[i], m.in_time[i], m.late[i], m.missing[i], m.out_of_order[i],
                                  m.duplicate[i], m.longest_gap_cycles[i], m.watchdog_cycles[i]});
      f.rt_stats_final = f.rt_stats_final || m.is_final;
      log.real_time = r;
    } else if (ch == channels::log_end) {
      hil::log_summary_t m;
      if (!of_run(m)) continue;
      if (f.sealed) continue;  // a second seal: counted above, after the first
      f.sealed = true;
      f.logger_missing = m.missing;
      f.logger_socket_drops = m.socket_drops;
      f.refused["logger"] = lcm_support::from_message(m.rejected);
      f.seal_recorded = m.recorded;
      f.seal_cycle = m.cycle;
    } else if (ch == channels::event) {
      hil::event_t m;
      if (!of_run(m)) continue;
      LoggedEvent le;
      le.cycle = m.cycle;
      le.source = m.source;
      le.event = lcm_support::from_message(m);
      f.verdict_pass += le.event.verdict == Verdict::pass ? 1 : 0;
      f.verdict_fail += le.event.verdict == Verdict::fail ? 1 : 0;
      log.events.push_back(le);
    } else if (ch == channels::hli_state) {
      hil::hli_state_t m;
      if (!of_run(m)) continue;
      lock_step(m.cycle);
      // At most INT64_MAX - 1: reports print last_cycle + 1 cycles.
      log.last_cycle = std::max(log.last_cycle, std::min(m.cycle, std::numeric_limits<int64_t>::max() - 1));
      log.hli.cycle.push_back(m.cycle);
      log.hli.path_velocity.push_back(m.path_velocity);
      log.hli.dist_prog_start_mm.push_back(m.dist_prog_start / hli_units_per_mm);
      log.hli.block_nr_r.push_back(m.block_nr_r);
      log.hli.channel_state.push_back(m.channel_state);
      log.hli.block_search_state.push_back(m.block_search.state_r.state);
      log.hli.stop_conditions.push_back(m.stop_conditions_r);
      log.hli.override_percent.push_back(m.override.state_r * 0.1);
      // The lift's limits (LIFT-2, LIFT-3): the cycles each axis lifts, and
      // where the path velocity changes.
      if (checker) checker->add_path_velocity(m.cycle, m.path_velocity);
      for (size_t i = 0; checker && i < m.lift_active.size() && i < m.axis_name.size(); ++i)
        if (m.lift_active[i])
          if (const int axis = log.scenario->machine.axis_index(m.axis_name[i]); axis >= 0)
            checker->add_lift_active(axis, m.cycle);
    } else if (ch == channels::hli_control) {
      hil::hli_control_t m;
      if (of_run(m)) lock_step(m.cycle);
    } else if (ch == channels::participant) {
      hil::participant_t m;
      if (!of_run(m) || m.phase != hil::participant_t::PHASE_RUN_END) continue;
      f.ended.insert(m.name);
      if (!m.rejected.empty()) add_refused(f.refused[m.name], lcm_support::from_message(m.rejected));
      if (m.name == "plc_sim") f.verdicts_announced = m.verdicts;
      if (m.name != "cnc") continue;
      f.end_cycle = m.cycle;
      for (size_t i = 0; i < m.lost.size() && i < m.lost_cycle.size(); ++i) f.lost[m.lost[i]] = m.lost_cycle[i];
    } else if (!channels::axis_of_command(ch).empty()) {
      hil::axis_setpoint_t m;
      if (!of_run(m)) continue;
      lock_step(m.cycle);
      const int axis = checker ? log.scenario->machine.axis_index(channels::axis_of_command(ch)) : -1;
      if (axis < 0) continue;
      checker->add_setpoint(axis, m.cycle, m.position);
      AxisTrace& t = log.axes[axis];
      t.cmd_cycle.push_back(m.cycle);
      t.cmd_position.push_back(m.position);
      t.cmd_velocity.push_back(m.velocity);
      t.cmd_acceleration.push_back(m.acceleration);
    } else if (!channels::axis_of_state(ch).empty()) {
      hil::axis_state_t m;
      if (!of_run(m)) continue;
      lock_step(m.cycle);
      const int axis = checker ? log.scenario->machine.axis_index(channels::axis_of_state(ch)) : -1;
      if (axis < 0) continue;
      checker->add_actual(axis, m.cycle, m.position, m.velocity, m.acceleration, m.following_error);
      AxisTrace& t = log.axes[axis];
      t.act_cycle.push_back(m.cycle);
      t.act_position.push_back(m.position);
      t.act_velocity.push_back(m.velocity);
      t.act_acceleration.push_back(m.acceleration);
      t.following_error.push_back(m.following_error);
    } else if (ch != channels::lcm_self_test) {
      in_log.refuse(ch, traffic::Refusal::undecodable);  // no channel of the rig
    }
  }
  if (file.records() == 0 && file.file_size() > 0)
    throw std::runtime_error(path + " is not an LCM event log (no event found)");
  if (file.damage().any()) f.unreadable.push_back("the file is damaged: " + file.damage().describe());
  if (report && checker) *report = checker->finish();
  return log;
}

namespace {

// "channel AXIS_X_CMD, message 7 (cycle 7): position_m 0.0123 vs 0.0124" (issue 37):
// the first field of the message that differs, and both values.
std::string describe_difference(const std::string& channel, size_t index, const std::string& a, const std::string& b) {
  auto decoded = [&](const std::string& bytes) {
    LogRecord record;
    record.channel = channel;
    record.data.assign(bytes.begin(), bytes.end());
    return message_columns(record);
  };
  std::string out = "channel " + channel + " differs at message " + std::to_string(index);
  const std::optional<MessageColumns> ma = decoded(a), mb = decoded(b);
  if (!ma || !mb || ma->type != mb->type) return out + " (not both decodable as one type of the rig)";
  out += " (" + ma->type + ", cycle " + std::to_string(ma->cycle) +
         (ma->cycle != mb->cycle ? " vs " + std::to_string(mb->cycle) : "") + ")";
  for (size_t k = 0; k < std::max(ma->names.size(), mb->names.size()); ++k) {
    const std::string* name_a = k < ma->names.size() ? &ma->names[k] : nullptr;
    const std::string* name_b = k < mb->names.size() ? &mb->names[k] : nullptr;
    if (!name_a || !name_b || *name_a != *name_b)
      return out + ": field " + (name_a ? *name_a : *name_b) + " only in " + (name_a ? "the first" : "the second");
    if (ma->cells[k] != mb->cells[k]) return out + ": " + *name_a + " " + ma->cells[k] + " vs " + mb->cells[k];
  }
  return out + " (in bytes the columns do not show)";
}

}  // namespace

std::string compare_run_logs(const std::string& a, const std::string& b) {
  // A damaged file differs from any log (its damage may hide a record).
  std::string damaged;
  auto load = [&damaged](const std::string& path) {
    EventLogReader file(path);
    std::map<std::string, std::vector<std::string>> payloads;
    while (const LogRecord* e = file.next()) {
      // Participant announcements, the logger's seal and LCM's own self test
      // follow wall-clock timing, not the run.
      if (e->channel == channels::participant || e->channel == channels::log_end ||
          e->channel == channels::lcm_self_test)
        continue;
      std::string bytes(e->data.begin(), e->data.end());
      // Every rig message begins with its type's 8-byte fingerprint and the
      // run id and ends with the run's MAC (lcmtypes/): the fields two equal
      // runs differ in.
      if (bytes.size() >= run_id_end + lcm_support::RunSecret::mac_bytes) {
        std::fill(bytes.begin() + 8, bytes.begin() + run_id_end, '\0');
        std::fill(bytes.end() - lcm_support::RunSecret::mac_bytes, bytes.end(), '\0');
      }
      payloads[e->channel].push_back(std::move(bytes));
    }
    if (file.records() == 0 && file.file_size() > 0)
      throw std::runtime_error(path + " is not an LCM event log (no event found)");
    if (file.damage().any() && damaged.empty()) damaged = path + " is damaged: " + file.damage().describe();
    return payloads;
  };
  auto pa = load(a), pb = load(b);
  if (!damaged.empty()) return damaged;
  // Events of one cycle come from several nodes in wall-clock order: compare
  // them as a set (each carries its cycle and source).
  std::sort(pa[channels::event].begin(), pa[channels::event].end());
  std::sort(pb[channels::event].begin(), pb[channels::event].end());
  for (const auto& [channel, messages] : pa) {
    const auto other = pb.find(channel);
    if (other == pb.end()) return "channel " + channel + " only in " + a;
    const auto& om = other->second;
    for (size_t i = 0; i < std::min(messages.size(), om.size()); ++i)
      if (messages[i] != om[i]) return describe_difference(channel, i, messages[i], om[i]);
    if (messages.size() != om.size())
      return "channel " + channel + ": " + std::to_string(messages.size()) + " vs " +
             std::to_string(om.size()) + " messages";
  }
  for (const auto& entry : pb)
    if (!pa.count(entry.first)) return "channel " + entry.first + " only in " + b;
  return "";
}

}  // namespace hil::logger
