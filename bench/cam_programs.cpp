// Issue 36 item 5 (KRN-3, KRN-6, KRN-9, docs/HSC.md): CAM programs run
// through the channel cycle by cycle as the rig runs them, each three ways —
// as written (a chord circle: every chord an exact stop; the corpus stops at
// its corners but where it selects G61 / G261 itself), with G261 (#CONTOUR MODE [DEV
// PATH_DEV=..]) and with #HSC ON [BSPLINE PATH_DEV=.. MERGE=1] — one line
// added after the program's first G90. The programs: 0.1 mm chord circles
// at 9, 4 and 3 decimals, the corpus of tests/programs and real CAM output
// from tests/programs/public. Prints per run:
// time from the first to the last cycle of motion against the ideal (each
// motion block's length over min(F, the axes' velocity limit along it), G00
// at its rapid limit), the median and 5th percentile path velocity of the
// cycles whose interpolator block is a G01/G02/G03, the largest distance of
// the commanded X Y Z from the programmed path, the offline limit check's
// violations, the channel's wall time per motion block (decode, plan,
// interpolate) and its 99th percentile cycle; with --losses N, the N NC
// lines whose time exceeds their share of the ideal most. Asserts nothing.
// Run: build/bin/cam_programs [--programs a,b] [--circles 9,4,3] [--ways written,g261,hsc] [--losses N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "channel.hpp"
#include "chord_circle_program.hpp"
#include "command_line.hpp"
#include "decoder.hpp"
#include "limit_check.hpp"
#include "machine_config.hpp"
#include "path_segment.hpp"
#include "scenario_engine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

struct Figures {
  double time_s = 0, ideal_s = 0, v_median = 0, v_p5 = 0, max_deviation = 0;
  double us_per_block = 0, cycle_p99_us = 0, cycle_max_us = 0;
  size_t violations = 0;
  bool finished = false;
  std::map<int64_t, int64_t> cycles_at_line;  // NC line -> cycles from the first to the last cycle of motion
};

// The programmed path: the motion blocks of a program as decoded.
struct ProgrammedPath {
  std::vector<PathSegment> segments;
  std::vector<int64_t> line;          // of each segment
  std::map<int64_t, bool> feed_line;  // NC line -> its motion is G01/G02/G03
  std::vector<int> main_axes;         // X Y Z
  double ideal_s = 0;
  std::map<int64_t, double> ideal_at_line;  // NC line -> its part of ideal_s
};

ProgrammedPath programmed_path(const std::string& program, const MachineConfig& machine,
                               const std::vector<double>& start) {
  ProgrammedPath path;
  for (size_t i = 0; i < machine.axes.size(); ++i)
    if (is_main_axis(machine.axes[i].name)) path.main_axes.push_back(static_cast<int>(i));
  const DecodedProgram decoded = decode_program(program, machine, start);
  if (decoded.error) std::printf("  decode error: %s\n", describe(*decoded.error).c_str());
  for (const Block& block : decoded.blocks) {
    if (!block.has_motion) continue;
    PathSegment segment(block.motion, machine);
    if (segment.length() <= 0) continue;
    const double ideal = segment.length() / std::min(segment.programmed_velocity(), segment.limits().v);
    path.ideal_s += ideal;
    path.ideal_at_line[block.nc_line] += ideal;
    path.feed_line[block.nc_line] = block.motion.type != MotionType::rapid;
    path.segments.push_back(std::move(segment));
    path.line.push_back(block.nc_line);
  }
  return path;
}

double distance_to(const PathSegment& segment, const std::vector<double>& point, const std::vector<int>& axes) {
  const double s = std::clamp(segment.length_to(point), 0.0, segment.length());
  const std::vector<double> on = segment.position(s);
  double sum = 0;
  for (int a : axes) sum += (on[a] - point[a]) * (on[a] - point[a]);
  return std::sqrt(sum);
}

Figures run(const MachineConfig& machine, const std::string& program, const ProgrammedPath& path,
            int64_t max_cycles) {
  Figures f;
  f.ideal_s = path.ideal_s;
  Channel channel(machine, program);
  logger::LimitChecker checker(machine);
  // The corpus scenarios' PLC: every M, H, S and T function acknowledged
  // two cycles after its request.
  Scenario plc_scenario;
  plc_scenario.m_function_ack_cycles = 2;
  plc::ScenarioEngine plc(plc_scenario);
  HliControl control;
  control.program_start = {true, true};
  int64_t first_moving = -1, last_moving = -1;
  size_t segment = 0;
  std::vector<double> cycle_us, cutting_velocity, previous;
  std::vector<int64_t> line_of_cycle;  // from the first cycle of motion
  std::vector<double> point(machine.axes.size());
  for (int64_t k = 0; k < max_cycles; ++k) {
    const auto before = std::chrono::steady_clock::now();
    channel.step(k, control);
    cycle_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - before).count());
    control = plc.cycle(channel.hli());
    const auto& sp = channel.setpoints();
    double v = 0;
    for (size_t i = 0; i < sp.size(); ++i) {
      checker.add_setpoint(static_cast<int>(i), k, sp[i].position);
      point[i] = sp[i].position;
      v += sp[i].velocity * sp[i].velocity;
    }
    v = std::sqrt(v);
    if (v > 0) {
      if (first_moving < 0) first_moving = k;
      last_moving = k;
    }
    if (first_moving >= 0 && point != previous) {
      // The nearest programmed motion around the interpolator's block (its
      // NC line; a closed contour's last line would else be as near as its
      // first at the start point).
      size_t from = segment >= 8 ? segment - 8 : 0, to = segment + 64;
      for (size_t s = from; s < path.segments.size() && s < from + 256; ++s)
        if (path.line[s] == channel.hli().block_count_r) {
          from = s >= 4 ? s - 4 : 0;
          to = s + 8;
          break;
        }
      double best = 1e300;
      size_t best_segment = segment;
      for (size_t s = from; s < path.segments.size() && s < to; ++s) {
        const double d = distance_to(path.segments[s], point, path.main_axes);
        if (d < best) {
          best = d;
          best_segment = s;
        }
      }
      segment = best_segment;
      if (!path.segments.empty()) f.max_deviation = std::max(f.max_deviation, best);
      previous = point;
    }
    if (first_moving >= 0) line_of_cycle.push_back(channel.hli().block_count_r);
    const auto line = path.feed_line.find(channel.hli().block_count_r);
    if (first_moving >= 0 && line != path.feed_line.end() && line->second) cutting_velocity.push_back(v);
    if (channel.finished()) {
      f.finished = true;
      break;
    }
  }
  f.time_s = first_moving < 0 ? 0 : (last_moving - first_moving + 1) * machine.cycle_time_s();
  for (int64_t k = 0; first_moving >= 0 && k <= last_moving - first_moving; ++k)
    ++f.cycles_at_line[line_of_cycle[static_cast<size_t>(k)]];
  double wall_us = 0;
  for (double us : cycle_us) wall_us += us;
  f.us_per_block = wall_us / static_cast<double>(std::max<size_t>(1, path.segments.size()));
  const auto at = [](std::vector<double>& values, double share) {
    if (values.empty()) return 0.0;
    const auto n = static_cast<size_t>(share * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n), values.end());
    return values[n];
  };
  f.cycle_p99_us = at(cycle_us, 0.99);
  if (!cycle_us.empty()) f.cycle_max_us = *std::max_element(cycle_us.begin(), cycle_us.end());
  f.v_median = at(cutting_velocity, 0.5);
  f.v_p5 = at(cutting_velocity, 0.05);
  f.violations = checker.finish().violations.size();
  return f;
}

// The program with `command` (one or two lines) after its first line with G90.
std::string with_after_g90(const std::string& program, const std::string& command) {
  std::istringstream in(program);
  std::string out, line;
  bool done = false;
  while (std::getline(in, line)) {
    out += line + "\n";
    if (!done && line.find("G90") != std::string::npos && line.find(';') > line.find("G90")) {
      out += command;
      done = true;
    }
  }
  return out;
}

// bench/linuxcnc/run.sh's table (program mode time_s v_med v_p5 dev_mm
// samples) for `names`: LinuxCNC's figures beside ours, a reference only.
struct ReferenceRow {
  std::string mode;
  double time_s = 0;
  std::string v_med, v_p5, dev;
};

std::map<std::string, std::vector<ReferenceRow>> linuxcnc_rows(const std::vector<std::string>& names) {
  std::string command = std::string(HIL_SOURCE_DIR) + "/bench/linuxcnc/run.sh";
  for (const std::string& name : names) command += " '" + name + "'";
  std::map<std::string, std::vector<ReferenceRow>> rows;
  FILE* out = popen(command.c_str(), "r");
  if (!out) return rows;
  char line[512];
  while (std::fgets(line, sizeof line, out)) {
    std::istringstream fields(line);
    std::string program;
    ReferenceRow row;
    std::string time;
    if (!(fields >> program >> row.mode >> time >> row.v_med >> row.v_p5 >> row.dev) || program == "program") continue;
    try {
      row.time_s = std::stod(time);
    } catch (const std::exception&) {
      continue;
    }
    rows[program].push_back(row);
  }
  pclose(out);
  return rows;
}

// The `count` NC lines of `program` whose time in the run exceeds their
// share of the ideal most, and what all lines together lose.
void print_losses(const Figures& f, const ProgrammedPath& path, const std::string& program, double cycle_s,
                  size_t count) {
  std::map<int64_t, double> lost;
  for (const auto& [line, ideal] : path.ideal_at_line) lost[line] = -ideal;
  for (const auto& [line, cycles] : f.cycles_at_line) lost[line] += static_cast<double>(cycles) * cycle_s;
  std::vector<std::pair<double, int64_t>> worst;
  for (const auto& [line, seconds] : lost) worst.emplace_back(seconds, line);
  std::sort(worst.rbegin(), worst.rend());
  std::vector<std::string> lines;
  std::stringstream in(program);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  for (size_t i = 0; i < worst.size() && i < count; ++i) {
    const auto [seconds, line] = worst[i];
    const auto ideal = path.ideal_at_line.find(line);
    const std::string text = line >= 1 && static_cast<size_t>(line) <= lines.size() ? lines[static_cast<size_t>(line) - 1] : "";
    std::printf("    line %-6lld %+8.3f s (ideal %.3f s)  %.60s\n", static_cast<long long>(line), seconds,
                ideal == path.ideal_at_line.end() ? 0.0 : ideal->second, text.c_str());
  }
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cam_programs: CAM programs as written, with G261 and with #HSC (issue 36, KRN-6, KRN-9)"};
  std::string programs =
      "surfacing_3d,engraving,plasma_profile,mixed_transitions,radius_arcs,public/jscut_jsdc,public/jscut_tball";
  std::string circles = "9,4,3", ways = "written,g261,hsc";
  std::string machine_file = std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml";
  double path_dev = 0.01, max_time_s = 1000;
  int chords = 10000;
  app.add_option("--programs", programs, "programs, comma separated: a file, or NAME of tests/programs/NAME.nc (public/NAME: real CAM output, "
                 "tests/programs/public/README.md)")
      ->capture_default_str();
  app.add_option("--circles", circles, "decimals of the 0.1 mm chord circles, comma separated; empty: none")
      ->capture_default_str();
  app.add_option("--chords", chords, "chords of each circle")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--ways", ways, "written (as written: at a corner an exact stop unless the program selects G61 / G261 there), g261, hsc; comma separated")->capture_default_str();
  app.add_option("--path-dev", path_dev, "PATH_DEV of G261 and #HSC, mm")->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--machine", machine_file, "machine file")->capture_default_str();
  double jerk_factor = 1;
  app.add_option("--jerk-factor", jerk_factor,
                 "every axis' j_max times this (100: acceleration-limited in effect, like LinuxCNC's planner; the "
                 "limit check then holds the scaled jerk)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  bool linuxcnc = false;
  app.add_flag("--linuxcnc", linuxcnc,
               "also run the programs on LinuxCNC's simulator (bench/linuxcnc/run.sh; Debian's linuxcnc-uspace, a "
               "reference only) and print its G61 and G64 figures beside ours");
  app.add_option("--max-time", max_time_s, "program time at which a run is cut, s")->capture_default_str();
  size_t losses = 0;
  app.add_option("--losses", losses,
                 "after each run, the N NC lines whose time exceeds their share of the ideal most (where a program "
                 "loses its time: corners, stops, slow curves)")
      ->capture_default_str();
  app.footer("Documentation: docs/HSC.md and docs/PERFORMANCE.md in the source tree");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  MachineConfig machine = parse_machine_config(YAML::LoadFile(machine_file));
  for (AxisConfig& axis : machine.axes) axis.j_max *= jerk_factor;
  const auto max_cycles = static_cast<int64_t>(max_time_s / machine.cycle_time_s());

  std::vector<std::pair<std::string, std::string>> sources;  // name, program as written
  for (const std::string& d : split(circles)) {
    bench::ChordCircle circle;
    circle.chords = chords;
    circle.decimals = std::stoi(d);
    sources.emplace_back("chord_circle_" + d + "dec", circle.program(bench::Smoothing::none));
  }
  for (const std::string& name : split(programs)) {
    const std::string path =
        std::filesystem::exists(name) ? name : std::string(HIL_SOURCE_DIR) + "/tests/programs/" + name + ".nc";
    std::ifstream in(path);
    if (!in) {
      std::fprintf(stderr, "cam_programs: cannot read %s\n", path.c_str());
      return 2;
    }
    std::stringstream text;
    text << in.rdbuf();
    sources.emplace_back(name, text.str());
  }

  std::map<std::string, std::vector<ReferenceRow>> reference;
  if (linuxcnc) {
    std::vector<std::string> names;
    for (const auto& source : sources) names.push_back(source.first);
    reference = linuxcnc_rows(names);
    if (reference.empty()) std::printf("LinuxCNC gave no figures (bench/linuxcnc/README.md)\n");
  }
  char dev[64], jerk[64] = "";
  std::snprintf(dev, sizeof dev, "%.6g", path_dev);
  if (jerk_factor != 1) std::snprintf(jerk, sizeof jerk, " (j_max x %g)", jerk_factor);
  std::printf("machine %s%s, PATH_DEV %s mm; time: first to last cycle of motion; v: path velocity in G01/G02/G03, "
              "mm/s; dev: largest distance from the programmed path, mm\n",
              machine.name.c_str(), jerk, dev);
  std::printf("%-26s %-9s %8s %8s %7s %7s %7s %9s %5s %9s %9s %9s\n", "program", "way", "time_s", "ideal_s", "x_ideal",
              "v_med", "v_p5", "dev_mm", "viol", "us/block", "p99_us", "max_us");
  std::vector<double> start;
  {
    const Channel idle(machine, std::string("M30\n"));
    for (const auto& s : idle.setpoints()) start.push_back(s.position);
  }
  for (const auto& [name, program] : sources) {
    const double ideal_s = programmed_path(program, machine, start).ideal_s;
    for (const std::string& way : split(ways)) {
      std::string text = program;
      if (way == "g261") text = with_after_g90(program, std::string("#CONTOUR MODE [DEV PATH_DEV=") + dev + "]\nG261\n");
      else if (way == "hsc") text = with_after_g90(program, std::string("#HSC ON [BSPLINE PATH_DEV=") + dev + " MERGE=1]\n");
      else if (way == "hsc+g261")
        text = with_after_g90(program, std::string("#CONTOUR MODE [DEV PATH_DEV=") + dev + "]\nG261\n#HSC ON [BSPLINE PATH_DEV=" +
                                           dev + " MERGE=1]\n");
      else if (way != "written") {
        std::fprintf(stderr, "cam_programs: unknown way %s\n", way.c_str());
        return 2;
      }
      // Decoded as run: the added lines shift the NC lines the interpolator shows.
      const ProgrammedPath path = programmed_path(text, machine, start);
      const Figures f = run(machine, text, path, max_cycles);
      std::printf("%-26s %-9s %8.2f %8.2f %6.2fx %7.1f %7.1f %9.5f %5zu %9.1f %9.0f %9.0f%s\n", name.c_str(),
                  way.c_str(), f.time_s, f.ideal_s, f.time_s / f.ideal_s, f.v_median, f.v_p5, f.max_deviation,
                  f.violations, f.us_per_block, f.cycle_p99_us, f.cycle_max_us, f.finished ? "" : "  (cut at --max-time)");
      if (losses > 0) print_losses(f, path, text, machine.cycle_time_s(), losses);
      std::fflush(stdout);
    }
    const auto ref = reference.find(std::filesystem::path(name).stem().string());  // as bench.py names it
    if (ref == reference.end()) continue;
    for (const ReferenceRow& row : ref->second)
      std::printf("%-26s %-9s %8.2f %8.2f %6.2fx %7s %7s %9s %5s %9s %9s\n", name.c_str(), ("lcnc_" + row.mode).c_str(),
                  row.time_s, ideal_s, row.time_s / ideal_s, row.v_med.c_str(), row.v_p5.c_str(), row.dev.c_str(), "-",
                  "-", "-");
  }
  return 0;
}
