// RIG-6, RIG-9 (issue 33): a node takes the CNC to be gone when the CNC has
// given no sign of life for the silence limit, whatever else it hears. The
// logger's heartbeat alone used to count: while the logger waited out a
// killed CNC's 10 s itself, every drive and the PLC went on serving, and
// hil run killed axis_sim X (waited for first) as hung.
#include <hil/participant_t.hpp>

#include <catch2/catch.hpp>
#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <thread>

#include "bus.hpp"
#include "channels.hpp"
#include "inbox.hpp"
#include "participant.hpp"

using namespace hil;
using clock_type = std::chrono::steady_clock;

namespace {

constexpr int64_t run_id = 33;

// A bus whose traffic a script makes: each wait is 5 ms, then the script
// hands on what arrives in it.
class ScriptedBus : public lcm_support::Bus {
 public:
  std::function<void(ScriptedBus&)> script;

  void publish(const std::string&, const void*, uint32_t) override {}
  int subscribe(const std::string& channel, Handler handler, int) override {
    handlers_[next_id_] = {channel, std::move(handler)};
    return next_id_++;
  }
  void unsubscribe(int id) override { handlers_.erase(id); }
  int handle_timeout(int) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (script) script(*this);
    return 0;
  }

  void announce(const std::string& name, int8_t phase, int64_t cycle) {
    hil::participant_t m{};
    m.run_id = run_id;
    m.cycle = cycle;
    m.name = name;
    m.phase = phase;
    const std::vector<uint8_t> bytes = lcm_support::encode(m);
    const lcm::ReceiveBuffer rbuf{const_cast<uint8_t*>(bytes.data()), static_cast<uint32_t>(bytes.size()), 0};
    for (auto& [id, h] : handlers_)
      if (h.first == channels::participant) h.second(rbuf, channels::participant);
  }

 private:
  std::map<int, std::pair<std::string, Handler>> handlers_;
  int next_id_ = 0;
};

double seconds_since(clock_type::time_point start) {
  return std::chrono::duration<double>(clock_type::now() - start).count();
}

constexpr auto silence = std::chrono::milliseconds(300);
constexpr int8_t alive = hil::participant_t::PHASE_ALIVE, run_end = hil::participant_t::PHASE_RUN_END;

}  // namespace

TEST_CASE("RIG-6 RIG-9 issue 33: a dead CNC is gone after the silence, though the logger's heartbeat goes on",
          "[RIG-6][RIG-9][participant]") {
  ScriptedBus bus;
  lcm_support::Inbox inbox(bus, run_id);
  lcm_support::Participant participant(inbox, "axis_sim X");
  const auto start = clock_type::now();
  // The logger's heartbeat at the last cycle it recorded; a RUN_END after
  // 3 s keeps the test from hanging on the old rule (it would then pass as
  // "ended" and fail below).
  bus.script = [&](ScriptedBus& b) {
    b.announce("logger", alive, 1001);
    if (seconds_since(start) > 3) b.announce("cnc", run_end, 1001);
  };
  CHECK_FALSE(participant.serve_until_end(silence, [] { return int64_t{1001}; }));
  const double gone_s = seconds_since(start);
  CHECK(gone_s >= 0.3);  // not before the silence, and long before the RUN_END at 3 s
  CHECK(gone_s < 2.0);
  CHECK_FALSE(participant.ended());
}

TEST_CASE("RIG-6 RIG-8 issue 33: the CNC's progress is a sign of life: its cycles, its messages, the logger's "
          "recorded cycle advancing",
          "[RIG-6][RIG-8][participant]") {
  ScriptedBus bus;
  lcm_support::Inbox inbox(bus, run_id);
  lcm_support::Participant participant(inbox, "axis_sim X");
  const auto start = clock_type::now();
  int64_t node_cycle = 0, recorded_cycle = 0;
  // 0 .. 0.5 s the node takes setpoints; 0.5 .. 1 s the faults drop them and
  // only the logger's recorded cycle advances; 1 .. 1.5 s the CNC announces
  // (nothing else); then it ends the run.
  bus.script = [&](ScriptedBus& b) {
    const double t = seconds_since(start);
    if (t < 0.5) ++node_cycle;
    else if (t < 1.0) b.announce("logger", alive, ++recorded_cycle);
    else if (t < 1.5) b.announce("cnc", hil::participant_t::PHASE_READY, 0);
    else b.announce("cnc", run_end, node_cycle);
  };
  CHECK(participant.serve_until_end(silence, [&] { return node_cycle; }));
  CHECK(participant.ended());
  CHECK(seconds_since(start) >= 1.5);
}

TEST_CASE("RIG-6 issue 33: a node whose CNC stops after taking cycles is gone after the silence",
          "[RIG-6][participant]") {
  ScriptedBus bus;
  lcm_support::Inbox inbox(bus, run_id);
  lcm_support::Participant participant(inbox, "plc_sim");
  const auto start = clock_type::now();
  int64_t node_cycle = 0;
  bus.script = [&](ScriptedBus& b) {
    if (seconds_since(start) < 0.4) ++node_cycle;
    b.announce("logger", alive, node_cycle);  // keeps up, then repeats the last cycle it recorded
    if (seconds_since(start) > 3) b.announce("cnc", run_end, node_cycle);
  };
  CHECK_FALSE(participant.serve_until_end(silence, [&] { return node_cycle; }));
  const double gone_s = seconds_since(start);
  CHECK(gone_s >= 0.65);  // the silence after the last cycle taken, near 0.4 s
  CHECK(gone_s < 2.5);
}
