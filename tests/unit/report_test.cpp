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
  m.axes[2].j_max = 60000;
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
  CHECK_THAT(text, Catch::Contains("lift_active 210 cycles: commanded |a| up to 1.50 a_max (the overload range above a_max)"));
  CHECK_THAT(text, Catch::Contains("lift_active 0 cycles: commanded |a| up to 0.00 a_max\n"));
  CHECK_THAT(text, Catch::Contains("limit violations: 0"));
  // Without a lift, no lift rows.
  logger::LimitChecker quiet(m);
  for (int64_t k = 0; k < 5; ++k) quiet.add_setpoint(0, k, 0);
  CHECK_THAT(rig::format_check(log, quiet.finish()), !Catch::Contains("lifting"));
}
