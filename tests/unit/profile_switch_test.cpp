// KRN-3, issue 17: the fast paths of the profile generator (closed form
// from rest to rest, bracketed search per drive phase elsewhere) against
// the solver they replaced (SwitchSearch::reference: Illinois regula falsi
// and bisection over the whole drive, to adjacent doubles) and, from rest,
// against the exact duration (the textbook closed form in long double).
// Target reached, limits held, durations not longer: on random moves from
// rest, on moves where a_max or v_max is just reached (to a few ulp), and
// from random states.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>

#include "position_profile.hpp"
#include "profile_check.hpp"

using namespace hil::cnc;

namespace {

Limits random_limits(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  return {std::pow(10.0, -2 + 2 * u(rng)), std::pow(10.0, -1 + 2.5 * u(rng)), std::pow(10.0, 0 + 3.5 * u(rng))};
}

// The exact rest-to-rest duration over the doubles' distance (TRAPEZ,
// STEP), in long double.
long double exact_duration(const MotionState& s, double target, const Limits& lim, SlopeType slope) {
  using real = long double;
  const real L = std::abs(static_cast<real>(target) - s.p), a = lim.a, v = lim.v;
  if (slope == SlopeType::step) return L * a >= v * v ? L / v + v / a : 2 * std::sqrt(L / a);
  const real j = lim.j;
  const bool a_before_v = v * j >= a * a;
  const real l_v = a_before_v ? v * (v / a + a / j) : 2 * v * std::sqrt(v / j);
  if (L >= l_v) return L / v + (a_before_v ? v / a + a / j : 2 * std::sqrt(v / j));
  if (L >= 2 * a * a * a / (j * j)) {
    const real vp = (-a * a / j + std::sqrt(a * a * a * a / (j * j) + 4 * a * L)) / 2;
    return 2 * (vp / a + a / j);
  }
  return 4 * std::cbrt(L / (2 * j));
}

// Fast against reference (and from rest against the exact duration);
// reports the worst duration differences.
struct Comparison {
  long cases = 0, failures = 0;
  double worst_relative = 0;        // |T_fast - T_reference| / T_reference
  double worst_exact_fast = 0;      // from rest: |T_fast - T_exact| / T_exact
  double worst_exact_reference = 0;  // from rest: |T_reference - T_exact| / T_exact
  std::ostringstream first;

  void add(const MotionState& s, double target, const Limits& lim, SlopeType slope) {
    ++cases;
    const MotionProfile fast = position_profile(s, target, lim, slope);
    const MotionProfile reference = position_profile(s, target, lim, slope, SwitchSearch::reference);
    const double T = reference.duration(), difference = std::abs(fast.duration() - T);
    if (T > 0) worst_relative = std::max(worst_relative, difference / T);
    bool ok = meets(fast, target, lim, slope);
    if (s.v == 0 && s.a == 0 && slope != SlopeType::sin2) {
      // From rest the fast path is closed-form: within 1e-12 of the exact
      // duration, and never further from it than the reference (whose
      // search resolves a tiny move far from 0 only to the position's ulp).
      const long double exact = exact_duration(s, target, lim, slope);
      if (exact > 0) {
        const double e_fast = static_cast<double>(std::abs(fast.duration() - exact) / exact);
        const double e_reference = static_cast<double>(std::abs(T - exact) / exact);
        worst_exact_fast = std::max(worst_exact_fast, e_fast);
        worst_exact_reference = std::max(worst_exact_reference, e_reference);
        ok = ok && e_fast <= 1e-12 && e_fast <= e_reference + 1e-15;
      }
    } else {
      ok = ok && difference <= 1e-12 * T + 1e-15;
    }
    if (ok) return;
    if (++failures <= 5) {
      std::ostringstream o;
      o.precision(17);
      o << to_string(slope) << " p0=" << s.p << " v0=" << s.v << " a0=" << s.a << " pf=" << target
        << " lim " << lim.v << ' ' << lim.a << ' ' << lim.j << ": T fast " << fast.duration() << " reference " << T
        << ", end p " << fast.end().p << " v " << fast.end().v << " a " << fast.end().a << '\n';
      first << o.str();
    }
  }
  void require() const {
    INFO(cases << " cases, " << failures << " failed; worst relative duration difference to the reference "
               << worst_relative << ", to the exact duration: fast " << worst_exact_fast << ", reference "
               << worst_exact_reference << ":\n"
               << first.str());
    REQUIRE(failures == 0);
  }
};

double a_max_edge(const Limits& lim) { return 2 * lim.a * lim.a * lim.a / (lim.j * lim.j); }
double v_max_edge(const Limits& lim) {
  return lim.v * lim.j >= lim.a * lim.a ? lim.v * (lim.v / lim.a + lim.a / lim.j) : 2 * lim.v * std::sqrt(lim.v / lim.j);
}

}  // namespace

TEST_CASE("KRN-3 profile, issue 17: closed form from rest, random moves: exact durations, none longer", "[ipo]") {
  std::mt19937_64 rng(1717);
  std::uniform_real_distribution<double> u(-1, 1);
  Comparison trapez, step;
  for (int i = 0; i < 200000; ++i) {
    const Limits lim = random_limits(rng);
    const MotionState s{0.02 * u(rng), 0, 0, 0};
    const double target = 0.02 * u(rng);
    trapez.add(s, target, lim, SlopeType::trapez);
    if (i % 4 == 0) step.add(s, target, lim, SlopeType::step);
  }
  trapez.require();
  step.require();
}

TEST_CASE("KRN-3 profile, issue 17: closed form on the a_max and v_max edges, to a few ulp", "[ipo]") {
  std::mt19937_64 rng(1718);
  std::uniform_real_distribution<double> u(-1, 1);
  Comparison edges;
  for (int i = 0; i < 10000; ++i) {
    const Limits lim = random_limits(rng);
    const double p0 = 0.02 * u(rng), dir = u(rng) < 0 ? -1 : 1;
    for (double edge : {a_max_edge(lim), v_max_edge(lim)}) {
      if (edge > v_max_edge(lim)) continue;  // v_max before a_max: no a edge
      double below = edge, above = edge;
      edges.add({p0, 0, 0, 0}, p0 + dir * edge, lim, SlopeType::trapez);
      for (int ulp = 0; ulp < 4; ++ulp) {
        below = std::nextafter(below, 0.0);
        above = std::nextafter(above, 2 * edge);
        edges.add({p0, 0, 0, 0}, p0 + dir * below, lim, SlopeType::trapez);
        edges.add({p0, 0, 0, 0}, p0 + dir * above, lim, SlopeType::trapez);
      }
      for (double factor : {1 - 1e-12, 1 + 1e-12, 1 - 1e-9, 1 + 1e-9, 1 - 1e-6, 1 + 1e-6})
        edges.add({p0, 0, 0, 0}, p0 + dir * edge * factor, lim, SlopeType::trapez);
    }
    const double step_edge = lim.v * lim.v / lim.a;  // STEP: v_max just reached
    for (double factor : {1.0, 1 - 1e-15, 1 + 1e-15, 1 - 1e-9, 1 + 1e-9})
      edges.add({p0, 0, 0, 0}, p0 + dir * step_edge * factor, lim, SlopeType::step);
  }
  edges.require();
  CHECK(edges.cases > 250000);
}

TEST_CASE("KRN-3 profile, issue 17: the phase-bracketed search gives the reference durations from any state",
          "[ipo]") {
  std::mt19937_64 rng(1719);
  std::uniform_real_distribution<double> u(-1, 1);
  Comparison comparison;
  for (int i = 0; i < 300000; ++i) {
    const Limits lim = random_limits(rng);
    const SlopeType slope = i % 3 == 0 ? SlopeType::trapez : i % 3 == 1 ? SlopeType::step : SlopeType::sin2;
    MotionState s{0.02 * u(rng), lim.v * u(rng), lim.a * u(rng), 0};
    if (i % 10 == 0) s.v = s.a = 0;  // SIN2 from rest goes through the search too
    if (std::abs(velocity_after_ramp_to_zero(s.v, s.a, lim, slope)) > lim.v) continue;
    comparison.add(s, 0.02 * u(rng), lim, slope);
  }
  comparison.require();
}

TEST_CASE("KRN-3 profile, issue 17: forward to a block end, fast and reference switch agree", "[ipo]") {
  std::mt19937_64 rng(1720);
  std::uniform_real_distribution<double> u(0, 1);
  long cases = 0, failures = 0;
  double worst = 0;
  std::ostringstream first;
  first.precision(17);
  for (int i = 0; i < 100000; ++i) {
    const Limits lim = random_limits(rng);
    const SlopeType slope = i % 3 == 0 ? SlopeType::trapez : i % 3 == 1 ? SlopeType::step : SlopeType::sin2;
    const MotionState s = i % 5 == 0 ? MotionState{} : MotionState{0, lim.v * u(rng), lim.a * (2 * u(rng) - 1), 0};
    const double v_natural = velocity_after_ramp_to_zero(s.v, s.a, lim, slope);
    if (v_natural < 0 || v_natural > lim.v) continue;
    const double target = 0.05 * u(rng), v_end = i % 4 == 0 ? 0.0 : lim.v * u(rng);
    ++cases;
    const MotionProfile fast = block_profile(s, target, v_end, lim, slope).profile;
    const MotionProfile reference = block_profile(s, target, v_end, lim, slope, SwitchSearch::reference).profile;
    const double T = reference.duration(), difference = std::abs(fast.duration() - T);
    if (T > 0) worst = std::max(worst, difference / T);
    // Where one ulp of the switch instant moves the end by more than
    // round-off (next to a kink of the overshoot, the arrival's plateau
    // appearing: slope 1343 m/s at TRAPEZ v0=0.13648388593732044
    // a0=-0.48146045809868948 pf=0.045357885793232355 v_end=0.17421845839510733
    // lim 0.1939155735217106 1.5951845581093549 4.6858575477030122, 3.5e-14
    // m either side, and T 4e-13 s apart), both searches end on adjacent
    // doubles and either may take the other one: then the fast one's end
    // must be no further from the target than the reference's, within that.
    const double miss_fast = std::abs(fast.end().p - target), miss_reference = std::abs(reference.end().p - target);
    const bool same_switch = difference <= 1e-12 * T + 1e-15 && std::abs(fast.end().p - reference.end().p) <= 1e-12;
    const bool adjacent_switch = miss_fast <= 1.5 * miss_reference && miss_fast <= 1e-12;
    const bool ok = (same_switch || adjacent_switch) && std::abs(fast.end().v - reference.end().v) <= 1e-9 * lim.v;
    if (!ok && ++failures <= 5)
      first << to_string(slope) << " v0=" << s.v << " a0=" << s.a << " pf=" << target << " v_end=" << v_end
            << " lim " << lim.v << ' ' << lim.a << ' ' << lim.j << ": T fast " << fast.duration() << " reference "
            << T << ", end p " << fast.end().p << " / " << reference.end().p << '\n';
  }
  INFO(cases << " cases, " << failures << " failed, worst relative duration difference " << worst << ":\n"
             << first.str());
  CHECK(cases > 50000);
  REQUIRE(failures == 0);
}
