// The way on or back along a block from where the path stands (KRN-5,
// DDTG-6): cnc/path/motion_parts.
#include <catch2/catch.hpp>

#include <cmath>

#include "motion_parts.hpp"
#include "path_segment.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

Motion line(std::vector<double> start, std::vector<double> end, MotionType type = MotionType::linear) {
  Motion m;
  m.type = type;
  m.start = std::move(start);
  m.end = std::move(end);
  m.feed = type == MotionType::rapid ? 0 : 50;
  return m;
}

// A G03 quarter circle around (0, 0) from (10, 0) to (0, 10).
Motion quarter_circle() {
  Motion m = line({10, 0, 0}, {0, 10, 0}, MotionType::arc_ccw);
  m.center[0] = m.center[1] = 0;
  return m;
}

}  // namespace

TEST_CASE("KRN-5 rest_of_motion: the block's own part from a point on it", "[path][backward]") {
  const MachineConfig machine = test::xyz_machine();
  const auto on = rest_of_motion(line({0, 0, 0}, {10, 0, 0}), {4, 0, 0}, false, machine);
  REQUIRE(on);
  CHECK(on->start == std::vector<double>{4, 0, 0});
  CHECK(on->end == std::vector<double>{10, 0, 0});
  const auto back = rest_of_motion(line({0, 0, 0}, {10, 0, 0}), {4, 0, 0}, true, machine);
  REQUIRE(back);
  CHECK(back->start == std::vector<double>{4, 0, 0});
  CHECK(back->end == std::vector<double>{0, 0, 0});
  const double r = 10 / std::sqrt(2.0);
  const auto arc = rest_of_motion(quarter_circle(), {r, r, 0}, false, machine);
  REQUIRE(arc);
  CHECK(arc->type == MotionType::arc_ccw);  // still the arc, from the point on it
  const auto arc_back = rest_of_motion(quarter_circle(), {r, r, 0}, true, machine);
  REQUIRE(arc_back);
  CHECK(arc_back->type == MotionType::arc_cw);  // reversed
  CHECK(arc_back->end == std::vector<double>{10, 0, 0});
  CHECK_FALSE(rest_of_motion(line({0, 0, 0}, {10, 0, 0}), {10, 0, 0}, false, machine));  // nothing left
}

TEST_CASE("KRN-5 DDTG-6 rest_of_motion: a straight line from a point off the block or under 10 nm from its end",
          "[path][backward]") {
  const MachineConfig machine = test::xyz_machine();
  // Off the arc (where a short cut ended midway): not an arc from off its circle.
  const auto off = rest_of_motion(quarter_circle(), {3, 4, 0}, false, machine);
  REQUIRE(off);
  CHECK(off->type == MotionType::linear);
  CHECK(off->start == std::vector<double>{3, 4, 0});
  CHECK(off->end == std::vector<double>{0, 10, 0});
  // 4 nm before the arc's end: a line, not the arc's full circle.
  const double a = std::atan2(1.0, 0.0) - 4e-7;  // 4e-6 mm on R 10
  const auto tiny = rest_of_motion(quarter_circle(), {10 * std::cos(a), 10 * std::sin(a), 0}, false, machine);
  REQUIRE(tiny);
  CHECK(tiny->type == MotionType::linear);
  CHECK(std::hypot(tiny->end[0] - tiny->start[0], tiny->end[1] - tiny->start[1]) < 1e-5);
  // A G00 block stays G00 (no F may be programmed at all).
  const auto rapid = rest_of_motion(line({0, 0, 0}, {10, 0, 0}, MotionType::rapid), {4, 1, 0}, false, machine);
  REQUIRE(rapid);
  CHECK(rapid->type == MotionType::rapid);
}

TEST_CASE("KRN-5 rest_of_motion: on a full circle its start is its end, the hint tells which", "[path][backward]") {
  const MachineConfig machine = test::xyz_machine();
  Motion circle = line({10, 0, 0}, {10, 0, 0}, MotionType::arc_ccw);
  circle.center[0] = circle.center[1] = 0;
  const auto from_start = rest_of_motion(circle, {10, 0, 0}, false, machine, false);
  REQUIRE(from_start);  // the whole circle ahead
  CHECK(from_start->type == MotionType::arc_ccw);
  CHECK_FALSE(rest_of_motion(circle, {10, 0, 0}, false, machine, true));  // at its end: nothing left
}

TEST_CASE("KRN-5 rest_of_motion: a point on an arc whose end radius is off its start radius lies on the arc",
          "[path][backward]") {
  // W (docs/FUZZ.md, arcs seed 15000914): the decoder accepts an end radius
  // a little off the start radius and the arc blends it (a spiral). A part
  // of it up to a point blends to that point's radius, so its own length is
  // not the whole arc's path length there: the point looked off the arc and
  // the rest became a straight line.
  const MachineConfig machine = test::xyz_machine();
  Motion spiral = line({15, 0, 0}, {0, -15.0015, 0}, MotionType::arc_ccw);  // 270 degrees
  spiral.center[0] = spiral.center[1] = 0;
  const PathSegment whole(spiral, machine);
  for (double share : {0.1, 0.5, 0.9}) {
    const std::vector<double> point = whole.position(share * whole.length());
    CHECK(whole.length_to(point) == Approx(share * whole.length()).epsilon(1e-12));
    const auto ahead = rest_of_motion(spiral, point, false, machine);
    REQUIRE(ahead);
    CHECK(ahead->type == MotionType::arc_ccw);
    const auto back = rest_of_motion(spiral, point, true, machine);
    REQUIRE(back);
    CHECK(back->type == MotionType::arc_cw);
    // Both parts run on the whole arc's path: their midpoints lie on it.
    const PathSegment rest(*ahead, machine);
    const std::vector<double> middle = rest.position(rest.length() / 2);
    const std::vector<double> on_whole = whole.position(whole.length_to(middle));
    CHECK(std::hypot(middle[0] - on_whole[0], middle[1] - on_whole[1]) < 1e-6);
  }
}
