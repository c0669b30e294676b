// RIG-8: the fault plan a scenario declares, the fate of each message, and
// which answers reach the CNC in which cycle — the rules the senders, the
// CNC and the offline check share.
#include <catch2/catch.hpp>
#include <map>

#include "config_error.hpp"
#include "fault_plan.hpp"

using namespace hil;

namespace {

MachineConfig machine() {
  MachineConfig m;
  m.cycle_time_us = 1000;
  for (const char* name : {"X", "Y"}) {
    AxisConfig a;
    a.name = name;
    m.axes.push_back(a);
  }
  return m;
}

FaultPlan plan(const std::string& yaml, int seed = 1) {
  return parse_fault_plan(YAML::Load(yaml), YAML::Load(std::to_string(seed)), machine());
}

}  // namespace

TEST_CASE("RIG-8 fault plan: the scenario's faults, each checked against the machine", "[RIG-8]") {
  const FaultPlan p = plan(R"([{drop: AXIS_Y_STATE, percent: 5, from_s: 1, until_s: 2},
                               {delay: axis_sim X, ms: 2.5}, {freeze: plc_sim, at_s: 0.5, for_s: 0.1},
                               {kill: axis_sim Y, at_s: 3}, {corrupt: HLI_CONTROL, at_s: 1.5},
                               {duplicate: AXIS_X_CMD, percent: 10}])");
  REQUIRE(p.faults.size() == 6);
  CHECK(p.faults[0].from_cycle == 1000);
  CHECK(p.faults[0].until_cycle == 2000);
  CHECK(p.faults[1].delay_cycles == 3);  // 2.5 ms at 1 ms cycles: 3 cycles
  CHECK(p.faults[2].from_cycle == 500);
  CHECK(p.faults[2].until_cycle == 600);
  CHECK(p.kill_cycle("axis_sim Y") == 3000);
  CHECK_FALSE(p.kill_cycle("axis_sim X"));
  CHECK(p.faults[4].until_cycle == 1501);
  for (const char* bad : {"[{drop: AXIS_Z_STATE}]", "[{drop: HIL_EVENT}]", "[{kill: cnc, at_s: 1}]",
                          "[{freeze: axis_sim Y, at_s: 1}]", "[{delay: plc_sim}]", "[{delay: plc_sim, cycles: 2, ms: 2}]",
                          "[{drop: HLI_STATE, percent: 101}]", "[{drop: HLI_STATE, at_s: 1, from_s: 1}]",
                          "[{drop: HLI_STATE, kill: plc_sim}]", "[{drop: HLI_STATE, sometimes: true}]", "[{}]",
                          "[{kill: axis_sim X, at_s: 0}]"})
    CHECK_THROWS_AS(plan(bad), ConfigError);
}

TEST_CASE("RIG-8 fault plan: a message's fate depends on the seed, channel and cycle only", "[RIG-8]") {
  const FaultPlan a = plan("[{drop: AXIS_Y_STATE, percent: 30}]", 7), b = plan("[{drop: AXIS_Y_STATE, percent: 30}]", 7),
                  c = plan("[{drop: AXIS_Y_STATE, percent: 30}]", 8);
  int dropped = 0, same = 0, same_other_seed = 0;
  for (int64_t k = 0; k < 10000; ++k) {
    dropped += a.fate("AXIS_Y_STATE", k).dropped ? 1 : 0;
    same += a.fate("AXIS_Y_STATE", k).dropped == b.fate("AXIS_Y_STATE", k).dropped ? 1 : 0;
    same_other_seed += a.fate("AXIS_Y_STATE", k).dropped == c.fate("AXIS_Y_STATE", k).dropped ? 1 : 0;
    CHECK_FALSE(a.fate("AXIS_X_STATE", k).dropped);
  }
  CHECK(dropped > 2800);
  CHECK(dropped < 3200);
  CHECK(same == 10000);
  CHECK(same_other_seed < 9000);
}

TEST_CASE("RIG-8 answer schedule: lost inputs, a delay, a freeze, a kill, a duplicate", "[RIG-8]") {
  auto run = [](const FaultPlan& p, const std::string& who, int64_t last) {
    AnswerSchedule s(p, who);
    std::map<int64_t, std::vector<int64_t>> arrived;
    for (int64_t j = 0; j <= last; ++j)
      if (auto a = s.arrivals(j); !a.empty()) arrived[j] = a;
    return arrived;
  };
  SECTION("a lost setpoint: no answer to it") {
    const auto a = run(plan("[{drop: AXIS_X_CMD, at_s: 0.003}]"), "axis_sim X", 5);
    CHECK(a.count(3) == 0);
    CHECK(a.at(4) == std::vector<int64_t>{4});
  }
  SECTION("a delay of 2 cycles from cycle 2: each answer two cycles late") {
    const auto a = run(plan("[{delay: axis_sim X, cycles: 2, from_s: 0.002, until_s: 0.004}]"), "axis_sim X", 6);
    CHECK(a.at(1) == std::vector<int64_t>{1});
    CHECK(a.count(2) == 0);
    CHECK(a.count(3) == 0);
    CHECK(a.at(4) == std::vector<int64_t>{2, 4});
    CHECK(a.at(5) == std::vector<int64_t>{3, 5});
  }
  SECTION("a freeze: all it held at once after it") {
    const auto a = run(plan("[{freeze: plc_sim, at_s: 0.002, for_s: 0.003}]"), "plc_sim", 6);
    CHECK(a.count(2) + a.count(3) + a.count(4) == 0);
    CHECK(a.at(5) == std::vector<int64_t>{2, 3, 4, 5});
  }
  SECTION("held answers wait for the next answer it sends") {
    const auto a = run(plan("[{freeze: axis_sim X, at_s: 0.002, for_s: 0.002}, {drop: AXIS_X_CMD, at_s: 0.004}]"),
                       "axis_sim X", 6);
    CHECK(a.count(4) == 0);
    CHECK(a.at(5) == std::vector<int64_t>{2, 3, 5});
  }
  SECTION("a kill: nothing from its cycle on, held answers lost") {
    const auto a = run(plan("[{kill: axis_sim Y, at_s: 0.003}, {delay: axis_sim Y, cycles: 5}]"), "axis_sim Y", 10);
    CHECK(a.empty());
    const auto b = run(plan("[{kill: axis_sim Y, at_s: 0.003}]"), "axis_sim Y", 10);
    CHECK(b.size() == 3);
  }
  SECTION("a duplicate arrives twice, a damaged answer not at all") {
    const auto a = run(plan("[{duplicate: HLI_CONTROL, at_s: 0.001}, {corrupt: HLI_CONTROL, at_s: 0.002}]"), "plc_sim", 3);
    CHECK(a.at(1) == std::vector<int64_t>{1, 1});
    CHECK(a.count(2) == 0);
  }
}
