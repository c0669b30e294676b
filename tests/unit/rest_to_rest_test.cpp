// KRN-3: the time-optimal jerk-limited rest-to-rest profile (TRAPEZ).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "rest_to_rest.hpp"

using namespace hil::cnc;

namespace {

// Ends at rest on the target and never exceeds a limit (sampled densely).
void check_profile(double distance, const Limits& lim) {
  const JerkProfile p = rest_to_rest(distance, lim);
  const MotionState end = p.at(p.duration());
  CHECK(end.p == Approx(distance).margin(1e-9));
  CHECK(std::abs(end.v) <= 1e-9 * lim.v);
  CHECK(std::abs(end.a) <= 1e-9 * lim.a);
  for (const JerkSegment& seg : p.segments()) {
    CHECK(seg.duration >= 0);
    CHECK(std::abs(seg.jerk) <= lim.j * (1 + 1e-12));
  }
  const int n = 2000;
  double previous = 0;
  for (int i = 0; i <= n; ++i) {
    const MotionState s = p.at(p.duration() * i / n);
    CHECK(s.v <= lim.v * (1 + 1e-9));
    CHECK(s.v >= -1e-9 * lim.v);
    CHECK(std::abs(s.a) <= lim.a * (1 + 1e-9));
    CHECK(s.p >= previous - 1e-12);  // never moves backwards
    previous = s.p;
  }
}

}  // namespace

TEST_CASE("KRN-3 rest-to-rest: durations match the closed form in all three cases", "[ipo]") {
  const Limits lim{100, 1000, 20000};  // a/j = 0.05 s, a^2/j = 50 mm/s
  SECTION("velocity and acceleration limits reached") {
    // T = L/v + v/a + a/j
    const double L = 50;
    CHECK(rest_to_rest(L, lim).duration() == Approx(L / 100 + 100.0 / 1000 + 1000.0 / 20000));
  }
  SECTION("acceleration reached, velocity not") {
    // v_p from v^2 + v a^2/j - a L = 0; T = 2 (v_p/a + a/j)
    const double L = 10;
    const double vp = (-50 + std::sqrt(50.0 * 50 + 4 * 1000 * L)) / 2;
    REQUIRE(vp < 100);
    REQUIRE(vp > 50);
    CHECK(rest_to_rest(L, lim).duration() == Approx(2 * (vp / 1000 + 1000.0 / 20000)));
  }
  SECTION("neither limit reached") {
    // T = 4 (L / 2j)^(1/3)
    const double L = 0.5;
    CHECK(rest_to_rest(L, lim).duration() == Approx(4 * std::cbrt(L / (2 * 20000))));
  }
  SECTION("velocity reached without reaching acceleration") {
    const Limits low_v{20, 1000, 20000};  // v < a^2/j: T = L/v + 2 sqrt(v/j)
    const double L = 10;
    CHECK(rest_to_rest(L, low_v).duration() == Approx(L / 20 + 2 * std::sqrt(20.0 / 20000)));
  }
}

TEST_CASE("KRN-3 rest-to-rest: boundary distances where the profile type changes", "[ipo]") {
  const Limits lim{100, 1000, 20000};
  // a_max just reached: L = 2 a^3/j^2; v_max just reached: L = v (v/a + a/j).
  const double a_edge = 2 * std::pow(1000.0, 3) / (20000.0 * 20000.0);
  const double v_edge = 100 * (100.0 / 1000 + 1000.0 / 20000);
  for (double edge : {a_edge, v_edge})
    for (double factor : {1 - 1e-12, 1.0, 1 + 1e-12, 1 - 1e-6, 1 + 1e-6}) check_profile(edge * factor, lim);
  CHECK(rest_to_rest(0, lim).duration() == 0);
}

TEST_CASE("KRN-3 rest-to-rest: random distances and limits", "[ipo]") {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> log_uniform(-4, 3);
  for (int i = 0; i < 300; ++i) {
    const double L = std::pow(10.0, log_uniform(rng));
    const Limits lim{std::pow(10.0, log_uniform(rng) / 2 + 1), std::pow(10.0, log_uniform(rng) / 2 + 3),
                     std::pow(10.0, log_uniform(rng) / 2 + 4.5)};
    INFO("L=" << L << " v=" << lim.v << " a=" << lim.a << " j=" << lim.j);
    check_profile(L, lim);
  }
}
