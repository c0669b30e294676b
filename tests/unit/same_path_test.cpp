// RIG-5 DPS-3: `same_path` compares two runs' commanded paths over
// dist_prog_start (logger/same_path.hpp), here on synthetic traces.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "same_path.hpp"

using namespace hil::logger;

namespace {

// A line along X (10 mm), then a quarter circle of radius 10 to (20, 10).
std::pair<double, double> line_and_arc(double s) {
  if (s <= 10) return {s, 0};
  const double phi = (s - 10) / 10;  // from the circle's bottom, centre (10, 10)
  return {10 + 10 * std::sin(phi), 10 - 10 * std::cos(phi)};
}
const double path_length = 10 + 10 * M_PI / 2;

// A run along the path: `step(cycle)` is the path covered in that cycle (0:
// it stands); dist_prog_start in whole 0.1 µm as the HLI has it.
PathTrace run(const std::function<double(int64_t)>& step, double end = path_length) {
  PathTrace t;
  t.axes = {"X", "Y"};
  t.modulo_range = {0, 0};
  t.position.resize(2);
  double s = 0;
  for (int64_t c = 0;; ++c) {
    const auto [x, y] = line_and_arc(s);
    t.cycle.push_back(c);
    t.dist_mm.push_back(std::round(s * 1e4) / 1e4);
    t.position[0].push_back(x);
    t.position[1].push_back(y);
    if (s >= end) break;
    s = std::min(end, s + step(c));
  }
  for (int i = 0; i < 20; ++i) {  // after program end
    t.cycle.push_back(t.cycle.back() + 1);
    t.dist_mm.push_back(t.dist_mm.back());
    t.position[0].push_back(t.position[0].back());
    t.position[1].push_back(t.position[1].back());
  }
  return t;
}

const PathTrace reference = run([](int64_t) { return 0.05; });

// Slower, a hold (50 cycles standing) at cycle 300, then faster: another sampling of the same path.
PathTrace held() {
  return run([](int64_t c) { return c < 300 ? 0.031 : c < 350 ? 0.0 : 0.077; });
}

}  // namespace

TEST_CASE("RIG-5 DPS-3 same_path: one path sampled at other velocities and with a hold is the same path",
          "[same_path][RIG-5][DPS-3]") {
  const SamePathResult r = compare_same_path(reference, held(), 0, 0.001);
  CHECK(r.holds);
  CHECK(r.failures.empty());
  CHECK(r.compared > 500);
  CHECK(r.skipped == 0);
  REQUIRE(r.worst);
  CHECK(std::abs(r.worst->difference_mm) < 0.0002);  // chord sag 0.05^2 / 80 and the 0.1 µm distances
  CHECK(r.variant_end_mm == Approx(path_length).margin(1e-4));
  CHECK_THAT(describe(r), Catch::Contains("samples compared, 0 skipped, worst difference"));
  // And the other way round.
  CHECK(compare_same_path(held(), reference, 0, 0.001).holds);
}

TEST_CASE("RIG-5 DPS-3 same_path: a 2 µm offset fails and names the worst sample", "[same_path][RIG-5][DPS-3]") {
  PathTrace off = held();
  for (size_t i = 0; i < off.dist_mm.size(); ++i)
    if (off.dist_mm[i] > 12) off.position[1][i] += 0.002;
  SamePathResult r = compare_same_path(reference, off, 0, 0.001);
  CHECK_FALSE(r.holds);
  REQUIRE(r.worst);
  CHECK(r.worst->axis == "Y");
  CHECK(r.worst->dist_mm > 12);
  CHECK(std::abs(r.worst->difference_mm) == Approx(0.002).margin(0.0002));
  CHECK_THAT(describe(r), Catch::Contains("differs by more than 1.000 µm") && Catch::Contains("Y: "));
  // Before the offset the paths agree: compared from 12.5 mm on it fails, up to 12 mm not at all.
  CHECK_FALSE(compare_same_path(reference, off, 12.5, 0.001).holds);
  CHECK(compare_same_path(reference, off, 0, 0.003).holds);  // within a tolerance of 3 µm
}

TEST_CASE("RIG-5 DPS-3 same_path: from_dist_mm leaves out the samples up to it", "[same_path][RIG-5][DPS-3]") {
  PathTrace other_start = held();
  for (size_t i = 0; i < other_start.dist_mm.size(); ++i)
    if (other_start.dist_mm[i] <= 5) other_start.position[0][i] -= 1;  // another start position, the first block
  CHECK_FALSE(compare_same_path(reference, other_start, 0, 0.001).holds);
  const SamePathResult r = compare_same_path(reference, other_start, 5, 0.001);
  CHECK(r.holds);
  CHECK(r.compared < compare_same_path(reference, held(), 0, 0.001).compared);
}

TEST_CASE("RIG-5 DPS-3 same_path: where the reference's distance stands while an axis moves, the sample is skipped",
          "[same_path][RIG-5][DPS-3]") {
  // X to 5 counted, X 5 -> 6 not counted (#DISTANCE PROG START OFF), X 6 -> 11 counted.
  auto with_plateau = [](double step) {
    PathTrace t;
    t.axes = {"X"};
    t.modulo_range = {0};
    t.position.resize(1);
    int64_t c = 0;
    auto add = [&](double d, double x) {
      t.cycle.push_back(c++);
      t.dist_mm.push_back(std::round(d * 1e4) / 1e4);
      t.position[0].push_back(x);
    };
    for (double x = 0; x < 5; x += step) add(x, x);
    for (double x = 5; x < 6; x += step) add(5, x);
    for (double x = 6; x <= 11 + 1e-9; x += step) add(x - 1, x);
    add(10, 11);
    return t;
  };
  const SamePathResult r = compare_same_path(with_plateau(0.1), with_plateau(0.07), 0, 0.001);
  CHECK(r.holds);
  CHECK(r.skipped > 10);  // the variant's own samples at 5 mm while it moved 5 -> 6
  CHECK(r.compared > 100);
  CHECK_THAT(describe(r), Catch::Contains(std::to_string(r.skipped) + " skipped"));
}

TEST_CASE("RIG-5 DPS-3 same_path: a variant that stops short of the reference's end fails",
          "[same_path][RIG-5][DPS-3]") {
  const PathTrace truncated = run([](int64_t) { return 0.04; }, 20);
  const SamePathResult r = compare_same_path(reference, truncated, 0, 0.001);
  CHECK_FALSE(r.holds);
  CHECK(r.compared > 100);
  CHECK(std::abs(r.worst->difference_mm) < 0.001);
  CHECK_THAT(describe(r), Catch::Contains("did not run to the end"));
  // The reference ends first: the variant's samples beyond its end fail it too.
  CHECK_FALSE(compare_same_path(truncated, reference, 0, 0.001).holds);
}

TEST_CASE("RIG-5 DPS-3 same_path: no sample compared fails", "[same_path][RIG-5][DPS-3]") {
  const SamePathResult r = compare_same_path(reference, held(), path_length + 1, 0.001);
  CHECK_FALSE(r.holds);
  CHECK(r.compared == 0);
  CHECK_THAT(describe(r), Catch::Contains("no sample was compared"));
}

TEST_CASE("RIG-5 DPS-3 same_path: a modulo axis compares modulo its range", "[same_path][RIG-5][DPS-3]") {
  PathTrace a, b;
  for (PathTrace* t : {&a, &b}) {
    t->axes = {"C"};
    t->modulo_range = {360};
    t->position.resize(1);
    t->cycle = {0, 1, 2};
    t->dist_mm = {0, 1, 2};
  }
  a.position[0] = {359.0, 359.9995, 0.9};
  b.position[0] = {-1.0, 0.0003, 360.9};
  CHECK(compare_same_path(a, b, 0, 0.001).holds);
  b.position[0][1] = 0.01;
  CHECK_FALSE(compare_same_path(a, b, 0, 0.001).holds);
}
