// Polynomial contouring measured (KRN-6, docs/PERFORMANCE.md): a CAM-style
// circle of short G01 chords and the demo contour, run through the channel
// cycle by cycle as the rig does. Prints program time against the ideal
// (length / feed), the largest distance of the commanded path from the
// programmed polyline, the offline limit check's maxima and violations, and
// the planning cost per block. Asserts nothing.
// Run: build/bin/contour_bench [--chords N] [--path-dev mm] [--csv out.csv]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "chord_circle_program.hpp"
#include "command_line.hpp"
#include "channel.hpp"
#include "limit_check.hpp"
#include "machine_config.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

struct Point {
  double x, y;
};

double distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len_sq = dx * dx + dy * dy;
  double t = len_sq > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len_sq : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

struct Result {
  std::vector<double> joint_min_velocity;  // per watched point: lowest path velocity within 1 mm of it
  double time_s = 0, ideal_s = 0, max_deviation = 0, min_velocity_in_contour = 1e300;
  double plan_us_per_block = 0;
  // Wall time of one channel cycle (decode, plan, interpolate): the 50th,
  // 99th percentile and the largest, µs.
  double cycle_p50_us = 0, cycle_p99_us = 0, cycle_max_us = 0;
  logger::CheckReport check;
};

// Runs `program`; `polyline`: the programmed XY path from its start (for
// the deviation), `length`/`feed` the ideal time; the contour part is the
// time between the first and the last polyline point.
Result run(const MachineConfig& machine, const std::string& program, const std::vector<Point>& polyline,
           double length, double feed, size_t blocks, FILE* csv, int64_t first_line = 0,
           const std::vector<Point>& joints = {}, double joint_z_below = 1e300) {
  Result r;
  r.joint_min_velocity.assign(joints.size(), 1e300);
  Channel channel(machine, program);
  logger::LimitChecker checker(machine);
  HliControl control;
  control.program_start = {true, true};
  int64_t k = 0, first_moving = -1, last_moving = -1, first_contour = -1;
  size_t seg = 0;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> cycle_us;
  for (; k < 2000000; ++k) {
    const auto before = std::chrono::steady_clock::now();
    channel.step(k, control);
    cycle_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - before).count());
    control.program_start.command_w = false;
    const auto& sp = channel.setpoints();
    for (size_t i = 0; i < sp.size(); ++i) checker.add_setpoint(static_cast<int>(i), k, sp[i].position);
    const Point p{sp[0].position, sp[1].position};
    double v = 0;
    for (const auto& s : sp) v += s.velocity * s.velocity;
    v = std::sqrt(v);
    for (size_t j = 0; j < joints.size(); ++j)
      if (std::hypot(p.x - joints[j].x, p.y - joints[j].y) < 1.0 && sp[2].position < joint_z_below)
        r.joint_min_velocity[j] = std::min(r.joint_min_velocity[j], v);
    if (v > 0) {
      if (first_moving < 0) first_moving = k;
      last_moving = k;
    }
    // nearest segment, searched forward from the last one
    double best = 1e300;
    size_t best_seg = seg;
    for (size_t s = seg; s + 1 < polyline.size() && s < seg + 8; ++s) {
      const double d = distance_to_segment(p, polyline[s], polyline[s + 1]);
      if (d < best) {
        best = d;
        best_seg = s;
      }
    }
    if (channel.hli().block_count_r >= first_line) seg = best_seg;
    if (polyline.size() > 1 && channel.hli().block_count_r >= first_line) {
      r.max_deviation = std::max(r.max_deviation, best);
      if (first_contour < 0) first_contour = k;
    }
    if (csv) std::fprintf(csv, "%lld %.9f %.9f %.9f %.6f\n", static_cast<long long>(k), sp[0].position, sp[1].position,
                          sp.size() > 2 ? sp[2].position : 0.0, v);
    if (channel.finished()) break;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // From the first cycle on the contour (or of motion) to the last cycle of motion.
  r.time_s = (last_moving - (first_contour >= 0 ? first_contour : first_moving) + 1) * machine.cycle_time_s();
  r.ideal_s = length / feed;
  r.plan_us_per_block = wall * 1e6 / static_cast<double>(blocks);
  if (!cycle_us.empty()) {
    std::sort(cycle_us.begin(), cycle_us.end());
    const auto at = [&](double share) { return cycle_us[static_cast<size_t>(share * double(cycle_us.size() - 1))]; };
    r.cycle_p50_us = at(0.5);
    r.cycle_p99_us = at(0.99);
    r.cycle_max_us = cycle_us.back();
  }
  r.check = checker.finish();
  return r;
}

// Issue 36 item 4: the corner speed the jerk limit allows within PATH_DEV
// (docs/CONTOURING.md "Corner speed bound"). The velocity vector turns from
// v t1 to v t2 as V(t) = v t1 + v (t2 - t1) s(t/T), s the jerk-limited S
// (2u^2, then 1 - 2(1-u)^2): axis i changes its velocity by v |t2_i - t1_i|
// with peak acceleration 2 v |dt_i| / T and jerk 4 v |dt_i| / T^2, so T >=
// the largest of 2 sqrt(v |dt_i| / j_i) and 2 v |dt_i| / a_i; the path
// passes the programmed corner at a distance that grows with v T: the
// corner deviation, which PATH_DEV bounds (TF5200 "Contouring with corner
// deviation": the distance of the rounded contour to the programmed corner
// point). The largest v whose shortest T keeps within PATH_DEV (found
// numerically) is the bound; the lowest path velocity of that turn is |V|
// at its middle.
struct CornerBound {
  double v = 0, v_lowest = 0;
};

// Corner deviation of the turn (v, T): its distance to the corner point.
double turn_deviation(Point t1, Point t2, double v, double T) {
  const int n = 2000;
  const double dt = T / n;
  // From the transition's start, which lies on line 1 at v T / 2 before the corner (the origin).
  Point p{-t1.x * v * T / 2, -t1.y * v * T / 2};
  double nearest = std::hypot(p.x, p.y);
  for (int k = 0; k < n; ++k) {
    const double u = (k + 0.5) / n;
    const double s = u < 0.5 ? 2 * u * u : 1 - 2 * (1 - u) * (1 - u);
    p.x += v * (t1.x + (t2.x - t1.x) * s) * dt;
    p.y += v * (t1.y + (t2.y - t1.y) * s) * dt;
    nearest = std::min(nearest, std::hypot(p.x, p.y));
  }
  return nearest;
}

CornerBound corner_bound(Point t1, Point t2, double path_dev, double feed, const MachineConfig& machine) {
  const double dt[2] = {std::abs(t2.x - t1.x), std::abs(t2.y - t1.y)};
  const auto shortest_turn = [&](double v) {
    double T = 0;
    for (int i = 0; i < 2; ++i) {
      const AxisConfig& axis = machine.axes[static_cast<size_t>(i)];
      T = std::max({T, 2 * std::sqrt(v * dt[i] / axis.j_max), 2 * v * dt[i] / axis.a_max});
    }
    return T;
  };
  double lo = 0, hi = feed;
  if (turn_deviation(t1, t2, hi, shortest_turn(hi)) <= path_dev) lo = hi;
  for (int k = 0; k < 60 && lo < hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (turn_deviation(t1, t2, mid, shortest_turn(mid)) <= path_dev ? lo : hi) = mid;
  }
  return {lo, lo * 0.5 * std::hypot(t1.x + t2.x, t1.y + t2.y)};
}

void print(const char* name, const Result& r, double path_dev) {
  std::printf("%s\n  program time %.3f s, ideal %.3f s: %.3fx\n", name, r.time_s, r.ideal_s, r.time_s / r.ideal_s);
  std::printf("  largest distance from the programmed polyline %.6f mm (PATH_DEV %.4f mm)\n", r.max_deviation,
              path_dev);
  std::printf("  channel cost %.1f us per block (decode, plan, interpolate, check)\n", r.plan_us_per_block);
  std::printf("  channel step per cycle: median %.1f us, 99th percentile %.1f us, largest %.1f us\n", r.cycle_p50_us,
              r.cycle_p99_us, r.cycle_max_us);
  std::printf("  limit check: %zu violations\n", r.check.violations.size());
  for (const auto& a : r.check.axes)
    std::printf("    %s: v %.1f/%.0f (%.0f%%)  a %.0f/%.0f (%.0f%%)  j %.0f/%.0f (%.0f%%)\n", a.axis.c_str(), a.cmd_v,
                a.v_max, 100 * a.cmd_v / a.v_max, a.cmd_a, a.a_max, 100 * a.cmd_a / a.a_max, a.cmd_j, a.j_max,
                100 * a.cmd_j / a.j_max);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"contour_bench: polynomial contouring (KRN-6) on a chord circle and the demo contour"};
  int chords = 10000, decimals = 9;
  double path_dev = 0.01, radius = 15.9, chord = 0.1;
  std::string csv_file, only_name, smoothing = "g261";
  int merge = 1;
  app.add_option("--chords", chords, "chords of the circle")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--path-dev", path_dev, "permitted path deviation, mm")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--csv", csv_file, "write the commanded path as CSV");
  app.add_option("--only", only_name, "circle, demo or corners")->check(CLI::IsMember({"circle", "demo", "corners"}));
  app.add_option("--decimals", decimals, "decimals of the chord end points")->check(CLI::Range(0, 15))->capture_default_str();
  app.footer("Documentation: docs/PERFORMANCE.md and docs/CONTOURING.md in the source tree");
  app.add_option("--smoothing", smoothing, "of the chord circle: g261 (polynomial contouring, KRN-6) or hsc "
                                           "(#HSC ON [BSPLINE PATH_DEV MERGE], KRN-9)")
      ->check(CLI::IsMember({"g261", "hsc"}))
      ->capture_default_str();
  app.add_option("--merge", merge, "MERGE of #HSC (0 or 1)")->check(CLI::Range(0, 1))->capture_default_str();
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  const char* csv_path = csv_file.empty() ? nullptr : csv_file.c_str();
  const char* only = only_name.empty() ? nullptr : only_name.c_str();
  const MachineConfig machine =
      parse_machine_config(YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml"));
  FILE* csv = csv_path ? std::fopen(csv_path, "w") : nullptr;

  if (!only || !std::strcmp(only, "circle")) {
    // A circle of radius `radius` as chords of `chord` mm, counter-clockwise from (R, 0).
    for (const bool contour : {false, true}) {
      if (!contour && chords > 2000) {
        std::printf("chord circle without G261: every chord an exact stop (%d chords: not run, ~%.0f s)\n", chords,
                    chords * 0.0416);
        continue;
      }
      bench::ChordCircle circle;
      circle.chords = chords;
      circle.radius = radius;
      circle.chord = chord;
      circle.path_dev = path_dev;
      circle.decimals = decimals;
      circle.merge = merge;
      const bool hsc = smoothing == "hsc";
      const std::string program =
          circle.program(!contour ? bench::Smoothing::none : hsc ? bench::Smoothing::hsc : bench::Smoothing::g261);
      std::vector<Point> polyline;
      for (int c = 0; c <= chords; ++c) polyline.push_back({circle.x(c), circle.y(c)});
      const Result r =
          run(machine, program, polyline, chords * chord, 100.0, chords, contour ? csv : nullptr, contour ? 4 : 3);
      char name[120];
      std::snprintf(name, sizeof name, "chord circle R%.1f, %d chords of %.2f mm, %d decimals, F6000%s", radius, chords,
                    chord, decimals,
                    !contour ? ", no contouring" : hsc ? (merge ? ", #HSC MERGE=1" : ", #HSC MERGE=0") : ", G261 PATH_DEV");
      print(name, r, path_dev);
    }
  }
  if (!only || !std::strcmp(only, "demo")) {
    for (const bool contour : {false, true}) {
      std::string program =
          "%demo\nN10 G90 G00 X10 Y10 Z5\nN20 G01 Z-2 F600\n";
      if (contour) program += "#CONTOUR MODE [DEV PATH_DEV=" + std::to_string(path_dev) + "]\nN25 G261\n";
      program +=
          "N30 X80 F3000\nN40 G03 X100 Y30 I0 J20\nN50 G01 Y70\nN60 G03 X80 Y90 I-20 J0\nN70 G01 X10\n"
          "N80 G91 Y-80\nN90 G90 G00 Z10\nN100 X0 Y0\nN110 M30\n";
      // The contour N30..N80 as a dense polyline (arcs sampled at 0.01 mm).
      std::vector<Point> polyline{{10, 10}, {80, 10}};
      for (int i = 1; i <= 3142; ++i) {
        const double a = -M_PI / 2 + (M_PI / 2) * i / 3142;
        polyline.push_back({80 + 20 * std::cos(a), 30 + 20 * std::sin(a)});
      }
      polyline.push_back({100, 70});
      for (int i = 1; i <= 3142; ++i) {
        const double a = (M_PI / 2) * i / 3142;
        polyline.push_back({80 + 20 * std::cos(a), 70 + 20 * std::sin(a)});
      }
      polyline.push_back({10, 90});
      polyline.push_back({10, 10});
      const Result r = run(machine, program, {}, 70 + 40 + 70 + 80 + 20 * M_PI, 50.0, 11, nullptr, 0,
                           {{80, 10}, {100, 30}, {100, 70}, {80, 90}}, -1.9);
      print(contour ? "demo, G261 from N30" : "demo, no contouring", r, path_dev);
      std::printf("  lowest path velocity within 1 mm of the tangent joints (feed 50 mm/s):");
      for (double v : r.joint_min_velocity) std::printf(" %.2f", v);
      std::printf(" mm/s\n");
      (void)polyline;
    }
  }
  if (!only || !std::strcmp(only, "corners")) {
    // One corner between lines of 20 mm at F6000: G261 against the bound.
    std::printf("corners of two 20 mm G01 lines, F6000, PATH_DEV %.4f mm: lowest path velocity within 1 mm of the "
                "corner (mm/s), against the jerk-limited turn within PATH_DEV (issue 36 item 4)\n",
                path_dev);
    std::printf("%7s %9s %9s %7s %10s %10s %8s %8s\n", "angle", "bound", "G261", "share", "time G261", "exact stop",
                "dev", "viol");
    for (const double degrees : {2.0, 5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 90.0, 120.0, 150.0}) {
      const double angle = degrees * M_PI / 180;
      const Point t1{1, 0}, t2{std::cos(angle), std::sin(angle)};
      const CornerBound bound = corner_bound(t1, t2, path_dev, 100.0, machine);
      char end[120];
      std::snprintf(end, sizeof end, "X%.6f Y%.6f\nM30\n", 20 + 20 * t2.x, 20 * t2.y);
      const std::vector<Point> polyline{{0, 0}, {20, 0}, {20 + 20 * t2.x, 20 * t2.y}};
      Result timed[2];
      for (const bool contour : {false, true}) {
        std::string program = "%corner\nN1 G90 G00 X0 Y0 Z0\n";
        if (contour) program += "#CONTOUR MODE [DEV PATH_DEV=" + std::to_string(path_dev) + "]\nG261\n";
        program += "G01 X20 F6000\n" + std::string(end);
        timed[contour] = run(machine, program, polyline, 40, 100.0, 2, nullptr, 0, {{20, 0}});
      }
      const Result& r = timed[1];
      // "-": no cycle within 1 mm of the corner (a large PATH_DEV).
      const double v = r.joint_min_velocity[0];
      char lowest[32] = "-", share[16] = "-";
      if (v < 1e300) {
        std::snprintf(lowest, sizeof lowest, "%.2f", v);
        std::snprintf(share, sizeof share, "%.0f%%", 100 * v / bound.v_lowest);
      }
      std::printf("%6.0f° %9.2f %9s %7s %9.3fs %9.3fs %8.5f %8zu\n", degrees, bound.v_lowest, lowest, share,
                  r.time_s, timed[0].time_s, r.max_deviation, r.check.violations.size());
    }
  }
  if (csv) std::fclose(csv);
  return 0;
}
