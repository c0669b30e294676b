// KRN-3: path limits keep every axis within its own v, a, j limits, on lines
// and on (helical) arcs. Checked through the offline checker, which takes
// v, a, j from differences of the sampled positions (RIG-4).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "decoder.hpp"
#include "limit_check.hpp"
#include "path_segment.hpp"
#include "position_profile.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

// Samples a rest-to-rest run over the segment at 0.1 ms and checks it.
logger::CheckReport sample(const PathSegment& seg, MachineConfig machine) {
  machine.cycle_time_us = 100;
  logger::LimitChecker checker(machine);
  const MotionProfile profile = rest_to_rest(seg.length(), seg.limits());
  const double dt = machine.cycle_time_s();
  const int64_t n = static_cast<int64_t>(std::ceil(profile.duration() / dt)) + 3;
  for (int64_t k = 0; k <= n; ++k) {
    const double s = std::min(profile.at(k * dt).p, seg.length());
    const std::vector<double> p = seg.position(s);
    for (size_t i = 0; i < p.size(); ++i) checker.add_setpoint(static_cast<int>(i), k, p[i]);
  }
  return checker.finish();
}

// No axis beyond its v, a, j on a rest-to-rest run, and the segment ends
// on its programmed end point within `margin`.
void check_limits_and_end(const PathSegment& seg, const MachineConfig& machine, double margin) {
  for (const auto& v : sample(seg, machine).violations) FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value);
  const std::vector<double> end = seg.position(seg.length());
  for (size_t i = 0; i < end.size(); ++i) CHECK(end[i] == Approx(seg.end()[i]).margin(margin));
}

Motion motion_of(const std::string& nc) {
  const DecodedProgram p = decode_program(nc, test::xyz_machine(), {0, 0, 0});
  REQUIRE_FALSE(p.error);
  return p.blocks.back().motion;
}

}  // namespace

TEST_CASE("KRN-3 path: a line's limits are each axis' limit over its share of the path", "[path]") {
  const MachineConfig m = test::xyz_machine();
  const PathSegment seg(motion_of("G01 X30 Z40 F60000"), m);  // direction (0.6, 0, 0.8)
  CHECK(seg.length() == Approx(50));
  CHECK(seg.limits().v == Approx(std::min(250 / 0.6, 150 / 0.8)));
  CHECK(seg.limits().a == Approx(std::min(2000 / 0.6, 1500 / 0.8)));
  CHECK(seg.limits().j == Approx(std::min(40000 / 0.6, 30000 / 0.8)));
  for (const auto& v : sample(seg, m).violations) FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value);
  // The programmed feed is the path velocity asked for, not a dynamic limit;
  // G00 asks for each axis' rapid velocity.
  CHECK(PathSegment(motion_of("G01 X30 Z40 F600"), m).programmed_velocity() == Approx(10));
  CHECK(PathSegment(motion_of("G01 X30 Z40 F600"), m).limits().v == Approx(std::min(250 / 0.6, 150 / 0.8)));
  CHECK(PathSegment(motion_of("G00 X30"), m).programmed_velocity() == Approx(250));
}

TEST_CASE("KRN-3 path: arcs keep every axis within v, a and j, whatever the radius", "[path]") {
  const MachineConfig m = test::xyz_machine();
  for (const char* nc : {"G01 X1 F30000\nG03 X1 Y0 I1 J0",        // full circle, r = 1
                         "G01 X10 F30000\nG02 X0 Y10 I-10 J0",    // quarter, r = 10
                         "G01 X100 F30000\nG03 X-100 Y0 I-100",   // half, r = 100
                         "G01 X5 F30000\nG03 X-5 Y0 Z20 I-5"}) {  // helix
    INFO(nc);
    check_limits_and_end(PathSegment(motion_of(nc), m), m, 1e-9);
  }
}

// The decoder takes an end radius up to 1 um off the start radius; the
// path blends the radius along the arc (a spiral). On a short arc the
// radial part outweighs the arc: found by the channel fuzz (a 0.9 um radial
// step over 0.01 um of arc gave Y a jerk of 844,060 mm/s^3, and
// dist_prog_start grew slower than the axes moved).
TEST_CASE("KRN-3 DPS-1 path: an arc whose end radius is a little off keeps every axis within v, a and j, its "
          "derivatives are the position's, and it covers at least what the axes move",
          "[path]") {
  const MachineConfig m = test::xyz_machine();
  for (const char* nc : {"G01 X0 F30000\nG03 X0.00001 Y-0.0009 I0 J0.01",   // r 0.01 -> 0.0109 over 0.9 mrad
                         "G01 X0 F30000\nG02 X0.00001 Y0.0009 I0 J-0.01",   // the same, clockwise
                         "G01 X10 F30000\nG03 X0 Y10.0009 I-10 J0",          // a quarter, 0.9 um off
                         "G01 X1 F30000\nG03 X1.0000004 Y0.0009 Z3 I-1 J0"}) {  // a helix, 0.8 um off
    INFO(nc);
    const PathSegment seg(motion_of(nc), m);
    check_limits_and_end(seg, m, 1e-12);
    const double L = seg.length(), h = L * 1e-4;
    double moved = 0;
    std::vector<double> before = seg.position(0);
    for (int k = 1; k <= 1000; ++k) {
      const double s = L * k / 1000;
      const std::vector<double> p = seg.position(s);
      double step = 0;
      for (size_t i = 0; i < p.size(); ++i) step += (p[i] - before[i]) * (p[i] - before[i]);
      moved += std::sqrt(step);
      before = p;
      if (k % 100 != 50) continue;
      const std::vector<double> t = seg.tangent(s), c = seg.curvature(s);
      const std::vector<double> ahead = seg.position(s + h), behind = seg.position(s - h);
      for (size_t i = 0; i < p.size(); ++i) {
        CHECK(t[i] == Approx((ahead[i] - behind[i]) / (2 * h)).margin(1e-6));
        CHECK(c[i] == Approx((ahead[i] - 2 * p[i] + behind[i]) / (h * h)).epsilon(1e-3).margin(1e-6 / L));
      }
    }
    CHECK(seg.covered_distance() >= moved * (1 - 1e-12));  // DPS-1: never behind the axes
  }
}

TEST_CASE("DPS-1 path: the covered distance is the main axis path; without it, the leading tracking axis",
          "[path]") {
  MachineConfig m = test::xyz_machine();
  AxisConfig a = m.axes[0];
  a.name = "A";
  a.v_max = 100;  // slower than X: leads when both move
  m.axes.push_back(a);
  auto covered = [&](const std::string& nc) {
    const DecodedProgram p = decode_program(nc, m, {0, 0, 0, 0});
    REQUIRE_FALSE(p.error);
    return PathSegment(p.blocks.back().motion, m).covered_distance();
  };
  CHECK(covered("G01 X30 Y40 A90 F600") == Approx(50));        // main axes only
  CHECK(covered("G01 A90 F600") == Approx(90));                 // tracking axis alone
  CHECK(covered("G01 X3 Y4 F600\nG03 X3 Y4 I-3 J-4 Z10") == Approx(std::hypot(10 * M_PI, 10)));  // helix
}
