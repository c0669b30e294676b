// KRN-3: the time-optimal jerk-limited profile generator of cnc/ipo:
// rest-to-rest against the closed form, 10^6 random states, dense grids of
// boundary cases, the velocity-target mode, slope types STEP and SIN2, and
// states outside the limits. SI units here (m, m/s, m/s², m/s³).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "bisect.hpp"
#include "position_profile.hpp"
#include "profile_check.hpp"
#include "velocity_profile.hpp"

using namespace hil::cnc;

namespace {

// The textbook rest-to-rest duration (TRAPEZ) in its three cases.
double closed_form_duration(double L, const Limits& lim) {
  const double a = lim.a, j = lim.j, v = lim.v;
  const bool a_reached_before_v = v * j >= a * a;
  const double l_v = a_reached_before_v ? v * (v / a + a / j) : 2 * v * std::sqrt(v / j);
  if (L >= l_v) return L / v + (a_reached_before_v ? v / a + a / j : 2 * std::sqrt(v / j));
  if (L >= 2 * a * a * a / (j * j)) {
    const double vp = (-a * a / j + std::sqrt(a * a * a * a / (j * j) + 4 * a * L)) / 2;
    return 2 * (vp / a + a / j);
  }
  return 4 * std::cbrt(L / (2 * j));
}

std::string describe(const MotionState& s, double target, const Limits& lim) {
  std::ostringstream o;
  o.precision(17);
  o << "p0=" << s.p << " v0=" << s.v << " a0=" << s.a << " pf=" << target << " vmax=" << lim.v << " amax=" << lim.a
    << " jmax=" << lim.j;
  return o.str();
}

// Counts the cases that fail `meets`; reports the first few.
struct Tally {
  long cases = 0, failures = 0;
  std::ostringstream first;
  void add(const MotionState& s, double target, const Limits& lim, SlopeType slope) {
    ++cases;
    const MotionProfile p = position_profile(s, target, lim, slope);
    if (meets(p, target, lim, slope)) return;
    if (++failures <= 5) {
      const ProfileExtremes x = extremes(p);
      first << to_string(slope) << ' ' << describe(s, target, lim) << " -> end p=" << p.end().p
            << " v=" << p.end().v << " a=" << p.end().a << " max v=" << x.max_v << " a=" << x.max_a
            << " j=" << x.max_j << '\n';
    }
  }
  void require() const {
    INFO(cases << " cases, " << failures << " failed:\n" << first.str());
    REQUIRE(failures == 0);
  }
};

// A state inside the limits from which |v| need not pass v_max: ramping the
// acceleration to 0 at once keeps |v| <= v_max.
MotionState random_feasible_state(std::mt19937_64& rng, const Limits& lim, SlopeType slope) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (;;) {
    const MotionState s{0.02 * u(rng), lim.v * u(rng), lim.a * u(rng), 0};
    if (std::abs(velocity_after_ramp_to_zero(s.v, s.a, lim, slope)) <= lim.v) return s;
  }
}

// The lowest velocity of a profile: at phase ends and where a crosses 0.
double min_velocity(const MotionProfile& p) {
  double v = p.start().v;
  for (size_t i = 0; i < p.phases().size(); ++i) {
    const MotionState s = p.phase_start(i), e = p.phase_start(i + 1);
    v = std::min(v, e.v);
    if ((s.a < 0) != (e.a < 0) && p.phases()[i].shape == Phase::Shape::linear && p.phases()[i].jerk != 0)
      v = std::min(v, advance(s, p.phases()[i], -s.a / p.phases()[i].jerk).v);
  }
  return v;
}

Limits random_limits(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  return {std::pow(10.0, -2 + 2 * u(rng)), std::pow(10.0, -1 + 2.5 * u(rng)), std::pow(10.0, 0 + 3.5 * u(rng))};
}

}  // namespace

TEST_CASE("KRN-3 profile: rest-to-rest durations match the closed form in all its cases", "[ipo]") {
  const Limits lim{0.1, 1, 20};  // a/j = 0.05 s, a²/j = 0.05 m/s
  for (double L : {0.05, 0.01, 0.0005, 1e-7}) {
    INFO("L=" << L);
    CHECK(rest_to_rest(L, lim).duration() == Approx(closed_form_duration(L, lim)).epsilon(1e-12));
  }
  const Limits low_v{0.02, 1, 20};  // v_max reached before a_max
  CHECK(rest_to_rest(0.01, low_v).duration() == Approx(0.01 / 0.02 + 2 * std::sqrt(0.02 / 20)).epsilon(1e-12));
  CHECK(rest_to_rest(0, lim).duration() == 0);
  CHECK(rest_to_rest(-0.05, lim).duration() == Approx(closed_form_duration(0.05, lim)).epsilon(1e-12));
}

TEST_CASE("KRN-3 profile: grid of boundary moves, 1 um steps to 20 mm and limit edges to a few ulp", "[ipo]") {
  const Limits round_limits[] = {{0.5, 5, 50}, {1, 10, 100}, {0.1, 2, 40}, {0.25, 1, 1000}, {0.05, 0.5, 1}};
  Tally tally;
  double worst_duration_error = 0;
  for (const Limits& lim : round_limits) {
    auto check = [&](double L) {
      tally.add(MotionState{}, L, lim, SlopeType::trapez);
      tally.add(MotionState{0.003, 0, 0, 0}, 0.003 - L, lim, SlopeType::trapez);
      const double T = rest_to_rest(L, lim).duration();
      worst_duration_error = std::max(worst_duration_error, std::abs(T - closed_form_duration(L, lim)) / T);
    };
    for (int um = 1; um <= 20000; ++um) check(um * 1e-6);
    // Distances at which a_max is just reached, v_max is just reached, and
    // (for v < a²/j) v_max is reached without a_max.
    const double a_edge = 2 * lim.a * lim.a * lim.a / (lim.j * lim.j);
    const double v_edge = lim.v * lim.j >= lim.a * lim.a ? lim.v * (lim.v / lim.a + lim.a / lim.j)
                                                         : 2 * lim.v * std::sqrt(lim.v / lim.j);
    for (double edge : {a_edge, v_edge}) {
      double below = edge, above = edge;
      check(edge);
      for (int ulp = 0; ulp < 8; ++ulp) {
        check(below = std::nextafter(below, 0.0));
        check(above = std::nextafter(above, 1.0));
      }
      for (double factor : {1 - 1e-12, 1 + 1e-12, 1 - 1e-9, 1 + 1e-9, 1 - 1e-6, 1 + 1e-6}) check(edge * factor);
    }
  }
  tally.require();
  CHECK(tally.cases > 200000);
  CHECK(worst_duration_error < 1e-9);
}

TEST_CASE("KRN-3 profile: 10^6 seeded random states reach the target within 1e-9, within the limits", "[ipo]") {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> u(-1, 1);
  Tally tally;
  for (int i = 0; i < 1000000; ++i) {
    const Limits lim = random_limits(rng);
    const MotionState s = random_feasible_state(rng, lim, SlopeType::trapez);
    tally.add(s, 0.02 * u(rng), lim, SlopeType::trapez);
  }
  tally.require();
}

TEST_CASE("KRN-3 profile: a state on the optimal profile replans to the rest of it (Bellman)", "[ipo]") {
  // A time-optimal profile's tail is time-optimal: replanning from any state
  // on it must take exactly the time left. A planner that is merely
  // feasible fails this.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  int mismatches = 0;
  std::ostringstream first;
  for (int i = 0; i < 100000; ++i) {
    const Limits lim = random_limits(rng);
    const MotionState s{0, lim.v * u(rng), lim.a * u(rng), 0};
    const double target = 0.02 * u(rng);
    const MotionProfile p = position_profile(s, target, lim, SlopeType::trapez);
    const double t = p.duration() * w(rng);
    const double rest = position_profile(p.at(t), target, lim, SlopeType::trapez).duration();
    // Resolution: a position round-off e moves the switch instant by up to
    // cbrt(6 e / j) (the position reacts to it cubically); e grows with the
    // distance covered (runaway starts reach far beyond v_max).
    const double e = 1e-14 * (extremes(p).max_v * p.duration() + 0.02);
    const double resolution = 1e-9 * std::max(1.0, p.duration()) + 2 * std::cbrt(6 * e / lim.j);
    if (std::abs(rest - (p.duration() - t)) > resolution && ++mismatches <= 5)
      first << describe(s, target, lim) << " t=" << t << " left " << p.duration() - t << " replanned " << rest
            << '\n';
  }
  INFO(first.str());
  CHECK(mismatches == 0);
}

TEST_CASE("KRN-3 profile: velocity-target mode ends on the target velocity with a = 0", "[ipo]") {
  const Limits lim{1, 10, 100};
  // From rest: T = v/a + a/j with an acceleration plateau, 2 sqrt(v/j) without.
  CHECK(velocity_profile({}, 0.5, lim, SlopeType::trapez).duration() == Approx(2 * std::sqrt(0.5 / 100)));
  CHECK(velocity_profile({}, 0.5, {1, 10, 1000}, SlopeType::trapez).duration() == Approx(0.5 / 10 + 0.01));
  CHECK(velocity_profile({}, 0.4, {1, 10, 10}, SlopeType::trapez).duration() == Approx(2 * std::sqrt(0.04)));
  CHECK(velocity_profile({}, 5, lim, SlopeType::trapez).end().v == Approx(1));  // clamped to v_max
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int failures = 0;
  for (int i = 0; i < 100000; ++i) {
    const Limits l = random_limits(rng);
    const MotionState s{0, l.v * u(rng), l.a * u(rng), 0};
    const double vt = l.v * u(rng);
    for (SlopeType slope : {SlopeType::step, SlopeType::trapez, SlopeType::sin2}) {
      const MotionProfile p = velocity_profile(s, vt, l, slope);
      const ProfileExtremes x = extremes(p);
      const bool ok = x.finite && std::abs(p.end().v - vt) <= 1e-9 * l.v && std::abs(p.end().a) <= 1e-9 * l.a &&
                      x.max_a <= l.a * (1 + 1e-9) && (slope == SlopeType::step || x.max_j <= l.j * (1 + 1e-9));
      failures += ok ? 0 : 1;
    }
  }
  CHECK(failures == 0);
}

TEST_CASE("KRN-3 profile: slope types STEP and SIN2", "[ipo]") {
  const Limits lim{0.1, 1, 20};
  SECTION("STEP: acceleration-limited, T = L/v + v/a, or 2 sqrt(L/a)") {
    CHECK(rest_to_rest(0.05, lim, SlopeType::step).duration() == Approx(0.05 / 0.1 + 0.1 / 1).epsilon(1e-12));
    CHECK(rest_to_rest(0.004, lim, SlopeType::step).duration() == Approx(2 * std::sqrt(0.004)).epsilon(1e-12));
  }
  SECTION("SIN2: sin² jerk pulses of peak j_max, slower than TRAPEZ") {
    for (double L : {0.05, 0.005, 0.0001}) {
      const MotionProfile p = rest_to_rest(L, lim, SlopeType::sin2);
      CHECK(p.duration() > rest_to_rest(L, lim).duration());
      CHECK(extremes(p).max_j == Approx(lim.j));
    }
    // Ramps that run whole are sin² pulses: the jerk starts and ends at 0.
    const MotionProfile p = rest_to_rest(0.05, lim, SlopeType::sin2);
    for (std::size_t i = 0; i < p.phases().size(); ++i)
      if (p.phases()[i].duration > 0) CHECK(std::abs(advance(p.phase_start(i), p.phases()[i], 0).j) < 1e-9);
  }
  SECTION("random states, STEP") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    Tally tally;
    for (int i = 0; i < 100000; ++i) {
      const Limits l = random_limits(rng);
      tally.add(random_feasible_state(rng, l, SlopeType::step), 0.02 * u(rng), l, SlopeType::step);
    }
    tally.require();
  }
  SECTION("random states, SIN2") {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-1, 1);
    Tally tally;
    for (int i = 0; i < 100000; ++i) {
      const Limits l = random_limits(rng);
      tally.add(i % 4 ? random_feasible_state(rng, l, SlopeType::sin2) : MotionState{}, 0.02 * u(rng), l,
                SlopeType::sin2);
    }
    tally.require();
  }
  SECTION("SIN2 replanned anywhere on a SIN2 profile, to a new target") {
    // The channel replans at every block transition, mostly in the middle
    // of a sin² ramp: the replanned motion must stay within the limits the
    // interrupted one kept.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
    Tally tally;
    for (int i = 0; i < 100000; ++i) {
      const Limits l = random_limits(rng);
      const MotionProfile p = position_profile(random_feasible_state(rng, l, SlopeType::sin2), 0.02 * u(rng), l,
                                               SlopeType::sin2);
      const MotionState s = p.at(p.duration() * w(rng));
      tally.add(s, s.p + 0.02 * u(rng), l, SlopeType::sin2);
    }
    tally.require();
  }
}

TEST_CASE("KRN-3 profile: states outside the limits are brought back, never driven further", "[ipo]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  Tally tally;
  for (int i = 0; i < 100000; ++i) {
    const Limits lim = random_limits(rng);
    const MotionState s{0, 2 * lim.v * u(rng), 3 * lim.a * u(rng), 0};
    // Leave out runaways (an acceleration whose unavoidable carry-on alone
    // exceeds 10 v_max): those are no motion of a real machine.
    if (s.a * s.a / (2 * lim.j) > 10 * lim.v) continue;
    for (SlopeType slope : {SlopeType::step, SlopeType::trapez, SlopeType::sin2}) tally.add(s, 0.05 * u(rng), lim, slope);
  }
  tally.require();
  // Far above v_max with the target ahead: brake to v_max first, then cruise.
  const Limits lim{0.1, 1, 20};
  const MotionProfile p = position_profile({0, 0.3, 0, 0}, 1.0, lim, SlopeType::trapez);
  const MotionState later = p.at(0.5);
  CHECK(later.v == Approx(0.1));
  CHECK(later.a == Approx(0).margin(1e-12));
}

TEST_CASE("KRN-3 profile: forward to a block end with an end velocity, a lower one, or the closest reachable one, and an arrival status that says which",
          "[ipo]") {
  std::mt19937_64 rng(31415);
  std::uniform_real_distribution<double> u(0, 1);
  long reached = 0, lower = 0, closest = 0, too_fast = 0, failures = 0;
  std::ostringstream first;
  for (int i = 0; i < 200000; ++i) {
    const Limits lim = random_limits(rng);
    const SlopeType slope = std::array{SlopeType::trapez, SlopeType::step, SlopeType::sin2}[i % 3];
    MotionState s;
    do {
      s = {0, lim.v * u(rng), lim.a * (2 * u(rng) - 1), 0};
    } while (velocity_after_ramp_to_zero(s.v, s.a, lim, slope) < 0 ||
             velocity_after_ramp_to_zero(s.v, s.a, lim, slope) > lim.v);
    const double target = 0.05 * u(rng), v_end = lim.v * u(rng);
    const BlockProfile planned = block_profile(s, target, v_end, lim, slope);
    const MotionProfile& p = planned.profile;
    const MotionProfile direct = velocity_profile(s, v_end, lim, slope);
    const ProfileExtremes x = extremes(p);
    const MotionState e = p.end();
    const double v_natural = velocity_after_ramp_to_zero(s.v, s.a, lim, slope);
    bool ok = x.finite && x.durations_valid && x.max_v <= lim.v * (1 + 1e-9) && x.max_a <= lim.a * (1 + 1e-9) &&
              std::abs(e.a) <= 1e-9 * lim.a && min_velocity(p) >= -1e-9 * lim.v;  // never backwards on a path
    if (direct.end().p <= target) {  // v_end reachable within the distance
      ++reached;
      ok = ok && std::abs(e.p - target) <= 1e-9 && std::abs(e.v - v_end) <= 1e-9 * lim.v &&
           planned.arrival == Arrival::as_asked;
    } else if (velocity_change(s.v, s.a, 0, lim, slope).end(s).p <= target ||
               (slope == SlopeType::sin2 &&  // SIN2 that cannot arrive falls back to full-jerk linear ramps
                velocity_change(s.v, s.a, 0, lim, SlopeType::trapez).end(s).p <= target)) {
      // v_end is the most the path may arrive with: a lower velocity that
      // can be reached on the target is taken (braking, a lower end
      // velocity can need less way).
      ++lower;
      ok = ok && std::abs(e.p - target) <= 1e-9 && e.v <= v_end + 1e-9 * lim.v &&
           (planned.arrival == Arrival::slower || planned.arrival == Arrival::as_asked);
    } else {
      ++closest;
      const double lo = std::min(v_end, v_natural), hi = std::max(v_end, v_natural);
      ok = ok && e.v >= lo - 1e-9 * lim.v && e.v <= hi + 1e-9 * lim.v && e.p >= target - 1e-9;
      // The status says whether the arrival keeps v_end as the most allowed.
      const bool kept = e.v <= v_end + 1e-9 * (1 + v_end) && e.p <= target + 1e-9 * (1 + target);
      ok = ok && kept == keeps_end(planned.arrival);
      if (!kept) ++too_fast;
    }
    // With v_end = 0 it is the (time-optimal) positioning to rest.
    if (ok && i % 10 == 0) {
      const MotionProfile to_rest = block_profile(s, target, 0, lim, slope).profile;
      const MotionProfile positioned = position_profile(s, target, lim, slope);
      if (positioned.end().p >= target - 1e-9 && extremes(positioned).max_v <= lim.v * (1 + 1e-9) &&
          velocity_change(s.v, s.a, 0, lim, slope).end(s).p <= target)
        ok = std::abs(to_rest.duration() - positioned.duration()) <= 1e-9 * (1 + positioned.duration());
    }
    if (!ok && ++failures <= 5)
      first << to_string(slope) << ' ' << describe(s, target, lim) << " v_end=" << v_end << " -> p=" << e.p
            << " v=" << e.v << " a=" << e.a << " max v=" << x.max_v << " a=" << x.max_a << '\n';
  }
  INFO(reached << " reached, " << lower << " lower, " << closest << " closest (" << too_fast << " too fast); "
                << failures << " failed:\n"
                << first.str());
  CHECK(reached > 50000);
  CHECK(lower > 1000);
  CHECK(closest > 10000);
  CHECK(too_fast > 1000);
  REQUIRE(failures == 0);
}

TEST_CASE("KRN-3 last_below: the last double that fits, as bisection finds it, in fewer evaluations", "[ipo]") {
  // The look-ahead's highest entry velocity (issue 36: 62 evaluations per
  // transition by bisection, 13 now on the rounded chord circle).
  std::mt19937_64 rng(36);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 2000; ++k) {
    const double r = u(rng) * 0.01, jerk = 1000 + u(rng) * 1e5, a = 100 + u(rng) * 5000, v1 = u(rng) * 50;
    const Limits lim{1e9, a, jerk};
    const SlopeType slope = k % 2 ? SlopeType::trapez : SlopeType::sin2;
    auto covers = [&](double v0) { return v0 * r + velocity_change_end({0, v0, 0, 0}, v1, lim, slope).p; };
    const double v_cap = v1 + 1 + u(rng) * 300, limit = covers(v1 + (v_cap - v1) * u(rng));
    int evaluations = 0;
    const double fast = last_below(v1, v_cap, limit, v1 * r, covers(v_cap), [&](double v) {
      ++evaluations;
      return covers(v);
    });
    const double bisected = last_fitting(v1, v_cap, [&](double v) { return covers(v) <= limit; });
    INFO("case " << k << ": " << fast << " against " << bisected);
    CHECK(covers(fast) <= limit);
    CHECK(covers(std::nextafter(fast, v_cap)) > limit);
    CHECK(std::abs(fast - bisected) <= 4 * std::numeric_limits<double>::epsilon() * bisected);
    CHECK(evaluations <= 40);
  }
}
