// KRN-3, issue 36 item 3: TRAPEZ's velocity change in closed form
// (trapez_change_end, and velocity_change's phases for TRAPEZ) ends where
// the slope types' one construction (velocity_change_reference) and
// advancing through its phases ends, with the same phases, to the last
// bit, from random states (inside and beyond the limits, on the round-off
// edge of "ramping a to 0 is the change"); with Dual its derivative is the
// finite difference's.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "trapez_change.hpp"
#include "velocity_profile.hpp"

using namespace hil::cnc;

namespace {

Limits random_limits(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  return {std::pow(10.0, -2 + 2 * u(rng)), std::pow(10.0, -1 + 2.5 * u(rng)), std::pow(10.0, 0 + 3.5 * u(rng))};
}

bool same(const Phase& x, const Phase& y) {
  return x.duration == y.duration && x.a_end == y.a_end && x.shape == y.shape && x.jerk == y.jerk &&
         x.ramp_time == y.ramp_time && x.ramp_delta_a == y.ramp_delta_a && x.u0 == y.u0;
}

}  // namespace

TEST_CASE("KRN-3 the closed-form TRAPEZ velocity change ends where its phases end, to the last bit",
          "[ipo]") {
  std::mt19937_64 rng(36003);
  std::uniform_real_distribution<double> u(-1, 1);
  long differing = 0;
  for (int i = 0; i < 200000; ++i) {
    const Limits lim = random_limits(rng);
    // A tenth beyond the limits (a state brought back), a tenth on the edge
    // where ramping a to 0 lands on the target velocity.
    const double scale = i % 10 == 0 ? 1.5 : 1.0;
    const MotionState s{0.02 * u(rng), scale * lim.v * u(rng), scale * lim.a * u(rng), 0};
    const double v_target = i % 10 == 1 ? velocity_after_ramp_to_zero(s.v, s.a, lim, SlopeType::trapez)
                                        : lim.v * u(rng);
    const VelocityChange reference = velocity_change_reference(s.v, s.a, v_target, lim, SlopeType::trapez);
    const MotionState phased = reference.end(s);
    const StateOf<double> closed = trapez_change_end(StateOf<double>{s.p, s.v, s.a, 0}, v_target, lim);
    const VelocityChange built = velocity_change(s.v, s.a, v_target, lim, SlopeType::trapez);
    bool same_phases = built.count() == reference.count();
    for (int k = 0; same_phases && k < built.count(); ++k)
      same_phases = same(built.phase(k), reference.phase(k));
    if (!same_phases || closed.p != phased.p || closed.v != phased.v || closed.a != phased.a || closed.j != phased.j) {
      if (differing == 0)
        UNSCOPED_INFO("first difference: p " << phased.p << " v " << phased.v << " a " << phased.a << " j "
                                            << phased.j << " closed p " << closed.p << " v " << closed.v << " a "
                                            << closed.a << " j " << closed.j);
      ++differing;
    }
  }
  CHECK(differing == 0);
}

TEST_CASE("KRN-3 the TRAPEZ velocity change's derivative along a jerk ramp is the finite difference's",
          "[ipo]") {
  std::mt19937_64 rng(36004);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    const Limits lim = random_limits(rng);
    const double v = lim.v * u(rng), a = lim.a * u(rng), jerk = lim.j * (u(rng) < 0 ? -1 : 1);
    const double v_target = lim.v * u(rng);
    const double tau = w(rng) * lim.a / lim.j;
    auto end_after = [&](auto t) {  // ramp at `jerk` for t from (0, v, a), then the change
      using T = decltype(t);
      const StateOf<T> s{t * (v + t * (a / 2 + t * jerk / 6)), v + t * (a + t * jerk / 2), a + t * jerk, jerk};
      return trapez_change_end(s, v_target, lim).p;
    };
    const Dual d = end_after(Dual{tau, 1});
    const double h = 1e-5 * lim.a / lim.j;
    const double fd = (end_after(tau + h) - end_after(tau - h)) / (2 * h);
    // Where a case boundary (a plateau appearing) lies within ±h the
    // difference quotient straddles it: skip those few.
    const double left = (end_after(tau) - end_after(tau - h)) / h, right = (end_after(tau + h) - end_after(tau)) / h;
    if (std::abs(left - right) > 1e-3 * (std::abs(fd) + lim.v)) continue;
    ++checked;
    INFO("case " << i << ": derivative " << d.d << ", finite difference " << fd << ", value " << d.x << " / "
                   << end_after(tau) << " (" << d.x - end_after(tau) << " apart)");
    // Dual divides by reciprocals: its value is double's to round-off (of
    // the way covered at up to lim.v over the change, as long as a ramp
    // from 0 to lim.v and a hold would take).
    const double way = lim.v * (tau + 2 * (lim.v / lim.a + lim.a / lim.j));
    REQUIRE(std::abs(d.x - end_after(tau)) <= 16 * std::numeric_limits<double>::epsilon() * (std::abs(d.x) + way));
    // The difference quotient's own round-off: the end position's over h.
    const double noise = 8 * std::numeric_limits<double>::epsilon() * (std::abs(d.x) + lim.v * lim.v / lim.a) / h;
    REQUIRE(std::abs(d.d - fd) <= 1e-6 * (std::abs(fd) + lim.v) + noise);
  }
  CHECK(checked > 19000);
}
