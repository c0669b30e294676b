// RIG-8: the sender's side of the faults. What a drive publishes through a
// FaultInjectingBus reaches the others as the plan says — and exactly as
// the CNC's AnswerSchedule expects it to.
#include <hil/axis_state_t.hpp>

#include <catch2/catch.hpp>
#include <vector>

#include "channels.hpp"
#include "fault_bus.hpp"
#include "in_process_bus.hpp"
#include "inbox.hpp"

using namespace hil;

namespace {

MachineConfig machine() {
  MachineConfig m;
  AxisConfig a;
  a.name = "X";
  m.axes.push_back(a);
  return m;
}

// Publishes the drive's answer for cycles 0 .. last through the decorator;
// returns, per cycle, the answers another node received in it (-1: damaged).
std::vector<std::vector<int64_t>> received(const FaultPlan& plan, int64_t last, bool* killed = nullptr) {
  lcm_support::InProcessBus bus;
  std::vector<std::vector<int64_t>> got(static_cast<size_t>(last + 1));
  int64_t now = 0;
  bus.subscribe(
      channels::axis_state("X"),
      [&](const lcm::ReceiveBuffer& rbuf, const std::string&) {
        hil::axis_state_t s;
        got[static_cast<size_t>(now)].push_back(lcm_support::decode(rbuf.data, rbuf.data_size, s) ? s.cycle : -1);
      },
      1000);
  lcm_support::FaultInjectingBus drive(bus, plan, "axis_sim X");
  for (now = 0; now <= last; ++now) {
    hil::axis_state_t s{};
    s.run_id = 1;
    s.cycle = now;
    s.axis = "X";
    static_cast<lcm_support::Bus&>(drive).publish(channels::axis_state("X"), s);
    bus.drain();
  }
  if (killed) *killed = drive.killed();
  return got;
}

}  // namespace

TEST_CASE("RIG-8 fault bus: drop, damage, duplicate, delay, freeze and kill at the sender, as scheduled", "[RIG-8]") {
  const FaultPlan plan = parse_fault_plan(YAML::Load(R"([{drop: AXIS_X_STATE, at_s: 0.001},
      {corrupt: AXIS_X_STATE, at_s: 0.002}, {duplicate: AXIS_X_STATE, at_s: 0.003},
      {delay: axis_sim X, cycles: 2, from_s: 0.005, until_s: 0.007}, {freeze: axis_sim X, at_s: 0.010, for_s: 0.003},
      {kill: axis_sim X, at_s: 0.016}])"),
                                          YAML::Node(), machine());
  bool killed = false;
  const auto got = received(plan, 20, &killed);
  CHECK(got[0] == std::vector<int64_t>{0});
  CHECK(got[1].empty());                            // dropped
  CHECK(got[2] == std::vector<int64_t>{-1});        // damaged: no receiver can decode it
  CHECK(got[3] == std::vector<int64_t>{3, 3});      // twice
  CHECK(got[5].empty());
  CHECK(got[6].empty());
  CHECK(got[7] == std::vector<int64_t>{5, 7});      // two cycles late, before the answer of its cycle
  CHECK(got[8] == std::vector<int64_t>{6, 8});
  CHECK(got[10].empty());
  CHECK(got[13] == std::vector<int64_t>{10, 11, 12, 13});  // all it held after the freeze
  CHECK(got[15] == std::vector<int64_t>{15});
  for (int64_t k = 16; k <= 20; ++k) CHECK(got[static_cast<size_t>(k)].empty());  // killed
  CHECK(killed);

  // What the CNC waits for in each cycle is exactly what came undamaged.
  AnswerSchedule schedule(plan, "axis_sim X");
  for (int64_t k = 0; k <= 20; ++k) {
    std::vector<int64_t> valid;
    for (const int64_t c : got[static_cast<size_t>(k)])
      if (c >= 0) valid.push_back(c);
    CHECK(schedule.arrivals(k) == valid);
  }
}
