#include "variant_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "plot_export.hpp"
#include "process.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

std::string num(double v, int digits = 3) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

int axis_of(const VariantFigures& v, const std::string& axis) {
  for (size_t i = 0; i < v.axes.size(); ++i)
    if (v.axes[i] == axis) return static_cast<int>(i);
  return -1;
}

const VariantFigures* variant_named(const std::vector<VariantFigures>& variants, const std::string& name) {
  for (const VariantFigures& v : variants)
    if (v.name == name) return &v;
  return nullptr;
}

// The commanded path: the setpoints (AXIS_<X>_CMD, the positions the drives
// are given) and dist_prog_start of the same cycle, both written by one
// interpolation step of the CNC.
logger::PathTrace path_trace(const logger::RunLog& log) {
  logger::PathTrace p;
  const MachineConfig& machine = log.scenario->machine;
  const size_t n = std::min(machine.axes.size(), log.axes.size());
  std::vector<std::map<int64_t, double>> by_cycle(n);
  for (size_t a = 0; a < n; ++a) {
    p.axes.push_back(machine.axes[a].name);
    p.modulo_range.push_back(machine.axes[a].modulo ? machine.axes[a].modulo_range() : 0.0);
    for (size_t i = 0; i < log.axes[a].cmd_cycle.size(); ++i)
      by_cycle[a][log.axes[a].cmd_cycle[i]] = log.axes[a].cmd_position[i];
  }
  p.position.resize(n);
  // A cycle's HLI state once, in cycle order; not the cycles off the
  // program's path: READY (before a start, after a reset) and a block
  // search's repositioning (DPS-3: the approach covers no distance).
  std::map<int64_t, double> dist;
  for (size_t i = 0; i < log.hli.cycle.size(); ++i)
    if (static_cast<ChannelState>(log.hli.channel_state[i]) != ChannelState::ready &&
        log.hli.block_search_state[i] != block_search_state::repositioning)
      dist.emplace(log.hli.cycle[i], log.hli.dist_prog_start_mm[i]);
  for (const auto& [cycle, d] : dist) {
    bool all = true;
    for (size_t a = 0; a < n; ++a) all = all && by_cycle[a].count(cycle);
    if (!all) continue;
    p.cycle.push_back(cycle);
    p.dist_mm.push_back(d);
    for (size_t a = 0; a < n; ++a) p.position[a].push_back(by_cycle[a][cycle]);
  }
  return p;
}

std::string same_path_line(const std::vector<VariantFigures>& variants, const VariantComparison& c, bool& holds) {
  const VariantFigures* reference = variant_named(variants, c.reference);
  const VariantFigures* variant = variant_named(variants, c.variant);
  std::string line = "compare same_path " + c.variant + " against " + c.reference + " (dist_prog_start > " +
                     num(c.from_dist_mm, 4) + " mm, tolerance " + num(c.tolerance_mm * 1000, 3) + " µm): ";
  if (!reference || !variant) {
    holds = false;
    return line + "FAILS (no figures of " + c.reference + " or " + c.variant + ")\n";
  }
  const logger::SamePathResult r =
      logger::compare_same_path(reference->path, variant->path, c.from_dist_mm, c.tolerance_mm);
  holds = r.holds;
  return line + logger::describe(r) + ": " + (r.holds ? "holds" : "FAILS") + "\n";
}

}  // namespace

VariantFigures figures_of(const std::string& name, bool passed, const logger::RunLog& log,
                          const logger::CheckReport* check) {
  VariantFigures f;
  f.name = name;
  f.passed = passed;
  if (!log.scenario) return f;
  const MachineConfig& machine = log.scenario->machine;
  const double dt = machine.cycle_time_s();
  std::map<int64_t, double> dist;
  std::optional<int64_t> active, end;
  for (size_t i = 0; i < log.hli.cycle.size(); ++i) {
    dist[log.hli.cycle[i]] = log.hli.dist_prog_start_mm[i];
    const auto state = static_cast<ChannelState>(log.hli.channel_state[i]);
    if (state == ChannelState::active && !active) active = log.hli.cycle[i];
    if (state == ChannelState::program_end && active && !end) end = log.hli.cycle[i];
  }
  if (active && end) f.path_time_s = (*end - *active) * dt;
  for (size_t a = 0; a < machine.axes.size() && a < log.axes.size(); ++a) {
    const logger::AxisTrace& t = log.axes[a];
    f.axes.push_back(machine.axes[a].name);
    f.a_max.push_back(machine.axes[a].a_max);
    f.a_err_limit.push_back(machine.axes[a].accel_error_limit());
    double hi = -INFINITY, lo = INFINITY;
    for (double p : t.cmd_position) hi = std::max(hi, p), lo = std::min(lo, p);
    f.max_mm.push_back(t.cmd_position.empty() ? NAN : hi);
    f.min_mm.push_back(t.cmd_position.empty() ? NAN : lo);
    double lift_a = 0;
    if (check)
      for (const auto& s : check->axes)
        if (s.axis == machine.axes[a].name) lift_a = s.cmd_a_lift;
    f.lift_a.push_back(lift_a);
  }
  // The plot's samples: the cycles of the first axis' setpoints.
  if (!log.axes.empty()) {
    const std::vector<int64_t>& cycles = log.axes.front().cmd_cycle;
    f.position.resize(f.axes.size());
    std::vector<std::map<int64_t, double>> by_cycle(f.axes.size());
    for (size_t a = 0; a < f.axes.size(); ++a)
      for (size_t i = 0; i < log.axes[a].cmd_cycle.size(); ++i)
        by_cycle[a][log.axes[a].cmd_cycle[i]] = log.axes[a].cmd_position[i];
    double last_dist = 0;
    for (int64_t c : cycles) {
      if (const auto d = dist.find(c); d != dist.end()) last_dist = d->second;
      f.t_s.push_back(c * dt);
      f.dist_mm.push_back(last_dist);
      for (size_t a = 0; a < f.axes.size(); ++a) {
        const auto p = by_cycle[a].find(c);
        f.position[a].push_back(p == by_cycle[a].end() ? NAN : p->second);
      }
    }
  }
  f.path = path_trace(log);
  return f;
}

std::string check_comparisons(const std::vector<VariantFigures>& variants,
                              const std::vector<VariantComparison>& comparisons, bool& all_hold) {
  std::ostringstream out;
  all_hold = true;
  for (const VariantComparison& c : comparisons) {
    if (c.key == "same_path") {
      bool holds = false;
      out << same_path_line(variants, c, holds);
      all_hold = all_hold && holds;
      continue;
    }
    const VariantFigures* g = variant_named(variants, c.greater);
    const VariantFigures* t = variant_named(variants, c.than);
    const int ga = g ? axis_of(*g, c.axis) : -1, ta = t ? axis_of(*t, c.axis) : -1;
    const bool max = c.key == "axis_max_mm";
    std::string what = std::string(max ? "highest " : "lowest ") + c.axis;
    if (ga < 0 || ta < 0) {
      all_hold = false;
      out << "compare " << what << ": FAILS (no figures of " << c.greater << " or " << c.than << ")\n";
      continue;
    }
    const double a = max ? g->max_mm[ga] : g->min_mm[ga], b = max ? t->max_mm[ta] : t->min_mm[ta];
    // axis_min_mm: "greater" is the one that went further down (DOWN lifts).
    const double margin = max ? a - b : b - a;
    const bool holds = std::isfinite(margin) && margin > c.by_at_least_mm;
    all_hold = all_hold && holds;
    out << "compare " << what << ": " << c.greater << " " << num(a) << " mm " << (max ? ">" : "<") << " "
        << c.than << " " << num(b) << " mm";
    if (c.by_at_least_mm > 0) out << " by more than " << num(c.by_at_least_mm) << " mm";
    out << " (difference " << num(margin) << " mm): " << (holds ? "holds" : "FAILS") << '\n';
  }
  return out.str();
}

std::string format_variants(const std::vector<VariantFigures>& variants) {
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "  %-34s", "variant");
  out << line;
  for (const VariantFigures& v : variants) {
    std::snprintf(line, sizeof line, " %18s", v.name.c_str());
    out << line;
  }
  out << '\n';
  auto row = [&](const std::string& label, auto value) {
    std::snprintf(line, sizeof line, "  %-34s", label.c_str());
    out << line;
    for (const VariantFigures& v : variants) {
      std::snprintf(line, sizeof line, " %18s", value(v).c_str());
      out << line;
    }
    out << '\n';
  };
  row("verdict", [](const VariantFigures& v) { return std::string(v.passed ? "PASSED" : "FAILED"); });
  row("path time (ACTIVE..PROGRAM_END) [s]",
      [](const VariantFigures& v) { return v.path_time_s ? num(*v.path_time_s) : std::string("-"); });
  if (variants.empty()) return out.str();
  for (const std::string& axis : variants.front().axes) {
    auto per_axis = [&](auto pick) {
      return [&, pick](const VariantFigures& v) {
        const int a = axis_of(v, axis);
        return a < 0 ? std::string("-") : pick(v, a);
      };
    };
    row("highest commanded " + axis + " [mm]", per_axis([](const VariantFigures& v, int a) { return num(v.max_mm[a]); }));
    row("lowest commanded " + axis + " [mm]", per_axis([](const VariantFigures& v, int a) { return num(v.min_mm[a]); }));
    row("lifting |a| " + axis + " [mm/s^2]", per_axis([](const VariantFigures& v, int a) {
          return num(v.lift_a[a], 1) + " (" + num(v.a_max[a] > 0 ? v.lift_a[a] / v.a_max[a] : 0, 2) + " a_max)";
        }));
  }
  return out.str();
}

std::string draw_comparison_plots(const std::string& scenario_name, const std::vector<VariantFigures>& variants,
                                  const std::vector<VariantComparison>& comparisons, const std::string& dir,
                                  std::vector<std::string>* drawn) {
  std::vector<std::string> axes;
  bool all_axes = comparisons.empty();
  for (const VariantComparison& c : comparisons) {
    if (c.key == "same_path") all_axes = true;  // a path is all axes
    else if (std::find(axes.begin(), axes.end(), c.axis) == axes.end()) axes.push_back(c.axis);
  }
  if (all_axes && !variants.empty())
    for (const std::string& a : variants.front().axes)
      if (std::find(axes.begin(), axes.end(), a) == axes.end()) axes.push_back(a);
  fs::create_directories(dir);
  const fs::path folder = fs::absolute(dir);
  for (const VariantFigures& v : variants) {
    std::ofstream data(folder / ("compare_" + v.name + ".tsv"));
    data.precision(10);
    data << "# t_s\tdist_prog_start_mm";
    for (const std::string& a : v.axes) data << '\t' << a;
    data << '\n';
    for (size_t i = 0; i < v.t_s.size(); ++i) {
      data << v.t_s[i] << '\t' << v.dist_mm[i];
      for (const auto& p : v.position) data << '\t' << (std::isfinite(p[i]) ? num(p[i], 6) : std::string("?"));
      data << '\n';
    }
  }
  std::ofstream gp(folder / "compare.gp");
  gp << "# The variants side by side: gnuplot compare.gp (in this folder)\n"
        "set terminal pngcairo noenhanced size 1400,1000 font \",10\"\n"
        "set datafile separator \"\\t\"\nset datafile missing \"?\"\nset grid\nset key outside right top\n"
        "set lmargin 14\nset rmargin 30\n";
  std::string images;
  for (const std::string& axis : axes) {
    const std::string image = "compare_" + axis + ".png";
    images += (images.empty() ? "" : ", ") + image;
    gp << "\nset output " << logger::gnuplot_quoted(image) << "\nset multiplot layout 2,1 title "
       << logger::gnuplot_quoted(scenario_name + ": commanded " + axis + " of each variant") << '\n';
    for (const char* x : {"t", "path"}) {
      const bool over_time = std::string(x) == "t";
      gp << "set xlabel " << logger::gnuplot_quoted(over_time ? "t [s]" : "dist_prog_start [mm]") << "\nset ylabel "
         << logger::gnuplot_quoted(axis + " [mm]") << "\nplot ";
      bool first = true;
      for (const VariantFigures& v : variants) {
        const int a = axis_of(v, axis);
        if (a < 0) continue;
        gp << (first ? "" : ", ") << logger::gnuplot_quoted("compare_" + v.name + ".tsv") << " u " << (over_time ? 1 : 2) << ':'
           << a + 3 << " w l lw 2 t " << logger::gnuplot_quoted(v.name + " (max " + num(v.max_mm[a]) + ")");
        first = false;
      }
      gp << '\n';
    }
    gp << "unset multiplot\n";
  }
  gp.close();
  std::string cd = "cd '";
  for (char c : folder.string()) cd += c == '\'' ? std::string("''") : std::string(1, c);
  cd += "'";
  Process gnuplot("gnuplot", {"gnuplot", "-e", cd, (folder / "compare.gp").string()},
                  (folder / "compare_gnuplot.out").string());
  const std::optional<int> status = gnuplot.wait_for(std::chrono::seconds(120));
  const int code = status ? *status : gnuplot.stop();
  if (code == 127) return "comparison plot: gnuplot not found; data and script in " + dir;
  if (code != 0) return "comparison plot: gnuplot failed (" + (folder / "compare_gnuplot.out").string() + ")";
  for (const std::string& axis : axes)
    if (drawn) drawn->push_back((folder / ("compare_" + axis + ".png")).string());
  return "comparison plot: " + dir + "/ (" + images + ")";
}

}  // namespace hil::rig
