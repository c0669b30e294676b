// KRN-9 HSC smoothing: #HSC ON/OFF [BSPLINE ..] decoded as the programming
// manual defines it, the spline through CAM polylines (cnc/path/hsc_spline),
// and CAM chord circles through the channel (docs/HSC.md).
#include <catch2/catch.hpp>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "decoder.hpp"
#include "hsc_spline.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

DecodedProgram decode_text(const std::string& text) {
  return decode_program(text, test::xyz_machine(), std::vector<double>(3, 0.0));
}

std::string rounded(double v, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

// A circle of `chords` G01 chords of 0.1 mm on R 15.9 from (R, 0), its points
// written with `decimals` decimals as CAM systems do.
std::string chord_circle(int chords, int decimals, const std::string& head) {
  const double radius = 15.9, step = 2 * std::asin(0.1 / (2 * radius));
  std::string program = "N1 G90 G00 X15.9 Y0 Z0\n" + head;
  for (int c = 1; c <= chords; ++c)
    program += std::string(c == 1 ? "G01 " : "") + "X" + rounded(radius * std::cos(c * step), decimals) + " Y" +
               rounded(radius * std::sin(c * step), decimals) + (c == 1 ? " F6000" : "") + "\n";
  return program + "M30\n";
}

// The motion blocks' end points of a decoded program (the first: its start).
std::vector<std::vector<double>> polyline(const DecodedProgram& p) {
  std::vector<std::vector<double>> points;
  for (const Block& b : p.blocks) {
    if (!b.has_motion || b.motion.type != MotionType::linear) continue;
    if (points.empty()) points.push_back(b.motion.start);
    points.push_back(b.motion.end);
  }
  return points;
}

double distance_to_polyline(const std::vector<double>& q, const std::vector<std::vector<double>>& points,
                            size_t from, size_t to) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = from; i + 1 < std::min(to, points.size()); ++i) {
    const std::vector<double>& a = points[i];
    const std::vector<double>& b = points[i + 1];
    double along = 0, size = 0;
    for (size_t k = 0; k < 3; ++k) {
      along += (q[k] - a[k]) * (b[k] - a[k]);
      size += (b[k] - a[k]) * (b[k] - a[k]);
    }
    const double u = size > 0 ? std::clamp(along / size, 0.0, 1.0) : 0.0;
    double d = 0;
    for (size_t k = 0; k < 3; ++k) d += std::pow(q[k] - a[k] - u * (b[k] - a[k]), 2);
    best = std::min(best, std::sqrt(d));
  }
  return best;
}

struct CircleRun {
  double moving_s = 0;
  double max_deviation = 0;  // from the programmed polyline
  logger::CheckReport check;
};

CircleRun run_chord_circle(int chords, int decimals, const std::string& head) {
  const MachineConfig m = test::xyz_machine();
  const std::string program = chord_circle(chords, decimals, head);
  const std::vector<std::vector<double>> points = polyline(decode_text(program));
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  CircleRun r;
  int64_t moving = 0;
  size_t near = 0;  // the polyline point nearest the path so far
  test::run_program(channel, &checker, [&](int64_t, const HliState& s, HliControl&) {
    const auto& sp = channel.setpoints();
    if (std::hypot(sp[0].velocity, sp[1].velocity) > 0 && s.block_count_r >= 3) ++moving;
    if (s.channel_state != ChannelState::active || s.block_count_r < 3) return;
    const std::vector<double> q{sp[0].position, sp[1].position, sp[2].position};
    while (near + 1 < points.size() && std::hypot(points[near + 1][0] - q[0], points[near + 1][1] - q[1]) <
                                           std::hypot(points[near][0] - q[0], points[near][1] - q[1]))
      ++near;
    r.max_deviation =
        std::max(r.max_deviation, distance_to_polyline(q, points, near >= 3 ? near - 3 : 0, near + 4));
  });
  r.moving_s = static_cast<double>(moving) * 1e-3;
  r.check = checker.finish();
  return r;
}

// The pieces an HscSpline makes of a decoded program's G01 blocks (a
// separated block as its line).
std::vector<PathPiece> spline_pieces(const DecodedProgram& p, const MachineConfig& m) {
  HscSpline spline(m);
  std::vector<PathPiece> pieces;
  const auto take = [&](std::vector<HscOutput>&& items) {
    for (HscOutput& item : items) {
      if (auto* part = std::get_if<SplinePiece>(&item)) pieces.push_back(std::move(part->piece));
      else {
        SeparatedBlock& s = std::get<SeparatedBlock>(item);
        pieces.push_back({s.piece.block, std::move(s.segment), s.piece.slope, s.stop_before, true, true});
      }
    }
  };
  for (size_t k = 0; k < p.blocks.size(); ++k) {
    const Block& b = p.blocks[k];
    if (!b.has_motion || b.motion.type != MotionType::linear) continue;
    const PathSegment segment(b.motion, m);
    const MotionPiece piece = MotionPiece::of_block(b, k, segment);
    REQUIRE(HscSpline::smooths(piece, segment));
    take(spline.add(piece, segment, false));
  }
  take(spline.flush());
  return pieces;
}

// The largest distance of the pieces (9 points each) from the polyline.
double largest_distance(const std::vector<PathPiece>& pieces, const std::vector<std::vector<double>>& points) {
  double largest = 0;
  for (const PathPiece& piece : pieces)
    for (int k = 0; k <= 8; ++k)
      largest = std::max(largest, distance_to_polyline(piece.segment.position(piece.segment.length() * k / 8), points,
                                                       0, points.size()));
  return largest;
}

double norm_of_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

}  // namespace

TEST_CASE("KRN-9 decoder: #HSC ON [BSPLINE ..] sets the modal HSC parameters, the manual's defaults otherwise",
          "[hsc][decoder]") {
  const DecodedProgram p = decode_text(
      "N10 G01 X1 F600\n"
      "N20 #HSC ON\n"
      "N30 X2\n"
      "N40 #HSC [BSPLINE PATH_DEV=0.05 TRACK_DEV=2 MERGE=1 MAX_ANGLE=20 MAX_PATH_LENGTH=3 AUTO_OFF_PATH=1]\n"
      "N50 X3\n"
      "N60 #HSC OFF\n"
      "N70 X4\n"
      "N80 #HSC ON [BSPLINE, PATH_DEV = 0.5]\n"
      "N90 X5\n"
      "M30\n");
  REQUIRE_FALSE(p.error);
  std::vector<HscMode> modes;
  for (const Block& b : p.blocks)
    if (b.has_motion) modes.push_back(b.hsc);
  REQUIRE(modes.size() == 5);
  CHECK_FALSE(modes[0].on);
  CHECK(modes[1].on);
  CHECK(modes[1].path_dev == 0.2);  // the manual's default
  CHECK(modes[1].track_dev == 5);
  CHECK_FALSE(modes[1].merge);
  CHECK(modes[2].on);  // parameters alone keep ON
  CHECK(modes[2].path_dev == 0.05);
  CHECK(modes[2].track_dev == 2);
  CHECK(modes[2].merge);
  CHECK(modes[2].max_angle == 20);
  CHECK(modes[2].max_path_length == 3);
  CHECK(modes[2].auto_off_path);
  CHECK_FALSE(modes[3].on);
  CHECK(modes[4].on);
  CHECK(modes[4].path_dev == 0.5);
  CHECK(modes[4].merge);  // modal: kept from N40
}

TEST_CASE("KRN-9 decoder: #HSC without BSPLINE first, unknown keys and values out of range are refused with the line",
          "[hsc][decoder]") {
  const struct {
    const char* line;
    const char* message;
  } cases[] = {
      {"N20 #HSC ON [PATH_DEV=0.1]", "BSPLINE must be the first keyword"},
      {"N20 #HSC ON [BSPLINE SMOOTH=1]", "unknown parameter 'SMOOTH'"},
      {"N20 #HSC ON [BSPLINE MERGE=2]", "MERGE must be 0 or 1"},
      {"N20 #HSC ON [BSPLINE PATH_DEV=-1]", "PATH_DEV must be >= 0"},
      {"N20 #HSC ON [BSPLINE MAX_ANGLE=200]", "MAX_ANGLE must be >= 0 and <= 180"},
      {"N20 #HSC ON [BSPLINE MERGE]", "'MERGE' needs a value"},
      {"N20 #HSC OFF [BSPLINE]", "#HSC OFF takes no parameters"},
      {"N20 #HSC", "#HSC needs ON, OFF or [BSPLINE ..]"},
  };
  for (const auto& c : cases) {
    INFO(c.line);
    const DecodedProgram p = decode_text(std::string("N10 G01 X1 F600\n") + c.line + "\nN30 X2\nM30\n");
    REQUIRE(p.error);
    CHECK(p.error->nc_line == 2);
    CHECK(p.error->block_nr == 20);
    CHECK_THAT(p.error->message, Catch::Contains(c.message));
  }
}

TEST_CASE("KRN-9 decoder: AUTO_OFF_G00 / AUTO_OFF_G60 switch HSC off at a G00 block / an exact stop; without them "
          "HSC stays on",
          "[hsc][decoder]") {
  auto modes_of = [](const std::string& head) {
    const DecodedProgram p =
        decode_text("N10 G01 X1 F600\n" + head + "\nN30 X2\nN40 G00 X3\nN50 G01 X4\nN60 G60 X5\nN70 X6\nM30\n");
    REQUIRE_FALSE(p.error);
    std::vector<bool> on;
    for (const Block& b : p.blocks)
      if (b.has_motion) on.push_back(b.hsc.on);
    return on;
  };
  CHECK(modes_of("N20 #HSC ON") == std::vector<bool>{false, true, true, true, true, true});
  CHECK(modes_of("N20 #HSC ON [BSPLINE AUTO_OFF_G00=1]") == std::vector<bool>{false, true, false, false, false, false});
  CHECK(modes_of("N20 #HSC ON [BSPLINE AUTO_OFF_G60=1]") == std::vector<bool>{false, true, true, true, false, false});
}

TEST_CASE("KRN-9 HSC spline through a chord circle of CAM's 4 decimals: from its first to its last programmed point, "
          "tangent and curvature continuous, within PATH_DEV, its curvature rate far below the chords' rounding",
          "[hsc]") {
  const MachineConfig m = test::xyz_machine();
  std::vector<double> rates;
  for (const bool merge : {false, true}) {
    INFO("MERGE=" << merge);
    const DecodedProgram p = decode_text(chord_circle(
        400, 4, std::string("#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=") + (merge ? "1" : "0") + "]\n"));
    REQUIRE_FALSE(p.error);
    const std::vector<std::vector<double>> points = polyline(p);
    const std::vector<PathPiece> pieces = spline_pieces(p, m);
    REQUIRE(pieces.size() == 400);
    double covered = 0, polyline_length = 0, max_rate = 0, max_deviation = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) polyline_length += norm_of_difference(points[i], points[i + 1]);
    for (size_t i = 0; i < pieces.size(); ++i) {
      const PathSegment& s = pieces[i].segment;
      REQUIRE(s.is_contour_curve());
      CHECK(pieces[i].begins_block);
      CHECK(pieces[i].ends_block);
      covered += s.covered_distance();
      if (i > 0) {  // continuous in position, tangent and curvature
        const PathSegment& before = pieces[i - 1].segment;
        CHECK(norm_of_difference(before.end(), s.position(0)) < 1e-9);
        CHECK(norm_of_difference(before.tangent(before.length()), s.tangent(0)) < 1e-9);
        CHECK(norm_of_difference(before.curvature(before.length()), s.curvature(0)) < 1e-6);
      }
      const ContourCurve::AxisBounds b = s.joint()->curve->bounds(s.curve_position(0), s.curve_position(s.length()));
      max_rate = std::max(max_rate, b.curvature_rate_norm);
      for (int k = 0; k <= 4; ++k)
        max_deviation = std::max(max_deviation, distance_to_polyline(s.position(s.length() * k / 4), points,
                                                                    i >= 30 ? i - 30 : 0, i + 30));
    }
    // The spline's ends are programmed points, exactly.
    CHECK(pieces.front().segment.position(0) == points.front());
    CHECK(pieces.back().segment.end() == points.back());
    CHECK(covered == Approx(polyline_length).epsilon(1e-12));
    CHECK(max_deviation <= 0.01);
    // A circle's is 0; one corner curve per chord (G261) swings by the
    // chords' rounding, 1e-3 rad over 0.1 mm twice: ~1 /mm^2. Knots at
    // every chord (MERGE=0) keep much of it; spans of 2 mm do not.
    rates.push_back(max_rate);
  }
  INFO("largest |dk/ds|: MERGE=0 " << rates[0] << ", MERGE=1 " << rates[1] << " /mm^2");
  CHECK(rates[1] < 0.01);
  CHECK(rates[1] < rates[0] / 10);
}

TEST_CASE("KRN-9 HSC keeps a bend sharper than MAX_ANGLE (default 30 degrees) as a corner, and ends the spline "
          "there at the programmed point",
          "[hsc]") {
  const MachineConfig m = test::xyz_machine();
  std::string program = "N1 G01 X0 Y0 F6000\n#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n";
  for (int i = 1; i <= 30; ++i) program += "X" + rounded(0.1 * i, 4) + " Y0\n";
  for (int i = 1; i <= 30; ++i) program += "X3 Y" + rounded(0.1 * i, 4) + "\n";
  program += "M30\n";
  const DecodedProgram p = decode_text(program);
  REQUIRE_FALSE(p.error);
  const std::vector<PathPiece> pieces = spline_pieces(p, m);
  REQUIRE(pieces.size() == 60);
  const PathSegment& before = pieces[29].segment;
  const PathSegment& after = pieces[30].segment;
  CHECK(norm_of_difference(before.end(), {3, 0, 0}) < 1e-12);
  CHECK(norm_of_difference(after.position(0), {3, 0, 0}) < 1e-12);
  CHECK(before.tangent(before.length())[0] == Approx(1).margin(1e-6));
  CHECK(after.tangent(0)[1] == Approx(1).margin(1e-6));
  // With MAX_ANGLE=100 the same corner is rounded off within PATH_DEV.
  const DecodedProgram rounded_corner = decode_text(
      std::string(program).replace(program.find("MERGE=1]"), 8, "MERGE=1 MAX_ANGLE=100]"));
  const std::vector<PathPiece> through = spline_pieces(rounded_corner, m);
  CHECK(largest_distance(through, polyline(rounded_corner)) <= 0.01);
}

TEST_CASE("KRN-9 KRN-3 issue 36: CAM chord circles of 4 and 3 decimals with #HSC ON [BSPLINE MERGE=1] run within "
          "1.10 of the ideal time, within PATH_DEV, every axis limit held",
          "[hsc]") {
  const int chords = 3000;  // 300 mm at F6000: 3 s
  const double ideal_s = chords * 0.1 / 100.0;
  for (const int decimals : {4, 3}) {
    const CircleRun r = run_chord_circle(chords, decimals, "#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n");
    INFO(decimals << " decimals: " << r.moving_s << " s, ideal " << ideal_s << " s, deviation " << r.max_deviation);
    CHECK(r.check.violations.empty());
    CHECK(r.moving_s <= 1.10 * ideal_s + 0.3);  // + accelerating from and braking to rest
    CHECK(r.max_deviation <= 0.01);
  }
}

TEST_CASE("KRN-9 TRACK_DEV bounds the miss of a tracking axis (C) on the spline; 0 does not check it", "[hsc]") {
  // XY chords of a circle while C turns by a varying step (a tool axis
  // following a CAM surface): the spline interpolates C with X and Y, and
  // misses C's polyline between the knots by a little.
  const MachineConfig m = test::xyzc_machine();
  auto pieces_with = [&](const std::string& track_dev) {
    std::string program = "N1 G00 X15.9 Y0 C0\n#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1 TRACK_DEV=" + track_dev + "]\n";
    const double step = 2 * std::asin(0.1 / (2 * 15.9));
    for (int c = 1; c <= 200; ++c)
      program += (c == 1 ? "G01 X" : "X") + rounded(15.9 * std::cos(c * step), 4) + " Y" +
                 rounded(15.9 * std::sin(c * step), 4) + " C" + rounded(0.5 * c + 3 * std::sin(c / 7.0), 4) +
                 (c == 1 ? " F6000\n" : "\n");
    program += "M30\n";
    const DecodedProgram p = decode_program(program, m, std::vector<double>(m.axes.size(), 0.0));
    REQUIRE_FALSE(p.error);
    return spline_pieces(p, m);
  };
  auto curves = [](const std::vector<PathPiece>& pieces) {
    return std::count_if(pieces.begin(), pieces.end(), [](const PathPiece& p) { return p.segment.is_contour_curve(); });
  };
  const std::vector<PathPiece> unchecked = pieces_with("0"), loose = pieces_with("5"), tight = pieces_with("0.00001");
  REQUIRE(unchecked.size() == 200);
  CHECK(curves(unchecked) == 200);
  CHECK(curves(loose) == 200);
  // Spans halved down to single blocks, and those that still miss by more
  // run as their programmed lines.
  CHECK(curves(tight) < 200);
  const int c_axis = m.axis_index("C");
  REQUIRE(c_axis >= 0);
  for (const PathPiece& piece : tight) {
    if (!piece.segment.is_contour_curve()) continue;
    const std::vector<double> a = piece.segment.position(0), b = piece.segment.end();
    const auto c = static_cast<size_t>(c_axis);
    for (int k = 1; k < 8; ++k) {
      const double share = k / 8.0;
      const std::vector<double> q = piece.segment.position(piece.segment.length() * share);
      // Within TRACK_DEV of the block's own C line (plus what the
      // sampling between the check's points may miss).
      CHECK(std::abs(q[c] - (a[c] + share * (b[c] - a[c]))) < 0.0005);
    }
  }
}

TEST_CASE("KRN-9 KRN-6 an exact stop at the end of a block before a spline and at the end of a spline's block "
          "stands the path there",
          "[hsc]") {
  // G60 on the line before the spline, which goes on straight ahead: the
  // contour builder closes the line, the spline takes the next block and
  // must still start from standstill. A G60 on a block inside the spline
  // ends it there, standing.
  std::string program = "N10 G01 X5 Y0 F6000\nN20 G60 X10 Y0\n#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n";
  for (int i = 1; i <= 20; ++i)
    program += "X" + rounded(10 + 0.1 * i, 4) + " Y" + rounded(-0.0001 * i * i, 4) + "\n";
  program += "G60 X12.1 Y-0.042\n";
  for (int i = 1; i <= 10; ++i) program += "X" + rounded(12.1 + 0.1 * i, 4) + " Y" + rounded(-0.042 - 0.004 * i, 4) + "\n";
  program += "M30\n";
  const MachineConfig m = test::xyz_machine();
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  // The lowest path velocity within 0.01 mm of either point: the cycles
  // around a stop there sample the path braking to it and starting again.
  double at_line_end = 1e9, at_g60 = 1e9;
  test::run_program(channel, &checker, [&](int64_t, const HliState&, HliControl&) {
    const auto& sp = channel.setpoints();
    const double v = std::hypot(sp[0].velocity, sp[1].velocity);
    if (std::hypot(sp[0].position - 10, sp[1].position) < 0.01) at_line_end = std::min(at_line_end, v);
    if (std::hypot(sp[0].position - 12.1, sp[1].position + 0.042) < 0.01) at_g60 = std::min(at_g60, v);
  });
  CHECK(checker.finish().violations.empty());
  INFO("lowest path velocity near the line's end " << at_line_end << ", near the G60 " << at_g60 << " mm/s");
  // Within 0.01 mm of a stop a jerk-limited path (j 40,000 mm/s^3) runs
  // below 2.6 mm/s; passed without a stop, both joints run at tens of mm/s.
  CHECK(at_line_end < 3);
  CHECK(at_g60 < 3);
}

namespace {

// Cycles from program start to its end, and the lowest path velocity
// between the first and the last cycle of motion (0: the path stood).
struct SmoothedRun {
  int64_t cycles = 0;
  double lowest_velocity = 0;
  size_t violations = 0;
};

SmoothedRun run_between_motion(const std::string& program) {
  const MachineConfig m = test::xyz_machine();
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  std::vector<double> velocity;
  SmoothedRun r;
  r.cycles = test::run_program(channel, &checker, [&](int64_t, const HliState&, HliControl&) {
    const auto& sp = channel.setpoints();
    velocity.push_back(std::hypot(sp[0].velocity, sp[1].velocity));
  });
  const auto first = std::find_if(velocity.begin(), velocity.end(), [](double v) { return v > 0; });
  const auto last = std::find_if(velocity.rbegin(), velocity.rend(), [](double v) { return v > 0; }).base();
  r.lowest_velocity = first < last ? *std::min_element(first, last) : 0.0;
  r.violations = checker.finish().violations.size();
  return r;
}

}  // namespace

TEST_CASE("KRN-9 KRN-6 a block HSC separates runs with its programmed transitions: G261 contours it", "[hsc]") {
  // Separated: a run of one block, or a block whose span leaves PATH_DEV.
  const std::string g261 = "#CONTOUR MODE [DEV PATH_DEV=0.02]\nG261\n";
  SECTION("lines between tangent arcs (a plasma profile): each line a run of one block") {
    const std::string profile =
        "G01 Y32 F2800\nG02 X8 Y40.8 I8.8 J0\nG01 X30\nG02 X38.8 Y32 I0 J-8.8\nG01 Y8\n"
        "G02 X30 Y-0.8 I-8.8 J0\nG01 X8\nM30\n";
    const SmoothedRun contoured = run_between_motion("N1 G90 G00 X-0.8 Y0 Z0\n" + g261 + profile);
    const SmoothedRun with_hsc =
        run_between_motion("N1 G90 G00 X-0.8 Y0 Z0\n" + g261 + "#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n" + profile);
    // Before: each line a spline of one straight span, its joints with the
    // arcs not contoured and its limits a curve's (a/2, j/3).
    CHECK(with_hsc.cycles == contoured.cycles);
    CHECK(with_hsc.violations == 0);
  }
  SECTION("chords of 1.4 mm turning 4 degrees (sagitta 0.012 mm) under PATH_DEV 0.005: every span is separated") {
    // An arc of R 20 as 30 chords in 3 decimals: the spline through the
    // points bulges 0.012 mm from each chord, beyond PATH_DEV.
    std::string chords;
    for (int i = 1; i <= 30; ++i) {
      const double a = i * 4 * M_PI / 180;
      chords += "X" + rounded(20 * std::sin(a), 3) + " Y" + rounded(20 - 20 * std::cos(a), 3) + "\n";
    }
    const std::string head = "N1 G90 G00 X0 Y0 Z0\n" + g261 + "G01 X0.001 F6000\n";
    const SmoothedRun contoured = run_between_motion(head + chords + "M30\n");
    const SmoothedRun with_hsc = run_between_motion(head + "#HSC ON [BSPLINE PATH_DEV=0.005]\n" + chords + "M30\n");
    INFO("G261 " << contoured.cycles << " cycles, lowest " << contoured.lowest_velocity << " mm/s; with #HSC "
                 << with_hsc.cycles << " cycles, lowest " << with_hsc.lowest_velocity << " mm/s");
    // Before: each separated chord ran as a line whose corners stopped.
    CHECK(with_hsc.lowest_velocity > 0.5 * contoured.lowest_velocity);
    CHECK(with_hsc.cycles <= contoured.cycles * 1.02);
    CHECK(with_hsc.violations == 0);
  }
  SECTION("G261's curve where a spline meets a separated block") {
    // One circle of R 20 in 3 decimals: chords of 0.2 mm (a spline), of
    // 1.4 mm (4 degrees, sagitta 0.012 mm: separated under PATH_DEV
    // 0.005), of 0.2 mm again. At the joints the spline's tangent and the
    // chord's differ by half the chord's turn, 2 degrees: a corner. Before,
    // the corner rule judged it, a stop (mixed_transitions: 12 such joints,
    // +0.03 .. 0.06 s each, docs/HSC.md).
    std::string chords;
    double angle = 0;
    const auto arc = [&](double step_deg, int count) {
      for (int i = 0; i < count; ++i) {
        angle += step_deg * M_PI / 180;
        chords += "X" + rounded(20 * std::sin(angle), 3) + " Y" + rounded(20 - 20 * std::cos(angle), 3) + "\n";
      }
    };
    arc(0.573, 20);
    arc(4, 6);
    arc(0.573, 20);
    const std::vector<double> end{20 * std::sin(angle), 20 - 20 * std::cos(angle)};
    const std::string hsc = "#HSC ON [BSPLINE PATH_DEV=0.005]\nG01 F6000\n";
    // The lowest path velocity more than 1 mm from the start and the end.
    const auto lowest_between = [&](const std::string& program, int64_t& cycles, size_t& violations) {
      const MachineConfig m = test::xyz_machine();
      Channel channel(m, program);
      logger::LimitChecker checker(m);
      double lowest = 1e9;
      cycles = test::run_program(channel, &checker, [&](int64_t, const HliState&, HliControl&) {
        const auto& sp = channel.setpoints();
        if (std::hypot(sp[0].position, sp[1].position) > 1 &&
            std::hypot(sp[0].position - end[0], sp[1].position - end[1]) > 1)
          lowest = std::min(lowest, std::hypot(sp[0].velocity, sp[1].velocity));
      });
      violations = checker.finish().violations.size();
      return lowest;
    };
    int64_t contoured_cycles = 0, cornered_cycles = 0;
    size_t contoured_violations = 0, cornered_violations = 0;
    const double contoured = lowest_between("N1 G90 G00 X0 Y0 Z0\n" + g261 + hsc + chords + "M30\n",
                                            contoured_cycles, contoured_violations);
    const double cornered =
        lowest_between("N1 G90 G00 X0 Y0 Z0\n" + hsc + chords + "M30\n", cornered_cycles, cornered_violations);
    INFO("G261: " << contoured_cycles << " cycles, lowest " << contoured << " mm/s; G260: " << cornered_cycles
                  << " cycles, lowest " << cornered << " mm/s");
    // Stopped, the path runs below 3 mm/s within 0.01 mm of the joint; the
    // curves on the blocks pass it at 11.8 mm/s (F6000; the curve from the
    // spline's knot through the vertex onto the chord bends more than the
    // circle: docs/HSC.md).
    CHECK(cornered < 3);
    CHECK(contoured > 8);
    CHECK(contoured_cycles < cornered_cycles);
    CHECK(contoured_violations == 0);
    CHECK(cornered_violations == 0);
  }
}

TEST_CASE("KRN-9 issue 36: a letter's tip in real CAM output (4 decimals, chords of 0.03 to 0.26 mm turning up to 9 "
          "degrees and back) is one spline: no block separated, within PATH_DEV, passed without a stop",
          "[hsc]") {
  // tests/programs/public/jscut_jsdc.nc (jscut, cncjs/cncjs, MIT), its
  // lines 818..862. A cubic fitted over 2 mm on either side of a knot cannot
  // follow a turn of 0.3 mm: every span here left PATH_DEV, and the blocks,
  // separated, stopped at each corner (the program took 40.2 s against
  // LinuxCNC's 36.1; 38.3 s since the fit's window narrows there). G92
  // puts its start where the channel stands.
  const char* tip[] = {
      "X48.0123 Y-33.4744", "X48.2605 Y-33.5222", "X48.5097 Y-33.5730", "X48.7601 Y-33.6268", "X48.8859 Y-33.6550",
      "X49.0116 Y-33.6840", "X49.1378 Y-33.7137", "X49.2641 Y-33.7442", "X49.3906 Y-33.7754", "X49.5173 Y-33.8074",
      "X49.7713 Y-33.8739", "X50.0258 Y-33.9435", "X50.1533 Y-33.9796", "X50.2811 Y-34.0164", "X50.4088 Y-34.0540",
      "X50.5366 Y-34.0924", "X50.5882 Y-34.1086", "X50.6367 Y-34.1221", "X50.6829 Y-34.1323", "X50.7261 Y-34.1389",
      "X50.7670 Y-34.1419", "X50.8053 Y-34.1409", "X50.8411 Y-34.1358", "X50.8747 Y-34.1259", "X50.9059 Y-34.1114",
      "X50.9351 Y-34.0919", "X50.9621 Y-34.0667", "X50.9869 Y-34.0363", "X51.0101 Y-33.9997", "X51.0311 Y-33.9573",
      "X51.0504 Y-33.9082", "X51.0682 Y-33.8526", "X51.0840 Y-33.7899", "X51.0984 Y-33.7200", "X51.1114 Y-33.6428",
      "X51.1228 Y-33.5577", "X51.1327 Y-33.4648", "X51.1416 Y-33.3634", "X51.1493 Y-33.2534", "X51.1556 Y-33.1346",
      "X51.1612 Y-33.0068", "X51.1655 Y-32.8696", "X51.1693 Y-32.7228", "X51.1719 Y-32.5661", "X51.1739 Y-32.3992"};
  std::string blocks;
  for (const char* point : tip) blocks += std::string("G01 ") + point + (blocks.empty() ? " F1016\n" : "\n");
  const std::string program =
      "N1 G90\nG92 X-47.7631 Y33.4279\n#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n" + blocks + "M30\n";
  const MachineConfig m = test::xyz_machine();
  const DecodedProgram p = decode_text(program);
  REQUIRE_FALSE(p.error);
  const std::vector<PathPiece> pieces = spline_pieces(p, m);
  const auto separated =
      std::count_if(pieces.begin(), pieces.end(), [](const PathPiece& piece) { return !piece.segment.joint(); });
  CHECK(separated == 0);
  CHECK(largest_distance(pieces, polyline(p)) <= 0.01);
  // Between reaching 10 mm/s and braking below it for the program end.
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  std::vector<double> velocity;
  test::run_program(channel, &checker, [&](int64_t, const HliState&, HliControl&) {
    velocity.push_back(std::hypot(channel.setpoints()[0].velocity, channel.setpoints()[1].velocity));
  });
  const auto fast = [](double v) { return v > 10; };
  const auto first = std::find_if(velocity.begin(), velocity.end(), fast);
  const auto last = std::find_if(velocity.rbegin(), velocity.rend(), fast).base();
  REQUIRE(first < last);
  const double lowest = *std::min_element(first, last);
  INFO(velocity.size() << " cycles, lowest " << lowest << " mm/s");
  CHECK(lowest > 2);
  CHECK(checker.finish().violations.empty());
}

TEST_CASE("KRN-9 KRN-3 issue 36: on a gentle curve (its curvature terms at the feed within a third of the axes' "
          "limits) the path brakes and accelerates with 2/3 of their acceleration and jerk, else with the shares",
          "[hsc]") {
  const MachineConfig m = test::xyz_machine();  // X, Y: a 2000 mm/s^2, j 40,000 mm/s^3
  const auto limits_at = [&](const std::string& feed) {
    std::string program = chord_circle(200, 4, "#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n");
    program.replace(program.find("F6000"), 5, feed);
    std::vector<Limits> limits;
    for (const PathPiece& piece : spline_pieces(decode_text(program), m))
      if (piece.segment.joint()) limits.push_back(piece.segment.limits());
    return limits;
  };
  // F600, R 15.9: k v^2 = 6.3 mm/s^2 and 3 k v a_t = 2,500 mm/s^3, far inside a third.
  const std::vector<Limits> slow = limits_at("F600");
  REQUIRE(slow.size() > 100);
  for (const Limits& lim : slow) {
    CHECK(lim.j == Approx(2 * 40000.0 / 3));
    CHECK(lim.a <= 2 * 2000.0 / 3);
    CHECK(lim.a >= 2 * 2000.0 / 3 * std::exp2(-1.0 / 16));
  }
  // F6000: 3 k v a_t at 2/3 of a would be 25,000 mm/s^3: the shares (a/2, j/3).
  for (const Limits& lim : limits_at("F6000")) {
    CHECK(lim.j == Approx(40000.0 / 3));
    CHECK(lim.a <= 1000.0);
  }
}
