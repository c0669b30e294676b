// RIG-8, RIG-6: lock-step with faults planned. The CNC waits only for the
// answers the plan lets arrive in a cycle, uses a late one when it comes,
// and its watchdog loses a participant silent for longer than its machine
// parameter (the channel then stops as on a drive error).
#include <catch2/catch.hpp>

#include "lock_step.hpp"

using namespace hil;

TEST_CASE("RIG-8 RIG-6 lock-step with faults: due answers only, a late one used, the watchdog", "[RIG-8]") {
  MachineConfig machine;
  AxisConfig x;
  x.name = "X";
  x.watchdog_cycles = 3;
  machine.axes.push_back(x);
  machine.plc_watchdog_cycles = 20;
  const FaultPlan plan = parse_fault_plan(
      YAML::Load("[{delay: axis_sim X, cycles: 2, from_s: 0.002, until_s: 0.004}, {kill: plc_sim, at_s: 0.004}]"),
      YAML::Node(), machine);
  cnc_node::LockStep lock_step(machine, false, 5000, 0, &plan);

  auto cycle = [&](int64_t k, std::vector<int64_t> axis_answers, bool plc) {
    lock_step.begin(k);
    for (const int64_t c : axis_answers) CHECK(lock_step.take_axis(0, c, c == 2 ? 4 : 0));
    if (plc) CHECK(lock_step.take_plc(k, HliControl{}));
    CHECK(lock_step.complete());
    return lock_step.take();
  };
  cycle(0, {0}, true);
  cycle(1, {1}, true);
  // cycles 2 and 3: X's answers are held back two cycles: nothing due from X
  lock_step.begin(2);
  CHECK(lock_step.awaited_axis(0).empty());
  CHECK_FALSE(lock_step.take_axis(0, 2, 0));  // not due now: refused
  CHECK(lock_step.take_plc(2, HliControl{}));
  CHECK(lock_step.complete());
  lock_step.take();
  cycle(3, {}, true);
  // cycle 4: the late answer to 2 (with a drive error) and 4's own; the PLC is killed
  const auto taken = cycle(4, {2, 4}, false);
  CHECK(taken.axis_errors.at(0) == 4);  // the late answer's error reaches the channel
  CHECK_FALSE(taken.control);          // the PLC's last control stays
  // cycle 5: the answer to 3 comes after 4's: out of order, taken but not used
  cycle(5, {3, 5}, false);
  // The PLC silent from 4 on: lost by its watchdog (20) in cycle 24.
  for (int64_t k = 6; k < 24; ++k) CHECK(cycle(k, {k}, false).lost.empty());
  const auto lost = cycle(24, {24}, false).lost;
  REQUIRE(lost.size() == 1);
  CHECK(lost[0].name == "plc_sim");
  CHECK(lost[0].parameter == "plc_watchdog_cycles");
  CHECK(lost[0].what == "watchdog: no answer for 21 cycles (plc_watchdog_cycles 20)");
  const auto counts = lock_step.answer_counts();
  CHECK(counts[0].second.late == 1);
  CHECK(counts[0].second.out_of_order == 1);
  CHECK(counts[0].second.missing == 1);  // the answer to 3 was never used
  CHECK(counts[1].second.missing == 21);
}
