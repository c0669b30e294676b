// The `cnc` node (RIG-1): the clock master. It wires LCM to the cycle loop
// (cnc/cycle): each cycle's setpoints and HLI state go out, and in
// lock-step it waits for every axis and the PLC to answer that cycle
// before the next (RIG-6).
#include <hil/axis_state_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <set>

#include "channel.hpp"
#include "cycle_loop.hpp"
#include "channels.hpp"
#include "cycle_messages.hpp"
#include "messages.hpp"
#include "node_options.hpp"
#include "participant.hpp"
#include "rerun.hpp"
#include "scenario.hpp"

namespace {

using namespace hil;
using clock_type = std::chrono::steady_clock;

// What the participants answered so far.
struct Answers {
  std::vector<int64_t> axis_cycle;
  std::vector<int32_t> axis_errors;  // MONITOR_* bits of the latest answer
  int64_t plc_cycle = -1;
  HliControl control;
  std::set<std::string> ready;
};

// RIG-6 lock-step over LCM: the CNC is the clock master; each cycle's
// output is published, and the answers to it are every axis' and the PLC's
// message for that cycle, waited for (the watchdog ends the run).
class CncNode : public cnc::CyclePolicy {
 public:
  CncNode(const Scenario& scenario, const std::string& url, std::vector<std::string> participants,
          std::chrono::milliseconds answer_timeout)
      : scenario_(scenario), machine_(scenario.machine), lcm_(url), participants_(std::move(participants)),
        answer_timeout_(answer_timeout) {
    lcm_support::require_good(lcm_, url);
    answers_.axis_cycle.assign(machine_.axes.size(), -1);
    answers_.axis_errors.assign(machine_.axes.size(), 0);
    for (size_t i = 0; i < machine_.axes.size(); ++i) {
      auto* sub = lcm_.subscribeFunction(
          channels::axis_state(machine_.axes[i].name),
          +[](const lcm::ReceiveBuffer*, const std::string& channel, const hil::axis_state_t* m, CncNode* self) {
            self->on_axis_state(channel, *m);
          },
          this);
      sub->setQueueCapacity(10000);
    }
    lcm_.subscribeFunction(
           channels::hli_control,
           +[](const lcm::ReceiveBuffer*, const std::string&, const hil::hli_control_t* m, CncNode* self) {
             if (m->cycle > self->answers_.plc_cycle) {
               self->answers_.plc_cycle = m->cycle;
               self->answers_.control = lcm_support::from_message(*m);
             }
           },
           this)
        ->setQueueCapacity(10000);
    lcm_.subscribeFunction(
        channels::participant,
        +[](const lcm::ReceiveBuffer*, const std::string&, const hil::participant_t* m, CncNode* self) {
          if (m->phase == hil::participant_t::PHASE_READY) self->answers_.ready.insert(m->name);
        },
        this);
  }

  int run() {
    if (!wait_for_participants()) return 3;
    publish_manifest();
    cnc::Channel channel(scenario_.machine, scenario_.nc_program);
    const cnc::CycleLoopResult result = cnc::run_cycles(channel, scenario_, *this);
    const int64_t k = result.last_cycle;
    hil::participant_t end;
    end.utime = k * machine_.cycle_time_us;
    end.cycle = k;
    end.name = "cnc";
    end.phase = hil::participant_t::PHASE_RUN_END;
    lcm_.publish(channels::participant, &end);
    spdlog::info("run ended after cycle {} ({:.3f} s simulated), channel {}", k, k * machine_.cycle_time_s(),
                 to_string(channel.hli().channel_state));
    return result.outcome == cnc::RunOutcome::answers_missing ? 3 : 0;
  }

  bool publish(int64_t k, const cnc::Channel& channel, const std::vector<Event>& events) override {
    for (const Event& e : events) log_event(e);
    for (const auto& m : cnc_node::cycle_messages(channel, machine_, events, k))
      lcm_.publish(m.channel, m.bytes.data(), static_cast<unsigned>(m.bytes.size()));
    return true;
  }

  bool publish_event(int64_t k, const Event& e) override {
    log_event(e);
    const auto m = cnc_node::event_message(e, machine_, k);
    lcm_.publish(m.channel, m.bytes.data(), static_cast<unsigned>(m.bytes.size()));
    return true;
  }

  std::optional<cnc::CycleAnswers> answers(int64_t k) override {
    if (!wait_for_answers(k)) return std::nullopt;
    return cnc::CycleAnswers{answers_.control, cnc_node::drive_errors(machine_, answers_.axis_errors)};
  }

 private:
  bool wait_for_participants() {
    const auto give_up = clock_type::now() + std::chrono::seconds(20);
    auto all_ready = [&] {
      for (const auto& name : participants_)
        if (!answers_.ready.count(name)) return false;
      return true;
    };
    while (!all_ready()) {
      if (clock_type::now() > give_up) {
        std::string missing;
        for (const auto& name : participants_)
          if (!answers_.ready.count(name)) missing += " '" + name + "'";
        spdlog::error("participants not ready after 20 s:{}", missing);
        return false;
      }
      lcm_.handleTimeout(50);
    }
    return true;
  }

  void publish_manifest() {
    hil::run_manifest_t m;
    m.utime = 0;
    m.cycle = 0;
    m.rig_version = HIL_VERSION;
    m.scenario_name = scenario_.name;
    m.cycle_us = machine_.cycle_time_us;
    m.scenario_yaml = to_yaml(scenario_);
    m.nc_program = scenario_.nc_program;
    lcm_.publish(channels::manifest, &m);
  }

  static void log_event(const Event& e) {
    spdlog::log(e.severity == Severity::error ? spdlog::level::err : spdlog::level::warn, "{}", describe(e));
  }

  bool wait_for_answers(int64_t k) {
    const auto give_up = clock_type::now() + answer_timeout_;
    for (;;) {
      bool complete = answers_.plc_cycle >= k;
      for (int64_t c : answers_.axis_cycle) complete = complete && c >= k;
      if (complete) return true;
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - clock_type::now());
      if (left.count() <= 0 || lcm_.handleTimeout(static_cast<int>(left.count()) + 1) < 0) break;
    }
    std::string silent = answers_.plc_cycle < k ? " plc_sim" : "";
    for (size_t i = 0; i < answers_.axis_cycle.size(); ++i)
      if (answers_.axis_cycle[i] < k) silent += " axis_sim " + machine_.axes[i].name;
    Event e;
    e.message = "lock-step broken: no answer to cycle " + std::to_string(k) + " within " +
                std::to_string(answer_timeout_.count()) + " ms from" + silent;
    publish_event(k, e);
    return false;
  }

  void on_axis_state(const std::string& channel, const hil::axis_state_t& m) {
    const int axis = machine_.axis_index(m.axis);
    if (axis < 0 || channels::axis_state(m.axis) != channel) return;
    if (m.cycle <= answers_.axis_cycle[axis]) return;
    answers_.axis_cycle[axis] = m.cycle;
    answers_.axis_errors[axis] = m.errors;
  }

  Scenario scenario_;
  MachineConfig machine_;
  lcm::LCM lcm_;
  std::vector<std::string> participants_;
  std::chrono::milliseconds answer_timeout_;
  Answers answers_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cnc: the CNC node of the HIL rig, clock master in lock-step"};
  hil::lcm_support::NodeOptions options;
  hil::lcm_support::add_node_options(app, options);
  std::vector<std::string> participants;
  app.add_option("--participants", participants,
                 "nodes to wait for before cycle 0 (default: every axis_sim, plc_sim, logger)");
  int answer_timeout_ms = 5000;
  app.add_option("--answer-timeout-ms", answer_timeout_ms, "lock-step watchdog per cycle")->check(CLI::PositiveNumber);
  std::string rerun_log;
  app.add_option("--rerun", rerun_log,
                 "instead of a live run: feed the PLC inputs recorded in this log into this build in lock-step "
                 "and report the first difference (RIG-7)")
      ->check(CLI::ExistingFile);
  // A rerun needs neither a scenario file nor a rig: the log has both.
  app.get_option("--scenario")->required(false)->excludes("--rerun");
  app.get_option("--url")->required(false)->excludes("--rerun");
  CLI11_PARSE(app, argc, argv);
  if (rerun_log.empty() && (options.scenario_file.empty() || options.url.empty())) {
    std::cerr << "cnc: --scenario and --url are required (or --rerun LOG)\n";
    return 2;
  }
  if (!rerun_log.empty())
    return hil::lcm_support::guarded_main("cnc", [&] { return hil::cnc_node::rerun(rerun_log, std::cout); });
  return hil::lcm_support::guarded_main("cnc", [&] {
    const hil::Scenario scenario = hil::load_scenario_file(options.scenario_file);
    if (participants.empty()) {
      for (const auto& axis : scenario.machine.axes) participants.push_back("axis_sim " + axis.name);
      participants.push_back("plc_sim");
      participants.push_back("logger");
    }
    CncNode node(scenario, options.url, participants, std::chrono::milliseconds(answer_timeout_ms));
    return node.run();
  });
}
