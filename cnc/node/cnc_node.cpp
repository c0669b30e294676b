#include "cnc_node.hpp"

#include <hil/axis_state_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <optional>
#include <thread>
#include <map>
#include <set>

#include "channel.hpp"
#include "channels.hpp"
#include "cycle_loop.hpp"
#include "cycle_messages.hpp"
#include "inbox.hpp"
#include "lift_limits.hpp"
#include "lock_step.hpp"
#include "messages.hpp"
#include "real_time_answers.hpp"
#include "rt_stats_message.hpp"
#include "run_identity.hpp"
#include "process_state.hpp"
#include "tick_clock.hpp"

namespace hil::cnc_node {
namespace {

using clock_type = std::chrono::steady_clock;

int64_t wall_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// RIG-6 over LCM: the CNC is the clock master; each cycle's output is
// published. In lock-step the answers to it are every axis' and the PLC's
// message for that cycle, waited for (the watchdog loses a silent one); in
// real time the CNC sleeps until the next tick is due and takes what has
// arrived by then (real_time_answers.hpp).
class CncNode : public cnc::CyclePolicy {
 public:
  CncNode(const Scenario& scenario, const std::string& scenario_text, lcm_support::Bus& bus, int64_t run_id,
          std::vector<std::string> participants, CncTiming timing, lcm_support::RealTimeProcess process)
      : scenario_(scenario), machine_(scenario.machine), scenario_text_(scenario_text), bus_(bus),
        inbox_(bus, run_id), participants_(std::move(participants)), timing_(timing),
        lock_step_(machine_, std::count(participants_.begin(), participants_.end(), "logger") > 0,
                   timing.answer.count(), timing.logger.count(), &scenario_.faults),
        realtime_(scenario.realtime), process_(std::move(process)),
        real_time_(machine_, std::count(participants_.begin(), participants_.end(), "logger") > 0,
                   timing.logger.count()),
        ticker_(clock_, static_cast<int64_t>(machine_.cycle_time_us) * 1000) {
    for (size_t i = 0; i < machine_.axes.size(); ++i)
      inbox_.on<hil::axis_state_t>(channels::axis_state(machine_.axes[i].name),
                                   [this, i](const hil::axis_state_t& m, const lcm::ReceiveBuffer&) {
                                     return m.axis == machine_.axes[i].name &&
                                            (realtime_ ? real_time_.take_axis(i, m.cycle, m.errors)
                                                       : lock_step_.take_axis(i, m.cycle, m.errors));
                                   });
    inbox_.on<hil::hli_control_t>(channels::hli_control, [this](const hil::hli_control_t& m, const lcm::ReceiveBuffer&) {
      return realtime_ ? real_time_.take_plc(m.cycle, lcm_support::from_message(m))
                       : lock_step_.take_plc(m.cycle, lcm_support::from_message(m));
    });
    // Deep: a long first cycle (decoding a big program) queues heartbeats.
    inbox_.on<hil::participant_t>(
        channels::participant,
        [this](const hil::participant_t& m, const lcm::ReceiveBuffer& rbuf) {
          if (m.phase == hil::participant_t::PHASE_READY) {
            ready_.insert(m.name);
            pids_[m.name] = m.pid;
          }
          if (m.name == "logger" && m.phase != hil::participant_t::PHASE_RUN_END) {
            lock_step_.logger_alive(rbuf.recv_utime, m.cycle);
            real_time_.logger_alive(rbuf.recv_utime);
          }
          return true;
        },
        100000);
  }

  int run() {
    if (!wait_for_participants()) return 3;
    publish_manifest();
    cnc::Channel channel(scenario_.machine, scenario_.nc_program);
    cnc::prepare_advanced_lifting_limits(scenario_.machine);  // not in a cycle
    if (realtime_) {
      lcm_support::publish_real_time(inbox_, process_, "cnc");
      real_time_.logger_alive(wall_us());
      ticker_.start();
    }
    const cnc::CycleLoopResult result = cnc::run_cycles(channel, scenario_, *this);
    const int64_t k = result.last_cycle;
    if (realtime_) publish_rt_stats(k, true);
    publish_run_end(k);
    spdlog::info("run ended after cycle {} ({:.3f} s simulated), channel {}", k, k * machine_.cycle_time_s(),
                 to_string(channel.hli().channel_state));
    if (realtime_)
      spdlog::info("real time: {} ticks, {} overrun(s), jitter p50 {} us, p99 {} us, max {} us",
                   ticker_.jitter().count(), ticker_.overruns(), ticker_.jitter().quantile_us(0.5),
                   ticker_.jitter().quantile_us(0.99), ticker_.jitter().max_us());
    if (!inbox_.ledger().empty()) spdlog::warn("refused: {}", inbox_.ledger().describe());
    // A participant lost to the scenario's own faults (RIG-8) is its design, not a failure.
    bool lost_unplanned = false;
    for (const auto& [name, cycle] : lost()) lost_unplanned = lost_unplanned || !scenario_.faults.touches(name);
    return !lost_unplanned && result.outcome != cnc::RunOutcome::answers_missing ? 0 : 3;
  }

  bool publish(int64_t k, const cnc::Channel& channel, const std::vector<Event>& events) override {
    for (const Event& e : events) log_event(e);
    // Before the output: an answer can only follow it.
    if (realtime_) real_time_.begin(k);
    else lock_step_.begin(k);
    if (!pace_start_ && timing_.pace > 0) pace_start_ = clock_type::now();
    for (const auto& m : cnc_node::cycle_messages(channel, machine_, events, k, inbox_.run_id()))
      bus_.publish(m.channel, m.bytes.data(), static_cast<uint32_t>(m.bytes.size()));
    if (realtime_) take_arrived();  // sends the cycle now, not at the next tick
    return true;
  }

  bool publish_event(int64_t k, const Event& e) override {
    log_event(e);
    const auto m = cnc_node::event_message(e, machine_, k, inbox_.run_id());
    bus_.publish(m.channel, m.bytes.data(), static_cast<uint32_t>(m.bytes.size()));
    return true;
  }

  std::optional<cnc::CycleAnswers> answers(int64_t k) override {
    if (realtime_) return real_time_answers(k);
    wait_for_answers();
    wait_for_logger();
    keep_pace(k);
    cnc_node::LockStep::Taken taken = lock_step_.take();
    return cnc::CycleAnswers{taken.control, cnc_node::drive_errors(machine_, taken.axis_errors),
                             std::move(taken.lost)};
  }

 private:
  const std::vector<std::pair<std::string, int64_t>>& lost() const {
    return realtime_ ? real_time_.lost() : lock_step_.lost();
  }

  // Real time: sleep until tick k+1 is due (an overrun runs at once), take
  // what has arrived, end cycle k. Never waits for an answer.
  cnc::CycleAnswers real_time_answers(int64_t k) {
    const Ticker::Tick tick = ticker_.wait(k + 1);
    take_arrived();
    RealTimeAnswers::Taken taken = real_time_.end_cycle(wall_us(), tick.overrun);
    if ((k + 1) % rt_stats_every_cycles == 0) publish_rt_stats(k, false);
    return cnc::CycleAnswers{taken.control, cnc_node::drive_errors(machine_, taken.axis_errors),
                             std::move(taken.lost)};
  }

  // Sends what is held and hands on every message that has arrived, without waiting.
  void take_arrived() {
    int handled = 0;
    while ((handled = bus_.handle_timeout(0)) > 0) {
    }
    if (handled < 0) throw std::runtime_error("LCM receive failed");
  }

  void publish_rt_stats(int64_t k, bool final) {
    const auto m = rt_stats_message(ticker_, real_time_, process_.what, k, machine_.cycle_time_us, inbox_.run_id(),
                                    final);
    bus_.publish(m.channel, m.bytes.data(), static_cast<uint32_t>(m.bytes.size()));
  }

  bool wait_for_participants() {
    announce_ready();  // those up before the CNC announce again at once
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
      bus_.handle_timeout(50);
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
    m.answer_timeout_ms = static_cast<int32_t>(timing_.answer.count());
    m.scenario_bytes = static_cast<int64_t>(scenario_text_.size() + scenario_.nc_program.size());
    m.scenario_digest = scenario_digest(scenario_text_, scenario_.nc_program);
    m.participants = participants_;
    m.n_participants = static_cast<int16_t>(m.participants.size());
    bus_.publish(channels::manifest, m);
  }

  // The CNC's own HIL_PARTICIPANT announcement at cycle `k`.
  hil::participant_t announcement(int8_t phase, int64_t k) const {
    hil::participant_t m;
    m.run_id = inbox_.run_id();
    m.utime = k * machine_.cycle_time_us;
    m.cycle = k;
    m.name = "cnc";
    m.phase = phase;
    m.verdicts = 0;
    m.n_rejected = 0;
    m.n_lost = 0;
    m.pid = static_cast<int32_t>(::getpid());
    return m;
  }

  // While it waits on a slow participant (longer than the others' patience,
  // lcm_support::cnc_silence), the CNC says it is still there.
  static constexpr std::chrono::seconds alive_every{1};
  void announce_alive() { bus_.publish(channels::participant, announcement(hil::participant_t::PHASE_ALIVE, lock_step_.cycle())); }

  void announce_ready() { bus_.publish(channels::participant, announcement(hil::participant_t::PHASE_READY, 0)); }

  void publish_run_end(int64_t k) {
    hil::participant_t end = announcement(hil::participant_t::PHASE_RUN_END, k);
    end.rejected = lcm_support::to_message(inbox_.ledger());
    end.n_rejected = static_cast<int16_t>(end.rejected.size());
    for (const auto& [name, cycle] : lost()) {
      end.lost.push_back(name);
      end.lost_cycle.push_back(cycle);
    }
    end.n_lost = static_cast<int16_t>(end.lost.size());
    bus_.publish(channels::participant, end);
  }

  static void log_event(const Event& e) {
    spdlog::log(e.severity == Severity::error ? spdlog::level::err : spdlog::level::warn, "{}", describe(e));
  }

  // A silent participant's process, said in the cnc's output when it is not running.
  ProcessState process_of(const std::string& name) const {
    const auto pid = pids_.find(name);
    const ProcessState state = process_state(pid == pids_.end() ? 0 : pid->second);
    if (state != ProcessState::running)
      spdlog::warn("cycle {}: {} is silent, its process {}", lock_step_.cycle(), name, to_string(state));
    return state;
  }

  // Until every participant not lost has answered. At the watchdog the
  // silent ones are lost, but for those whose process is alive and running
  // (a loaded host): they are waited for on, and said so each timeout.
  void wait_for_answers() {
    const auto since = clock_type::now();
    auto give_up = since + timing_.answer;
    auto next_alive = since + alive_every, next_report = since;
    while (!lock_step_.complete()) {
      if (clock_type::now() >= next_alive) {
        announce_alive();
        next_alive = clock_type::now() + alive_every;
      }
      const auto left = std::min(std::chrono::duration_cast<std::chrono::milliseconds>(give_up - clock_type::now()),
                                 std::chrono::duration_cast<std::chrono::milliseconds>(alive_every));
      if (left.count() <= 0) {
        const std::vector<std::string> waited_for =
            lock_step_.lose_silent([this](const std::string& name) { return process_of(name); });
        if (waited_for.empty()) return;
        if (clock_type::now() >= next_report) {  // at once, then once a second
          std::string names;
          for (const auto& name : waited_for) names += (names.empty() ? "" : ", ") + name;
          spdlog::warn("cycle {}: no answer from {} for {:.3f} s, its process alive and running: waiting on (a "
                       "loaded host?)",
                       lock_step_.cycle(), names, std::chrono::duration<double>(clock_type::now() - since).count());
          next_report = clock_type::now() + alive_every;
        }
        give_up = clock_type::now() + timing_.answer;
        continue;
      }
      if (bus_.handle_timeout(static_cast<int>(std::max<int64_t>(left.count(), 0)) + 1) < 0)
        throw std::runtime_error("LCM receive failed");
    }
  }

  // Paced (CncTiming::pace): until cycle k may end, taking what arrives
  // and saying the CNC is alive meanwhile.
  void keep_pace(int64_t k) {
    if (!pace_start_) return;
    const auto due = *pace_start_ + std::chrono::duration_cast<clock_type::duration>(std::chrono::duration<double>(
                                        static_cast<double>(k + 1) * machine_.cycle_time_s() / timing_.pace));
    auto next_alive = clock_type::now() + alive_every;
    while (clock_type::now() < due) {
      if (bus_.handle_timeout(0) < 0) throw std::runtime_error("LCM receive failed");
      std::this_thread::sleep_until(std::min({due, next_alive, clock_type::now() + std::chrono::milliseconds(10)}));
      if (clock_type::now() >= next_alive) {
        announce_alive();
        next_alive = clock_type::now() + alive_every;
      }
    }
  }

  // Until the logger is within LockStep::logger_window cycles, or lost; a
  // logger whose process is alive and running is waited for.
  void wait_for_logger() {
    auto next_report = clock_type::now() + timing_.logger;
    const auto liveness = [this](const std::string& name) { return process_of(name); };
    while (lock_step_.check_logger(wall_us(), liveness) || lock_step_.logger_behind()) {
      if (clock_type::now() > next_report) {
        spdlog::warn("cycle {}: the logger is behind or silent, its process alive and running: waiting on (a loaded "
                     "host?)",
                     lock_step_.cycle());
        announce_alive();
        next_report = clock_type::now() + std::min<clock_type::duration>(timing_.logger, alive_every);
      }
      if (bus_.handle_timeout(10) < 0) throw std::runtime_error("LCM receive failed");
    }
  }

  Scenario scenario_;
  MachineConfig machine_;
  std::string scenario_text_;
  lcm_support::Bus& bus_;
  lcm_support::Inbox inbox_;
  std::vector<std::string> participants_;
  CncTiming timing_;
  std::optional<clock_type::time_point> pace_start_;  // cycle 0's start, if paced
  cnc_node::LockStep lock_step_;
  bool realtime_;
  lcm_support::RealTimeProcess process_;
  RealTimeAnswers real_time_;
  MonotonicClock clock_;
  Ticker ticker_;
  std::set<std::string> ready_;
  std::map<std::string, int32_t> pids_;  // by participant, from its READY
};

}  // namespace

int run_cnc(const Scenario& scenario, const std::string& scenario_text, lcm_support::Bus& bus, int64_t run_id,
            std::vector<std::string> participants, CncTiming timing, const lcm_support::RealTimeProcess& process) {
  CncNode node(scenario, scenario_text, bus, run_id, std::move(participants), timing, process);
  return node.run();
}

}  // namespace hil::cnc_node
