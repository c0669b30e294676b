// RIG-6 real-time mode, free of LCM and of the wall clock: the CNC's tick on
// an absolute clock (a fake one here), its jitter and overruns, which
// answers it takes when it never waits, and the watchdog that stops the
// channel on the path when a participant falls silent.
#include <catch2/catch.hpp>

#include <deque>
#include <string>

#include "channel_runner.hpp"
#include "cycle_loop.hpp"
#include "limit_check.hpp"
#include "real_time_answers.hpp"
#include "scenario.hpp"
#include "test_machine.hpp"
#include "tick_clock.hpp"

using namespace hil;
using cnc_node::RealTimeAnswers;
using cnc_node::Ticker;

namespace {

// Time passes only when told; sleeping moves it to the due time plus the
// next wake-up latency queued (0 if none).
class FakeClock : public cnc_node::TickClock {
 public:
  int64_t now_ns() override { return now_; }
  void sleep_until_ns(int64_t due_ns) override {
    REQUIRE(due_ns > now_);  // never asked to sleep into the past
    now_ = due_ns;
    if (!latencies.empty()) {
      now_ += latencies.front();
      latencies.pop_front();
    }
  }
  void advance(int64_t ns) { now_ += ns; }
  std::deque<int64_t> latencies;

 private:
  int64_t now_ = 5'000'000'000;
};

constexpr int64_t ms = 1'000'000, us = 1'000;

}  // namespace

TEST_CASE("RIG-6 real time: ticks are due at start + k * period, slept to absolutely, the lateness is the jitter",
          "[RIG-6][real_time]") {
  FakeClock clock;
  Ticker ticker(clock, 1 * ms);
  ticker.start();
  const int64_t t0 = clock.now_ns();
  clock.latencies = {10 * us, 20 * us, 30 * us};
  for (int64_t k = 1; k <= 3; ++k) {
    clock.advance(300 * us);  // the cycle's work
    const Ticker::Tick t = ticker.wait(k);
    CHECK(t.late_ns == k * 10 * us);
    CHECK_FALSE(t.overrun);
    CHECK(clock.now_ns() == t0 + k * ms + k * 10 * us);  // no drift from the work or the lateness
  }
  CHECK(ticker.jitter().count() == 3);
  CHECK(ticker.jitter().quantile_us(0.5) == 21);  // the upper edge of its 1 us bin
  CHECK(ticker.jitter().max_us() == 30);
  CHECK(ticker.overruns() == 0);
}

TEST_CASE("RIG-6 real time: a tick woken for after the next was due is an overrun, run at once, none skipped",
          "[RIG-6][real_time]") {
  FakeClock clock;
  Ticker ticker(clock, 1 * ms);
  ticker.start();
  const int64_t t0 = clock.now_ns();
  clock.advance(2500 * us);  // cycle 0 took 2.5 periods
  Ticker::Tick t = ticker.wait(1);
  CHECK(t.overrun);
  CHECK(t.late_ns == 1500 * us);
  CHECK(clock.now_ns() == t0 + 2500 * us);  // no sleep
  t = ticker.wait(2);  // due 0.5 ms ago, still less than a period: late, no overrun
  CHECK_FALSE(t.overrun);
  CHECK(t.late_ns == 500 * us);
  t = ticker.wait(3);  // back on the grid
  CHECK(clock.now_ns() == t0 + 3 * ms);
  CHECK(t.late_ns == 0);
  CHECK(ticker.overruns() == 1);
  CHECK(ticker.jitter().count() == 3);
  CHECK(ticker.jitter().max_us() == 1500);
}

TEST_CASE("RIG-6 real time: jitter percentiles to the microsecond, a maximum beyond the histogram exact",
          "[RIG-6][real_time]") {
  cnc_node::JitterStats j;
  CHECK(j.quantile_us(0.99) == 0);
  for (int i = 0; i < 98; ++i) j.add(5 * us + 300);  // 5.3 us: bin 5, upper edge 6
  j.add(80 * us);
  j.add(50 * ms);  // beyond the 20 ms histogram
  CHECK(j.quantile_us(0.5) == 6);
  CHECK(j.quantile_us(0.99) == 81);
  CHECK(j.quantile_us(1.0) == 50000);
  CHECK(j.max_us() == 50000);
  j.add(-3);  // a clock that read before the due time counts as on time
  CHECK(j.count() == 101);
}

TEST_CASE("RIG-6 real time: answers in time, late (used in the next cycle), missing; the PLC's last control stays",
          "[RIG-6][real_time]") {
  const MachineConfig machine = test::xyz_machine();
  RealTimeAnswers a(machine, false, 2000);
  HliControl c5;
  c5.cycle = 5;
  a.begin(5);
  CHECK(a.take_axis(0, 5, 0));
  CHECK(a.take_axis(1, 5, 0));
  CHECK(a.take_plc(5, c5));
  RealTimeAnswers::Taken t = a.end_cycle(0);  // Z did not answer 5 in time
  REQUIRE(t.control);
  CHECK(t.control->cycle == 5);
  CHECK(t.lost.empty());

  a.begin(6);  // nothing from the PLC in cycle 6: its control of 5 stays in force (none handed on)
  CHECK(a.take_axis(2, 5, 2));  // Z's answer to 5, late: used (its error bit reaches the channel)
  CHECK(a.take_axis(2, 6, 0));
  t = a.end_cycle(0);
  CHECK_FALSE(t.control);
  CHECK(t.axis_errors == std::vector<int32_t>{0, 0, 2});
  const auto& w = a.watches();
  REQUIRE(w.size() == 4);
  CHECK(w[2].name() == "axis_sim Z");
  CHECK(w[2].counts().in_time == 1);
  CHECK(w[2].counts().late == 1);
  CHECK(w[2].counts().missing == 0);
  CHECK(w[3].name() == "plc_sim");
  CHECK(w[3].counts().missing == 1);
  CHECK(w[0].counts().missing == 1);  // X did not answer 6

  a.begin(7);
  CHECK_FALSE(a.take_axis(0, 8, 0));  // a cycle not yet sent: forged, refused
  CHECK(a.take_axis(1, 6, 0));        // late
  CHECK(a.take_axis(1, 6, 4));        // the same again: counted, not used
  CHECK(a.take_axis(1, 5, 4));        // older than one taken: counted, not used
  t = a.end_cycle(0);
  CHECK(t.axis_errors[1] == 0);
  CHECK(w[1].counts().duplicate == 1);
  CHECK(w[1].counts().out_of_order == 1);
}

TEST_CASE("RIG-6 real time: a participant silent longer than its watchdog is lost once, naming the watchdog",
          "[RIG-6][real_time]") {
  MachineConfig machine = test::xyz_machine();
  machine.axes[1].watchdog_cycles = 20;
  machine.plc_watchdog_cycles = 5;
  RealTimeAnswers a(machine, true, 2000);
  a.logger_alive(0);
  std::vector<cnc::LostParticipant> lost;
  for (int64_t k = 0; k < 40; ++k) {
    a.begin(k);
    a.take_axis(0, k, 0);
    a.take_axis(2, k, 0);
    if (k < 10) a.take_plc(k, HliControl{});
    if (k < 3) a.take_axis(1, k, 0);
    a.logger_alive(k * 1000);
    for (auto& l : a.end_cycle(k * 1000).lost) lost.push_back(l);
  }
  REQUIRE(lost.size() == 2);
  CHECK(lost[0].name == "plc_sim");
  CHECK(lost[0].axis.empty());
  CHECK(lost[0].what == "watchdog: no answer for 6 cycles (plc_watchdog_cycles 5)");
  CHECK(lost[1].name == "axis_sim Y");
  CHECK(lost[1].axis == "Y");
  CHECK(lost[1].what == "watchdog: no answer for 21 cycles (watchdog_cycles 20)");
  REQUIRE(a.lost().size() == 2);
  CHECK(a.lost()[0].second == 15);  // the PLC last answered in cycle 9
  CHECK(a.lost()[1].second == 23);  // Y last answered in cycle 2

  // The logger answers no cycle: only its heartbeat counts, 2 s.
  const auto l = a.end_cycle(40 * 1000 + 2'000'001).lost;
  REQUIRE(l.size() == 1);
  CHECK(l[0].name == "logger");
  CHECK_THAT(l[0].what, Catch::Contains("no heartbeat for 2001 ms"));
}

TEST_CASE("RIG-6 real time: cycles the CNC ran late (overruns) do not count towards a watchdog", "[RIG-6][real_time]") {
  MachineConfig machine = test::xyz_machine();
  RealTimeAnswers a(machine, false, 2000);
  auto cycle = [&](int64_t k, bool y_answers, bool overrun) {
    a.begin(k);
    for (size_t i = 0; i < machine.axes.size(); ++i)
      if (i != 1 || y_answers) a.take_axis(i, k, 0);
    a.take_plc(k, HliControl{});
    return a.end_cycle(k * 1000, overrun).lost;
  };
  // A host stall: the CNC runs 40 cycles at once, nobody answers in them;
  // Y answers again after it.
  for (int64_t k = 0; k < 5; ++k) CHECK(cycle(k, true, false).empty());
  for (int64_t k = 5; k < 45; ++k) CHECK(cycle(k, k < 5, true).empty());
  for (int64_t k = 45; k < 50; ++k) CHECK(cycle(k, false, false).empty());  // 5 counted cycles silent
  CHECK(cycle(50, true, false).empty());
  CHECK(a.watches()[1].counts().longest_gap_cycles == 45);
  // Y is gone: lost after 21 counted cycles, 40 overrun cycles meanwhile
  std::vector<cnc::LostParticipant> lost;
  for (int64_t k = 51; k < 140 && lost.empty(); ++k) lost = cycle(k, false, k >= 60 && k < 100);
  REQUIRE(lost.size() == 1);
  CHECK(lost[0].name == "axis_sim Y");
  CHECK(lost[0].what == "watchdog: no answer for 21 cycles (watchdog_cycles 20), 40 more the CNC ran late (overruns) "
                        "not counted");
  CHECK(a.lost()[0].second == 111);
}

namespace {

// The real-time policy as the node runs it, on a fake clock and a fake
// bus: the drives and the PLC answer every cycle in time, but for axis Y,
// silent from cycle `y_silent_from` on.
class FakeRealTime : public cnc::CyclePolicy {
 public:
  FakeRealTime(const MachineConfig& machine, int64_t y_silent_from)
      : machine_(machine), ticker_(clock_, machine.cycle_time_us * us), answers_(machine, false, 2000),
        checker_(machine), y_silent_from_(y_silent_from) {
    ticker_.start();
  }
  bool publish(int64_t k, const cnc::Channel& channel, const std::vector<Event>& events) override {
    for (const Event& e : events) events_.push_back(e.message);
    answers_.begin(k);
    for (size_t i = 0; i < channel.setpoints().size(); ++i)
      checker_.add_setpoint(static_cast<int>(i), k, channel.setpoints()[i].position);
    clock_.advance(200 * us);  // the cycle's work and the answers on the way
    for (size_t i = 0; i < machine_.axes.size(); ++i)
      if (machine_.axes[i].name != "Y" || k < y_silent_from_) answers_.take_axis(i, k, 0);
    HliControl control = test::start_command(k >= 5 && k < 10);
    control.cycle = k;
    answers_.take_plc(k, control);
    return true;
  }
  bool publish_event(int64_t, const Event& e) override {
    events_.push_back(e.message);
    return true;
  }
  std::optional<cnc::CycleAnswers> answers(int64_t k) override {
    const Ticker::Tick tick = ticker_.wait(k + 1);
    RealTimeAnswers::Taken t = answers_.end_cycle(clock_.now_ns() / 1000, tick.overrun);
    std::vector<cnc::DriveError> errors;
    return cnc::CycleAnswers{t.control, errors, std::move(t.lost)};
  }

  FakeClock clock_;
  MachineConfig machine_;
  Ticker ticker_;
  RealTimeAnswers answers_;
  logger::LimitChecker checker_;
  int64_t y_silent_from_;
  std::vector<std::string> events_;
};

Scenario scenario_on(const MachineConfig& machine) {
  Scenario s;
  s.machine = machine;
  s.nc_program = "N10 G01 X100 Y100 F6000\nN20 M30\n";
  s.max_time_s = 20;
  s.realtime = true;
  return s;
}

}  // namespace

TEST_CASE("RIG-6 real time: a drive silent longer than its watchdog stops the channel on the path, jerk-limited",
          "[RIG-6][real_time]") {
  const MachineConfig machine = test::xyz_machine();
  const Scenario s = scenario_on(machine);
  cnc::Channel channel(machine, s.nc_program);
  FakeRealTime policy(machine, 500);  // Y falls silent in the middle of the move
  const cnc::CycleLoopResult r = cnc::run_cycles(channel, s, policy);
  CHECK(r.outcome == cnc::RunOutcome::settled);
  CHECK(channel.hli().channel_state == ChannelState::error);
  std::string all;
  for (const auto& e : policy.events_) all += e + "\n";
  CHECK_THAT(all, Catch::Contains("axis_sim Y lost: watchdog: no answer for 21 cycles (watchdog_cycles 20)"));
  CHECK(policy.answers_.lost().at(0).second == 520);
  CHECK(policy.checker_.finish().passed());  // the stop stays within v, a, j
  CHECK(policy.ticker_.overruns() == 0);
  CHECK(policy.ticker_.jitter().count() == r.last_cycle + 1);

  // The same run without the silence reaches the program's end.
  cnc::Channel whole(machine, s.nc_program);
  FakeRealTime quiet(machine, 1'000'000);
  CHECK(cnc::run_cycles(whole, s, quiet).outcome == cnc::RunOutcome::settled);
  CHECK(whole.hli().channel_state == ChannelState::program_end);
  CHECK(quiet.answers_.lost().empty());
}
