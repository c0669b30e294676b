// LIFT-2 RIG-4: the report shows what the lift took of the overload range.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "report.hpp"
#include "test_machine.hpp"

using namespace hil;

TEST_CASE("LIFT-2 RIG-4 report: per axis the commanded |a| while lift_active beside P-AXIS-00442", "[report][lift]") {
  MachineConfig m = test::xyz_machine();  // Z: a_max 1500, P-AXIS-00442 2000: 3000
  m.axes[2].v_max = 250;
  m.axes[2].j_max = 80000;
  m.lift_method = LiftMethod::time_based;  // the overload range throughout the lift
  logger::LimitChecker checker(m);
  logger::RunLog log;
  // Z rest to rest in 200 cycles with a = 2250 sin(w t) (1.5 a_max) while lifting.
  const double dt = m.cycle_time_s(), w = 2 * M_PI / (200 * dt), a0 = 2250;
  for (int64_t k = 0; k < 300; ++k) {
    const double t = std::clamp<double>(static_cast<double>(k - 50), 0, 200) * dt;
    checker.add_setpoint(2, k, a0 / w * (t - std::sin(w * t) / w));
    if (k >= 50 && k < 260) checker.add_lift_active(2, k);
  }
  const std::string text = rig::format_check(log, checker.finish());
  CHECK_THAT(text, Catch::Contains("lifting |a| [mm/s^2] / P-AXIS-00442"));
  CHECK_THAT(text, Catch::Contains("3000.0000     25.0 %"));
  CHECK_THAT(text, Catch::Contains("lifting |j| [mm/s^3] / j_max"));
  CHECK_THAT(text, Catch::Contains("80000.0000"));
  CHECK_THAT(text, Catch::Contains("lift_active 210 cycles: commanded |a| up to 1.50 a_max (the overload range above a_max)"));
  CHECK_THAT(text, Catch::Contains("lift_active 0 cycles: commanded |a| up to 0.00 a_max\n"));
  CHECK_THAT(text, Catch::Contains("limit violations: 0"));
  // Without a lift, no lift rows.
  logger::LimitChecker quiet(m);
  for (int64_t k = 0; k < 5; ++k) quiet.add_setpoint(0, k, 0);
  CHECK_THAT(rig::format_check(log, quiet.finish()), !Catch::Contains("lifting"));
}

TEST_CASE("RIG-6 report: a real-time run's tick jitter, overruns, each participant's answers and scheduling",
          "[report][RIG-6]") {
  logger::RunLog log;
  CHECK(rig::format_real_time(log) == "real time: no statistics (HIL_RT_STATS) in the log\n");
  logger::RealTimeFigures r;
  r.final = true;
  r.cycle_us = 1000;
  r.ticks = 600000;
  r.overruns = 2;
  r.jitter_p50_us = 9;
  r.jitter_p99_us = 38;
  r.jitter_max_us = 1203;
  r.participants = {{"axis_sim X", 599990, 7, 3, 0, 1, 2, 20}, {"plc_sim", 600000, 0, 0, 0, 0, 0, 20}};
  log.real_time = r;
  logger::LoggedEvent e;
  e.source = "axis_sim X";
  e.event.severity = Severity::warning;
  e.event.message = "real time: normal scheduling (SCHED_FIFO refused: Operation not permitted), memory locked";
  log.events.push_back(e);
  const std::string text = rig::format_real_time(log);
  CHECK_THAT(text, Catch::Contains("real time: 1000 us cycle, 600000 ticks, overruns (missed ticks) 2; tick jitter "
                                   "(wake-up - due) p50 9 us, p99 38 us, max 1203 us\n"));
  CHECK_THAT(text, Catch::Contains("scheduling: axis_sim X normal scheduling (SCHED_FIFO refused: Operation not "
                                   "permitted), memory locked\n"));
  CHECK_THAT(text, Catch::Contains("  axis_sim X         599990        7        3             0          1             2"
                                   "        20\n"));
  r.final = false;  // a log cut short has only a periodic one
  log.real_time = r;
  CHECK_THAT(rig::format_real_time(log), Catch::Contains("(not the final statistics: the run was cut short)"));
}
