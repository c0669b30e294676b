// KRN-6 polynomial contouring (G261/G260/G61, #CONTOUR MODE), exact stop
// (G60/G360/G359), and KRN-3's rule for tangent transitions with a
// curvature step; the look-ahead over polylines of short chords.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "contour_builder.hpp"
#include "contour_curve.hpp"
#include "corner_rule.hpp"
#include "decoder.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;
using hil::test::run_program;

namespace {

DecodedProgram decode_text(const std::string& text) {
  const MachineConfig m = test::xyz_machine();
  return decode_program(text, m, std::vector<double>(3, 0.0));
}

// A circle of `chords` G01 chords of `chord` mm from (R, 0), counter-clockwise.
std::string chord_circle(int chords, double radius, double chord, const std::string& head) {
  const double step = 2 * std::asin(chord / (2 * radius));
  std::string program = "N1 G90 G00 X" + std::to_string(radius) + " Y0 Z0\n" + head;
  char line[120];
  for (int c = 1; c <= chords; ++c) {
    std::snprintf(line, sizeof line, "%sX%.9f Y%.9f%s\n", c == 1 ? "G01 " : "", radius * std::cos(c * step),
                  radius * std::sin(c * step), c == 1 ? " F6000" : "");
    program += line;
  }
  return program + "M30\n";
}

struct Run {
  int64_t moving_cycles = 0;
  double max_deviation = 0;  // from the chord polyline
  logger::CheckReport check;
  std::vector<double> dps_at_block_change;  // dist_prog_start (mm) whenever block_nr_r changed
};

Run run_circle(const std::string& program, double radius, double chord, int64_t first_chord_line) {
  const MachineConfig m = test::xyz_machine();
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  Run r;
  const double step = 2 * std::asin(chord / (2 * radius));
  const double half_step = step / 2;
  test::run_program(channel, &checker, [&](int64_t, const HliState& s, HliControl&) {
    const auto& sp = channel.setpoints();
    const double v = std::hypot(sp[0].velocity, sp[1].velocity);
    if (v > 0 && s.block_count_r >= first_chord_line) ++r.moving_cycles;
    // Distance from the polyline: the chord's line is at R cos(step/2) from
    // the centre, along the chord's middle direction.
    double angle = std::atan2(sp[1].position, sp[0].position);
    if (angle < 0) angle += 2 * M_PI;
    const double c = std::floor(angle / step);
    const double mid = (c + 0.5) * step;
    const double along = sp[0].position * std::cos(mid) + sp[1].position * std::sin(mid);
    if (s.channel_state == ChannelState::active && s.block_count_r >= first_chord_line)
      r.max_deviation = std::max(r.max_deviation, std::abs(along - radius * std::cos(half_step)));
  });
  r.check = checker.finish();
  return r;
}

}  // namespace

TEST_CASE("KRN-6 decoder: G61/G261/G260 and G60/G360/G359 set each block's transition", "[contour]") {
  const DecodedProgram p = decode_text(
      "N10 G01 X1 F600\n"
      "N20 X2 G61\n"
      "N30 X3\n"
      "N40 G261 X4\n"
      "N50 X5 G60\n"
      "N60 X6\n"
      "N70 G260 X7\n"
      "N80 G360 X8\n"
      "N90 G261 X9\n"
      "N100 G359 X10\n"
      "N110 G360 X11\n"
      "N120 G359 X12\n");
  REQUIRE_FALSE(p.error);
  using T = BlockTransition;
  const std::vector<T> expected{T::standard, T::contour,    T::standard, T::contour, T::exact_stop, T::contour,
                                T::standard, T::exact_stop, T::contour,  T::contour, T::exact_stop, T::standard};
  REQUIRE(p.blocks.size() == expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    INFO("block " << i);
    CHECK(p.blocks[i].transition == expected[i]);
  }
}

TEST_CASE("KRN-6 decoder: two block transition G functions in one block are error 20117", "[contour]") {
  for (const char* line : {"N10 G01 X1 F600 G61 G60\n", "N10 G261 G260 X1 F600\n", "N10 G360 G261 X1 F600\n",
                           "N10 G61 G61 X1 F600\n"}) {
    const DecodedProgram p = decode_text(line);
    REQUIRE(p.error);
    CHECK(p.error->id == 20117);
    CHECK(p.error->nc_line == 1);
  }
}

TEST_CASE("KRN-6 decoder: #CONTOUR MODE parameters, ON/OFF as G261/G260, other types refused by name",
          "[contour]") {
  const DecodedProgram p = decode_text(
      "N10 G01 X1 F600\n"
      "#CONTOUR MODE [DEV PATH_DEV=0.05]\n"
      "N20 X2\n"
      "#CONTOUR MODE ON [DIST DIST=0.2]\n"
      "N30 X3\n"
      "#CONTOUR MODE [DEV, PATH_DEV = 0.002]\n"
      "N40 X4\n"
      "#CONTOUR MODE OFF\n"
      "N50 X5\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 5);
  CHECK(p.blocks[1].transition == BlockTransition::standard);  // parameters alone do not switch it on
  CHECK(p.blocks[1].contour.path_dev == 0.05);
  CHECK(p.blocks[2].transition == BlockTransition::contour);
  CHECK(p.blocks[2].contour.type == ContourMode::Type::dist);
  CHECK(p.blocks[2].contour.dist == 0.2);
  CHECK(p.blocks[3].contour.type == ContourMode::Type::dev);
  CHECK(p.blocks[3].contour.path_dev == 0.002);
  CHECK(p.blocks[4].transition == BlockTransition::standard);
  for (const std::string bad : {"#CONTOUR MODE [PTP]", "#CONTOUR MODE [DIST_SOFT DIST=1]",
                                 "#CONTOUR MODE [DEV TRACK_DEV=0.1]", "#CONTOUR MODE [DEV PATH_DEV=0]",
                                 "#CONTOUR MODE [DEV PATH_DEV=-1]", "#CONTOUR MODE [DEV FOO=1]", "#CONTOUR MODE",
                                 "#CONTOUR MODE [DIST]", "#CONTOUR MODE [DEV DIST=1]"}) {
    INFO(bad);
    const DecodedProgram q = decode_text(bad + "\nN10 G01 X1 F600\n");
    REQUIRE(q.error);
    CHECK(q.error->nc_line == 1);
  }
  const DecodedProgram q = decode_text("#CONTOUR MODE [PTP]\n");
  CHECK_THAT(q.error->message, Catch::Contains("PTP"));
}

TEST_CASE("KRN-6 contouring curve: position, tangent and curvature of both ends", "[contour]") {
  const ContourCurve::End a{{0, 0, 0}, {1, 0, 0}, {0, 0.1, 0}};
  const double s = std::sqrt(0.5);
  const ContourCurve::End b{{2, 1, 0}, {s, s, 0}, {-0.05, 0.05, 0}};
  const ContourCurve c(a, b);
  for (size_t i = 0; i < 3; ++i) {
    CHECK(c.position(0)[i] == Approx(a.point[i]).margin(1e-12));
    CHECK(c.position(c.length())[i] == Approx(b.point[i]).margin(1e-12));
    CHECK(c.tangent(0)[i] == Approx(a.tangent[i]).margin(1e-12));
    CHECK(c.tangent(c.length())[i] == Approx(b.tangent[i]).margin(1e-12));
    CHECK(c.curvature(0)[i] == Approx(a.curvature[i]).margin(1e-9));
    CHECK(c.curvature(c.length())[i] == Approx(b.curvature[i]).margin(1e-9));
  }
  // Parametrised by path length: |dP/ds| = 1 between samples.
  for (int k = 0; k < 100; ++k) {
    const double s0 = c.length() * k / 100, s1 = c.length() * (k + 1) / 100;
    const auto p0 = c.position(s0), p1 = c.position(s1);
    CHECK(std::hypot(p1[0] - p0[0], p1[1] - p0[1]) == Approx(s1 - s0).epsilon(1e-4));
  }
}

TEST_CASE("KRN-6 corner distance: PATH_DEV is met at the programmed corner of two lines", "[contour]") {
  for (double angle_deg : {1.0, 30.0, 90.0, 135.0, 160.0}) {
    const double th = angle_deg * M_PI / 180;
    const std::vector<double> t1{1, 0, 0}, t2{std::cos(th), std::sin(th), 0};
    const double e = 0.01;
    const double d = ContourBuilder::dev_distance(e, t1, t2);
    const ContourCurve c({{-d, 0, 0}, t1, {0, 0, 0}}, {{d * t2[0], d * t2[1], 0}, t2, {0, 0, 0}});
    INFO("angle " << angle_deg);
    CHECK(c.distance_to({0, 0, 0}) == Approx(e).epsilon(1e-6));
  }
}

// The rule of corner_rule.hpp for the demo's N30 -> N40 (line along +X into
// a G03 arc of radius 20 mm): Y's curvature steps by dk = 1/20 = 0.05 1/mm,
// kappa = 0.05, j_Y = 40000 mm/s^3, T = 1 ms. By hand:
//   50 v^2 + 0.0025 v^3 + 12 v = 20000  ->  v = 19.86 mm/s
// (50 * 19.86^2 = 19721.0, 0.0025 * 19.86^3 = 19.6, 12 * 19.86 = 238.3:
// 19978.9; at 19.87: 19998.9; at 19.871: 20000.9).
TEST_CASE("KRN-3 curvature step: the demo's line into arc joint passes at the hand-computed 19.87 mm/s",
          "[contour]") {
  const MachineConfig m = test::xyz_machine();
  Motion line{MotionType::linear, {10, 10, -2}, {80, 10, -2}, {-1, -1}, {0, 0}, 50};
  Motion arc{MotionType::arc_ccw, {80, 10, -2}, {100, 30, -2}, {0, 1}, {80, 30}, 50};
  const Junction j = junction(PathSegment(line, m), PathSegment(arc, m), m);
  CHECK(j.curvature_step);
  CHECK(j.v_max == Approx(19.8705).margin(0.001));
  CHECK(50 * j.v_max * j.v_max + 0.0025 * std::pow(j.v_max, 3) + 12 * j.v_max == Approx(20000).epsilon(1e-9));
}

TEST_CASE("KRN-6 chord circle: 1000 chords of 0.1 mm at F6000 with G261 PATH_DEV=0.01 run at the feed",
          "[contour]") {
  const int chords = 1000;
  const Run r = run_circle(chord_circle(chords, 15.9, 0.1, "#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n"), 15.9, 0.1, 4);
  const double ideal_s = chords * 0.1 / 100.0;
  const double time_s = r.moving_cycles * 1e-3;
  INFO("time " << time_s << " s, ideal " << ideal_s << " s, deviation " << r.max_deviation);
  CHECK(r.check.violations.empty());
  CHECK(time_s <= 1.1 * ideal_s + 0.3);  // + accelerating from and braking to rest (~0.23 s each way)
  CHECK(r.max_deviation <= 0.01);
}

TEST_CASE("KRN-6 without G261 a chord polyline still stops at every corner (today's behaviour)", "[contour]") {
  const int chords = 20;
  const Run plain = run_circle(chord_circle(chords, 15.9, 0.1, ""), 15.9, 0.1, 2);
  const Run smooth = run_circle(chord_circle(chords, 15.9, 0.1, "G261\n"), 15.9, 0.1, 3);
  CHECK(plain.check.violations.empty());
  CHECK(smooth.check.violations.empty());
  // 20 rest-to-rest moves of 0.1 mm vs. one smooth motion of 2 mm.
  CHECK(plain.moving_cycles > 3 * smooth.moving_cycles);
}

TEST_CASE("KRN-6 G60 stops at its block's end even on a straight line; G61 contours only its own block's end",
          "[contour]") {
  const MachineConfig m = test::xyz_machine();
  auto lowest_velocity_near = [&](const std::string& program, double x, double y) {
    Channel channel(m, program);
    logger::LimitChecker checker(m);
    double lowest = 1e300;
    run_program(channel, &checker, [&](int64_t, const HliState& s, HliControl&) {
      const auto& sp = channel.setpoints();
      if (s.channel_state == ChannelState::active && std::hypot(sp[0].position - x, sp[1].position - y) < 0.01)
        lowest = std::min(lowest, std::hypot(sp[0].velocity, sp[1].velocity));
    });
    CHECK(checker.finish().violations.empty());
    return lowest;
  };
  // Collinear: passes at the feed; with G60 the path stops at X10 (it stops
  // between two cycles: the sampled velocity is a rounding above 0).
  constexpr double stands = 0.01;  // mm/s
  CHECK(lowest_velocity_near("N10 G01 X10 F3000\nN20 X20\nN30 M30\n", 10, 0) > 40);
  CHECK(lowest_velocity_near("N10 G01 X10 F3000 G60\nN20 X20\nN30 M30\n", 10, 0) < stands);
  // G360 modal, G359 ends it.
  CHECK(lowest_velocity_near("N5 G360\nN10 G01 X10 F3000\nN20 X20\nN30 X30\nN40 M30\n", 20, 0) < stands);
  CHECK(lowest_velocity_near("N5 G360\nN10 G01 X10 F3000\nN20 G359 X20\nN30 X30\nN40 M30\n", 20, 0) > 40);
  // A corner: stops without contouring; G61 on N10 contours the corner at
  // X10 but not the one at X10 Y10 (N20 has none). With PATH_DEV 0.5 mm the
  // 90° curve allows 8 mm/s (with 0.01 mm, 0.6 mm/s).
  const std::string square = "#CONTOUR MODE [DEV PATH_DEV=0.5]\nN10 G01 X10 F3000 G61\nN20 Y10\nN30 X0\nN40 M30\n";
  CHECK(lowest_velocity_near("N10 G01 X10 F3000\nN20 Y10\nN30 M30\n", 10, 0) < stands);
  CHECK(lowest_velocity_near(square, 10, 0) == 1e300);  // never within 0.01 mm of the corner
  CHECK(lowest_velocity_near(square, 10, 1) > 5);       // just after the curve, never stood
  CHECK(lowest_velocity_near(square, 10, 10) < stands);
}

TEST_CASE("KRN-6 DPS-1 contoured blocks end on the programmed sums of dist_prog_start", "[contour]") {
  const MachineConfig m = test::xyz_machine();
  // A zigzag polyline with sharp and gentle corners, G261 PATH_DEV = 0.05.
  const std::string program =
      "#CONTOUR MODE [DEV PATH_DEV=0.05]\nN10 G01 G261 X10 F6000\nN20 X20 Y1\nN30 X21 Y5\nN40 X21.5 Y5.2\n"
      "N50 X22 Y5.3\nN60 X30 Y0\nN70 M30\n";
  const std::vector<std::vector<double>> points{{0, 0}, {10, 0}, {20, 1}, {21, 5}, {21.5, 5.2}, {22, 5.3}, {30, 0}};
  std::vector<double> sums{0};
  for (size_t i = 1; i < points.size(); ++i)
    sums.push_back(sums.back() + std::hypot(points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1]));
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  std::vector<double> at_change;
  int64_t last_block = -1;
  double previous_dps = 0;
  run_program(channel, &checker, [&](int64_t, const HliState& s, HliControl&) {
    if (s.block_nr_r != last_block && last_block >= 10) at_change.push_back(previous_dps);
    last_block = s.block_nr_r;
    previous_dps = s.dist_prog_start * 1e-4;
  });
  CHECK(checker.finish().violations.empty());
  CHECK(channel.hli().dist_prog_start * 1e-4 == Approx(sums.back()).epsilon(1e-9));
  // Where the block number changes (the middle of a curve), the count is the
  // programmed sum up to that block's end, to within the last cycle's way.
  REQUIRE(at_change.size() >= 5);
  for (size_t i = 0; i < 5; ++i) {
    INFO("block end " << i + 1);
    CHECK(at_change[i] == Approx(sums[i + 1]).margin(0.11));  // <= one cycle at 100 mm/s
  }
}

namespace {
// Largest distance of a commanded position from the programmed path (any
// of its motion blocks) while the channel runs the program.
struct PathRun {
  double max_deviation = 0;
  int64_t cycles = 0;
  logger::CheckReport check;
};
PathRun run_against_path(const std::string& program) {
  const MachineConfig m = test::xyz_machine();
  const DecodedProgram decoded = decode_program(program, m, std::vector<double>(3, 0.0));
  REQUIRE_FALSE(decoded.error);
  std::vector<PathSegment> path;
  for (const Block& b : decoded.blocks)
    if (b.has_motion) path.emplace_back(b.motion, m);
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  PathRun r;
  r.cycles = test::run_program(channel, &checker, [&](int64_t, const HliState& s, HliControl&) {
    if (s.channel_state != ChannelState::active) return;
    AxisValues q;
    for (const auto& sp : channel.setpoints()) q.push_back(sp.position);
    double nearest = std::numeric_limits<double>::infinity();
    for (const PathSegment& seg : path) {
      const std::vector<double> p = seg.position(std::clamp(seg.length_to(q), 0.0, seg.length()));
      nearest = std::min(nearest, std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]));
    }
    r.max_deviation = std::max(r.max_deviation, nearest);
  });
  r.check = checker.finish();
  return r;
}
}  // namespace

TEST_CASE("KRN-6 issue 36: G261 between tangent arcs of other radii (G165, CAM's 4 decimals) keeps PATH_DEV",
          "[contour]") {
  // Arcs of radius 10, 20, 7, 15 and 30 mm turning left and right in turn,
  // each tangent to the one before, centres programmed with I J. The
  // contouring curve of a tangent joint with a curvature step passes the
  // joint itself; checked only there, it left the arcs between by 0.060
  // mm for PATH_DEV 0.01 (radius 7 into 15), at 9 decimals as at 4.
  const std::string four_decimals =
      "N10 G90 G17 G00 X0 Y0 Z0\n"
      "N20 #CONTOUR MODE [DEV PATH_DEV=0.01]\n"
      "N30 G165 G261 G01 X20 Y0 F6000\n"
      "N40 G03 X27.6604 Y3.5721 I0.0000 J10.0000\n"
      "N50 G02 X46.4543 Y10.4125 I15.3209 J-12.8558\n"
      "N60 G03 X54.2477 Y14.9120 I1.2155 J6.8937\n"
      "N70 G02 X60.8431 Y22.7721 I14.0954 J-5.1303\n"
      "N80 G03 X70.4176 Y31.5456 I-15.0000 J25.9808\n"
      "N90 G01 X81.8892 Y47.9286\n"
      "N100 M30\n";
  const PathRun r = run_against_path(four_decimals);
  INFO("deviation " << r.max_deviation << " mm, " << r.cycles << " cycles");
  CHECK(r.check.violations.empty());
  CHECK(r.max_deviation <= 0.01);
  CHECK(r.max_deviation > 0.001);  // the joints are contoured, not passed as steps
}
