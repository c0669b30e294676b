// What the interpolator hands the look-ahead (issue 35): one MotionPiece
// for lines, arcs and spans of contouring curves, split where an insert
// stop mark lies (ISC-3), and the stop on its two scales (PathStop).
#include <catch2/catch.hpp>

#include <cmath>

#include "contour_builder.hpp"
#include "look_ahead.hpp"
#include "motion_piece.hpp"
#include "path_stop.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

Motion line(std::vector<double> start, std::vector<double> end) {
  Motion m;
  m.start = std::move(start);
  m.end = std::move(end);
  m.feed = 50;
  return m;
}

MotionPiece piece_of(const Motion& motion, double covered) {
  MotionPiece piece;
  piece.block = 3;
  piece.motion = motion;
  piece.covered = covered;
  piece.origin = 0;
  piece.out = Corner{BlockTransition::contour, {}, {}};
  piece.whole_block = piece.block_stop = true;
  return piece;
}

// The contouring curve G261 puts between X10 and Y10 from (0, 0).
std::shared_ptr<const ContourJoint> corner_curve(const MachineConfig& machine) {
  ContourBuilder builder(machine);
  MotionPiece a = piece_of(line({0, 0, 0}, {10, 0, 0}), 10), b = piece_of(line({10, 0, 0}, {10, 10, 0}), 10);
  a.block = 0;
  b.block = 1;
  b.out = Corner{};
  builder.add(a, a.segment(machine), false);
  for (PathPiece& p : builder.add(b, b.segment(machine), false))
    if (p.segment.is_contour_curve()) return p.segment.joint();
  return nullptr;
}

}  // namespace

TEST_CASE("ISC-3 a piece of a line splits where the stop lies: the first ends as programmed, the second is no block stop",
          "[path][isc]") {
  const MachineConfig machine = test::xyz_machine();
  const MotionPiece whole = piece_of(line({0, 0, 0}, {10, 0, 0}), 10);
  const PathSegment segment = whole.segment(machine);
  REQUIRE(whole.length_at(4, segment) == Approx(4));
  const auto [first, second] = whole.split_at(4, segment, 1.0);
  CHECK(first.motion.end[0] == Approx(4));
  CHECK(second.motion.start[0] == Approx(4));
  CHECK(second.motion.end[0] == 10);
  CHECK(first.covered + second.covered == Approx(10));
  CHECK(second.origin == Approx(4));
  // The corner at the mark is not contoured: the path stands on it.
  REQUIRE(first.out);
  CHECK(first.out->transition == BlockTransition::standard);
  CHECK(second.out->transition == BlockTransition::contour);
  CHECK(first.block_stop);
  CHECK_FALSE(second.block_stop);
  CHECK_FALSE(first.whole_block);
  CHECK_FALSE(second.whole_block);
  // The two are one motion again (a restart joins them, fuzz seed 12010265).
  CHECK(first.continued_by(second));
  CHECK_FALSE(second.continued_by(first));
}

TEST_CASE("ISC-3 DPS-1 backward, the second half begins where the first ends in the block's programmed distance",
          "[path][isc]") {
  const MachineConfig machine = test::xyz_machine();
  MotionPiece whole = piece_of(line({10, 0, 0}, {0, 0, 0}), 10);
  whole.origin = 10;  // backward: from the block's end
  const auto [first, second] = whole.split_at(2.5, whole.segment(machine), -1.0);
  CHECK(first.motion.end[0] == Approx(7.5));
  CHECK(second.origin == Approx(7.5));
}

TEST_CASE("ISC-3 KRN-6 a span of a contouring curve splits on the curve, each half covering its share", "[path][isc]") {
  const MachineConfig machine = test::xyz_machine();
  const std::shared_ptr<const ContourJoint> joint = corner_curve(machine);
  REQUIRE(joint);
  for (const bool reversed : {false, true}) {
    const CurveSpan span{joint, 0, joint->parts[0].end, reversed};
    const std::optional<MotionPiece> piece = MotionPiece::on_curve(Block{}, 0, span, machine);
    REQUIRE(piece);
    CHECK_FALSE(piece->along_chord);
    CHECK_FALSE(piece->out);
    const PathSegment segment = piece->segment(machine);
    CHECK(segment.is_contour_curve());
    CHECK(piece->covered == Approx(joint->covered(0, joint->parts[0].end)));
    const double s = segment.length() / 3;
    const auto [first, second] = piece->split_at(s, segment, 1.0);
    REQUIRE(first.curve);
    REQUIRE(second.curve);
    const double at = reversed ? joint->parts[0].end - s : s;
    CHECK((reversed ? first.curve->from : first.curve->to) == Approx(at));
    CHECK((reversed ? second.curve->to : second.curve->from) == Approx(at));
    CHECK(first.covered + second.covered == Approx(piece->covered));
    const std::vector<double> point = joint->curve->position(at);
    for (size_t i = 0; i < point.size(); ++i) {
      CHECK(first.motion.end[i] == Approx(point[i]).margin(1e-12));
      CHECK(second.motion.start[i] == Approx(point[i]).margin(1e-12));
    }
    CHECK_FALSE(first.continued_by(second));  // on a curve: not joined
  }
  // A span of 5 nm is its chord, and so is one of 0.5 nm (fuzz AH: dropped,
  // the path jumped); one within the coordinates' round-off is none.
  const double mid = joint->curve->length() / 2;
  for (const double length : {5e-6, 5e-10}) {
    const std::optional<MotionPiece> tiny = MotionPiece::on_curve(Block{}, 0, {joint, mid, mid + length, false}, machine);
    REQUIRE(tiny);
    CHECK(tiny->along_chord);
  }
  CHECK_FALSE(MotionPiece::on_curve(Block{}, 0, {joint, mid, std::nextafter(mid, 1e9), false}, machine));
}

TEST_CASE("ISC-3 a stop asked while standing is on the covered scale until placed, then on path length", "[path][isc]") {
  PathStop stop;
  stop.ask_covered(100, 7);
  REQUIRE(stop.unplaced());
  CHECK(*stop.unplaced() == 107);
  CHECK_FALSE(stop.at());
  stop.place(55, {1, 2, 3}, 106.5);
  CHECK_FALSE(stop.unplaced());
  CHECK(*stop.at() == 55);
  REQUIRE(stop.placed());
  CHECK(stop.placed()->covered == 6.5);  // less: moved to the end of what there is
  stop.not_before(60);  // the path cannot brake before 60
  CHECK(*stop.at() == 60);
  // A stop asked while moving takes the place of any asked before.
  stop.ask_covered(0, 5);
  stop.ask_at_length(80);
  CHECK_FALSE(stop.unplaced());
  CHECK_FALSE(stop.placed());
  CHECK(*stop.at() == 80);
  stop.release();
  CHECK_FALSE(stop.at());
}

TEST_CASE("KRN-6 LIFT-2 LIFT-3 a contouring curve's halves keep the caps of their blocks' pieces", "[path][lift]") {
  const MachineConfig machine = test::xyz_machine();
  // The limits of the curve's halves, the block before the corner capped or not.
  auto halves = [&](const Limits& caps) {
    MotionPiece a = piece_of(line({0, 0, 0}, {10, 0, 0}), 10), b = piece_of(line({10, 0, 0}, {10, 10, 0}), 10);
    a.block = 0;
    b.block = 1;
    b.out = Corner{};
    a.motion.path_caps = caps;
    ContourBuilder builder(machine);
    CHECK(builder.add(a, a.segment(machine), false).empty());  // waits for its successor
    std::vector<Limits> limits;
    for (const PathPiece& p : builder.add(b, b.segment(machine), false))
      if (p.segment.is_contour_curve()) limits.push_back(p.segment.limits());
    REQUIRE(limits.size() == 2);
    return limits;
  };
  const std::vector<Limits> free = halves(Limits::none());
  const Limits caps{free[0].v / 2, free[0].a / 2, free[0].j / 2};  // a lift range's, on the block before
  const std::vector<Limits> capped_halves = halves(caps);
  // v counts covered distance per second there, of which the curve covers more than its length.
  CHECK(capped_halves[0].v <= caps.v);
  CHECK(capped_halves[0].a == caps.a);
  CHECK(capped_halves[0].j == caps.j);
  // The block after the corner has none: its half is as it was.
  CHECK(capped_halves[1].v == free[1].v);
  CHECK(capped_halves[1].a == free[1].a);
  CHECK(capped_halves[1].j == free[1].j);
}

TEST_CASE("KRN-6 DDTG-2 the look-ahead contours a piece that says how the path leaves it, and takes one without as it is",
          "[path][look_ahead]") {
  const MachineConfig machine = test::xyz_machine();
  for (const bool contoured : {true, false}) {
    MotionPiece a = piece_of(line({0, 0, 0}, {10, 0, 0}), 10), b = piece_of(line({10, 0, 0}, {10, 10, 0}), 10);
    a.block = 0;
    b.block = 1;
    if (!contoured) a.out.reset();  // a short cut (DDTG-2)
    LookAhead look_ahead(machine);
    look_ahead.push(a);
    look_ahead.push(b);
    look_ahead.flush();
    bool curve = false;
    double covered = 0;
    for (; !look_ahead.empty(); look_ahead.pop_front()) {
      curve = curve || look_ahead.front().segment.is_contour_curve();
      covered += look_ahead.front().segment.covered_distance();
    }
    CHECK(curve == contoured);
    CHECK(covered == Approx(20));  // DPS-1: the programmed lengths, contoured or not
  }
}

TEST_CASE("KRN-6 issue 36 item 4: a lone corner's curve takes all of PATH_DEV where that costs less time; one another "
          "curve may meet takes half",
          "[path][contour]") {
  const MachineConfig machine = test::xyz_machine();
  // The curve at a corner of `degrees` after a 20 mm line into a line of `after` mm, and where it passes the corner.
  struct Made {
    std::shared_ptr<const ContourJoint> joint;
    double from_corner = 0;
  };
  auto curve_at = [&](double degrees, double after) {
    const double th = degrees * M_PI / 180;
    const std::vector<double> corner{20, 0, 0}, end{20 + after * std::cos(th), after * std::sin(th), 0};
    MotionPiece a = piece_of(line({0, 0, 0}, corner), 20), b = piece_of(line(corner, end), after);
    a.block = 0;
    b.block = 1;
    b.out = Corner{};
    a.motion.feed = b.motion.feed = 100;
    ContourBuilder builder(machine);
    builder.add(a, a.segment(machine), false);
    Made made;
    for (PathPiece& p : builder.add(b, b.segment(machine), false))
      if (p.segment.is_contour_curve()) made.joint = p.segment.joint();
    if (made.joint) made.from_corner = made.joint->curve->distance_to(corner);
    return made;
  };
  const double path_dev = ContourMode{}.path_dev;
  // 10°: the turn in all of PATH_DEV, passed faster than the curve it
  // replaces (contour_bench --only corners: 19.9 mm/s against 9.9).
  const Made lone = curve_at(10, 20);
  REQUIRE(lone.joint);
  CHECK(lone.joint->lone_corner);
  CHECK(lone.from_corner > 0.9 * path_dev);
  CHECK(lone.from_corner <= path_dev);
  // The same corner into a block the next curve may take half of: half.
  const Made shared = curve_at(10, 0.3);
  REQUIRE(shared.joint);
  CHECK_FALSE(shared.joint->lone_corner);
  CHECK(shared.from_corner <= path_dev / 2);
  CHECK(shared.from_corner > 0.45 * path_dev);
  // 150°: any curve is slow there; the turn in half of PATH_DEV costs less
  // time than the one in all of it (contour_bench --only corners: 0.612 s
  // against 0.617) and than the shared curve.
  const Made wide = curve_at(150, 20);
  REQUIRE(wide.joint);
  CHECK(wide.joint->lone_corner);
  CHECK(wide.joint->curve->shape() == ContourCurve::Shape::turn);
  CHECK(wide.from_corner <= path_dev / 2);
  CHECK(wide.from_corner > 0.45 * path_dev);
  // The lone curve's limits give the curvature more of the jerk: its
  // velocity limit is above the shared curve's of the same corner.
  PathSegment lone_half(lone.joint, 0, lone.joint->parts[0].end, false, machine);
  PathSegment shared_half(shared.joint, 0, shared.joint->parts[0].end, false, machine);
  CHECK(lone_half.limits().v > 1.5 * shared_half.limits().v);
}
