// The `cnc` node (RIG-1): the clock master. It wires LCM to the cycle loop
// (cnc/cycle): each cycle's setpoints and HLI state go out, and in
// lock-step it waits for every axis and the PLC to answer that cycle
// before the next (RIG-6). Which answers it takes is lock_step.hpp; what
// reaches it at all (this run's messages only) is lcm_support/inbox.hpp.
#include <hil/axis_state_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <set>

#include "channel.hpp"
#include "channels.hpp"
#include "cycle_loop.hpp"
#include "cycle_messages.hpp"
#include "inbox.hpp"
#include "lock_step.hpp"
#include "messages.hpp"
#include "node_options.hpp"
#include "participant.hpp"
#include "rerun.hpp"
#include "run_identity.hpp"
#include "scenario.hpp"

namespace {

using namespace hil;
using clock_type = std::chrono::steady_clock;

int64_t wall_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

struct Timeouts {
  std::chrono::milliseconds answer, logger;
};

// RIG-6 lock-step over LCM: the CNC is the clock master; each cycle's
// output is published, and the answers to it are every axis' and the PLC's
// message for that cycle, waited for (the watchdog loses a silent one).
class CncNode : public cnc::CyclePolicy {
 public:
  CncNode(const Scenario& scenario, const std::string& scenario_text, const std::string& url, int64_t run_id,
          std::vector<std::string> participants, Timeouts timeouts)
      : scenario_(scenario), machine_(scenario.machine), scenario_text_(scenario_text), lcm_(url),
        inbox_(lcm_, run_id), participants_(std::move(participants)), timeouts_(timeouts),
        lock_step_(machine_, std::count(participants_.begin(), participants_.end(), "logger") > 0,
                   timeouts.answer.count(), timeouts.logger.count()) {
    lcm_support::require_good(lcm_, url);
    for (size_t i = 0; i < machine_.axes.size(); ++i)
      inbox_.on<hil::axis_state_t>(channels::axis_state(machine_.axes[i].name),
                                   [this, i](const hil::axis_state_t& m, const lcm::ReceiveBuffer&) {
                                     return m.axis == machine_.axes[i].name &&
                                            lock_step_.take_axis(i, m.cycle, m.errors);
                                   });
    inbox_.on<hil::hli_control_t>(channels::hli_control, [this](const hil::hli_control_t& m, const lcm::ReceiveBuffer&) {
      return lock_step_.take_plc(m.cycle, lcm_support::from_message(m));
    });
    // Deep: a long first cycle (decoding a big program) queues heartbeats.
    inbox_.on<hil::participant_t>(
        channels::participant,
        [this](const hil::participant_t& m, const lcm::ReceiveBuffer& rbuf) {
          if (m.phase == hil::participant_t::PHASE_READY) ready_.insert(m.name);
          if (m.name == "logger" && m.phase != hil::participant_t::PHASE_RUN_END) lock_step_.logger_alive(rbuf.recv_utime, m.cycle);
          return true;
        },
        100000);
  }

  int run() {
    if (!wait_for_participants()) return 3;
    publish_manifest();
    cnc::Channel channel(scenario_.machine, scenario_.nc_program);
    const cnc::CycleLoopResult result = cnc::run_cycles(channel, scenario_, *this);
    const int64_t k = result.last_cycle;
    publish_run_end(k);
    spdlog::info("run ended after cycle {} ({:.3f} s simulated), channel {}", k, k * machine_.cycle_time_s(),
                 to_string(channel.hli().channel_state));
    if (!inbox_.ledger().empty()) spdlog::warn("refused: {}", inbox_.ledger().describe());
    return lock_step_.lost().empty() && result.outcome != cnc::RunOutcome::answers_missing ? 0 : 3;
  }

  bool publish(int64_t k, const cnc::Channel& channel, const std::vector<Event>& events) override {
    for (const Event& e : events) log_event(e);
    lock_step_.begin(k);  // before the output: an answer can only follow it
    for (const auto& m : cnc_node::cycle_messages(channel, machine_, events, k, inbox_.run_id()))
      lcm_.publish(m.channel, m.bytes.data(), static_cast<unsigned>(m.bytes.size()));
    return true;
  }

  bool publish_event(int64_t k, const Event& e) override {
    log_event(e);
    const auto m = cnc_node::event_message(e, machine_, k, inbox_.run_id());
    lcm_.publish(m.channel, m.bytes.data(), static_cast<unsigned>(m.bytes.size()));
    return true;
  }

  std::optional<cnc::CycleAnswers> answers(int64_t) override {
    wait_for_answers();
    wait_for_logger();
    cnc_node::LockStep::Taken taken = lock_step_.take();
    return cnc::CycleAnswers{taken.control, cnc_node::drive_errors(machine_, taken.axis_errors),
                             std::move(taken.lost)};
  }

 private:
  bool wait_for_participants() {
    const auto give_up = clock_type::now() + std::chrono::seconds(20);
    auto missing = [&] {
      std::string names;
      for (const auto& name : participants_)
        if (!ready_.count(name)) names += " '" + name + "'";
      return names;
    };
    while (!missing().empty()) {
      if (clock_type::now() > give_up) {
        spdlog::error("participants not ready after 20 s:{}", missing());
        return false;
      }
      lcm_.handleTimeout(50);
    }
    lock_step_.logger_alive(wall_us(), -1);
    return true;
  }

  void publish_manifest() {
    hil::run_manifest_t m;
    m.run_id = inbox_.run_id();
    m.utime = 0;
    m.cycle = 0;
    m.rig_version = HIL_VERSION;
    m.scenario_name = scenario_.name;
    m.cycle_us = machine_.cycle_time_us;
    m.answer_timeout_ms = static_cast<int32_t>(timeouts_.answer.count());
    m.scenario_bytes = static_cast<int64_t>(scenario_text_.size() + scenario_.nc_program.size());
    m.scenario_digest = scenario_digest(scenario_text_, scenario_.nc_program);
    m.participants = participants_;
    m.n_participants = static_cast<int16_t>(m.participants.size());
    lcm_.publish(channels::manifest, &m);
  }

  void publish_run_end(int64_t k) {
    hil::participant_t end;
    end.run_id = inbox_.run_id();
    end.utime = k * machine_.cycle_time_us;
    end.cycle = k;
    end.name = "cnc";
    end.phase = hil::participant_t::PHASE_RUN_END;
    end.verdicts = 0;
    end.rejected = lcm_support::to_message(inbox_.ledger());
    end.n_rejected = static_cast<int16_t>(end.rejected.size());
    for (const auto& [name, cycle] : lock_step_.lost()) {
      end.lost.push_back(name);
      end.lost_cycle.push_back(cycle);
    }
    end.n_lost = static_cast<int16_t>(end.lost.size());
    lcm_.publish(channels::participant, &end);
  }

  static void log_event(const Event& e) {
    spdlog::log(e.severity == Severity::error ? spdlog::level::err : spdlog::level::warn, "{}", describe(e));
  }

  // Until every participant not lost has answered; the watchdog loses the
  // silent ones.
  void wait_for_answers() {
    const auto give_up = clock_type::now() + timeouts_.answer;
    while (!lock_step_.complete()) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - clock_type::now());
      if (left.count() <= 0) return lock_step_.lose_silent();
      if (lcm_.handleTimeout(static_cast<int>(left.count()) + 1) < 0) throw std::runtime_error("LCM receive failed");
    }
  }

  // Until the logger is within LockStep::logger_window cycles, or lost.
  void wait_for_logger() {
    lock_step_.check_logger(wall_us());
    while (lock_step_.logger_behind()) {
      if (lcm_.handleTimeout(10) < 0) throw std::runtime_error("LCM receive failed");
      lock_step_.check_logger(wall_us());
    }
  }

  Scenario scenario_;
  MachineConfig machine_;
  std::string scenario_text_;
  lcm::LCM lcm_;
  lcm_support::Inbox inbox_;
  std::vector<std::string> participants_;
  Timeouts timeouts_;
  cnc_node::LockStep lock_step_;
  std::set<std::string> ready_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cnc: the CNC node of the HIL rig, clock master in lock-step"};
  hil::lcm_support::NodeOptions options;
  hil::lcm_support::add_node_options(app, options);
  std::vector<std::string> participants;
  app.add_option("--participants", participants,
                 "nodes to wait for before cycle 0 (default: every axis_sim, plc_sim, logger)");
  int answer_timeout_ms = 5000, logger_timeout_ms = 2000;
  app.add_option("--answer-timeout-ms", answer_timeout_ms, "lock-step watchdog per cycle")->check(CLI::PositiveNumber);
  app.add_option("--logger-timeout-ms", logger_timeout_ms, "the logger's heartbeat may fall silent this long")
      ->check(CLI::PositiveNumber);
  std::string rerun_log;
  app.add_option("--rerun", rerun_log,
                 "instead of a live run: feed the PLC inputs recorded in this log into this build in lock-step "
                 "and report the first difference (RIG-7)")
      ->check(CLI::ExistingFile);
  // A rerun needs neither a scenario file nor a rig: the log has both.
  for (const char* option : {"--scenario", "--url", "--run-id"})
    app.get_option(option)->required(false)->excludes("--rerun");
  CLI11_PARSE(app, argc, argv);
  if (rerun_log.empty() && (options.scenario_file.empty() || options.url.empty() || options.run_id <= 0)) {
    std::cerr << "cnc: --scenario, --url and --run-id are required (or --rerun LOG)\n";
    return 2;
  }
  if (!rerun_log.empty())
    return hil::lcm_support::guarded_main("cnc", [&] { return hil::cnc_node::rerun(rerun_log, std::cout); });
  return hil::lcm_support::guarded_main("cnc", [&] {
    const std::string text = hil::read_text(options.scenario_file);
    const hil::Scenario scenario = hil::load_scenario_file(options.scenario_file);
    if (participants.empty()) {
      for (const auto& axis : scenario.machine.axes) participants.push_back("axis_sim " + axis.name);
      participants.push_back("plc_sim");
      participants.push_back("logger");
    }
    CncNode node(scenario, text, options.url, options.run_id, participants,
                 {std::chrono::milliseconds(answer_timeout_ms), std::chrono::milliseconds(logger_timeout_ms)});
    return node.run();
  });
}
