#include "plot_export.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "hli.hpp"

namespace hil::logger {
namespace {

namespace fs = std::filesystem;

// Commanded and actual samples joined by cycle; '?' where one is missing.
void write_axis_data(const AxisTrace& t, double dt, const std::string& path) {
  std::ofstream out(path);
  out.precision(10);
  out << "# t_s\tcmd_position\tcmd_velocity\tcmd_acceleration\tposition\tvelocity\tacceleration\tfollowing_error\n";
  std::map<int64_t, size_t> actual;
  for (size_t i = 0; i < t.act_cycle.size(); ++i) actual[t.act_cycle[i]] = i;
  for (size_t i = 0; i < t.cmd_cycle.size(); ++i) {
    out << t.cmd_cycle[i] * dt << '\t' << t.cmd_position[i] << '\t' << t.cmd_velocity[i] << '\t'
        << t.cmd_acceleration[i];
    const auto a = actual.find(t.cmd_cycle[i]);
    if (a == actual.end()) {
      out << "\t?\t?\t?\t?\n";
      continue;
    }
    const size_t k = a->second;
    out << '\t' << t.act_position[k] << '\t' << t.act_velocity[k] << '\t' << t.act_acceleration[k] << '\t'
        << t.following_error[k] << '\n';
  }
}

// The contour in the XY plane: commanded and actual, by cycle.
void write_xy_data(const AxisTrace& x, const AxisTrace& y, const std::string& path) {
  std::ofstream out(path);
  out.precision(10);
  out << "# cmd_x\tcmd_y\tx\ty\n";
  const size_t n = std::min(x.cmd_cycle.size(), y.cmd_cycle.size());
  const size_t m = std::min(x.act_cycle.size(), y.act_cycle.size());
  for (size_t i = 0; i < n; ++i) {
    out << x.cmd_position[i] << '\t' << y.cmd_position[i];
    if (i < m) out << '\t' << x.act_position[i] << '\t' << y.act_position[i] << '\n';
    else out << "\t?\t?\n";
  }
}

void write_hli_data(const HliTrace& h, double dt, const std::string& path) {
  std::ofstream out(path);
  out.precision(10);
  out << "# t_s\tpath_velocity\tblock_nr_r\tdist_prog_start_mm\tchannel_state\tstop_conditions_r\toverride_percent\n";
  for (size_t i = 0; i < h.cycle.size(); ++i)
    out << h.cycle[i] * dt << '\t' << h.path_velocity[i] << '\t' << h.block_nr_r[i] << '\t'
        << h.dist_prog_start_mm[i] << '\t' << h.channel_state[i] << '\t' << h.stop_conditions[i] << '\t'
        << h.override_percent[i] << '\n';
}

// Commanded thick and translucent, actual thin and dark on top: both seen
// where they coincide (issue 37: they merged into one line).
std::string commanded_and_actual(const std::string& data, int commanded, int actual) {
  return gnuplot_quoted(data) + " u 1:" + std::to_string(commanded) +
         " w l lw 4 lc rgb \"#801f77b4\" t \"commanded\", '' u 1:" + std::to_string(actual) +
         " w l lw 1 lc rgb \"#000000\" t \"actual\"";
}

// The cycles where plc_sim judged an expectation: a dotted line each, green
// PASS, red FAIL, across a figure's panels.
std::string verdict_lines(const RunLog& log, double dt) {
  std::string out;
  for (const LoggedEvent& e : log.events) {
    if (e.event.verdict == Verdict::none) continue;
    const std::string t = std::to_string(static_cast<double>(e.cycle) * dt);
    out += "set arrow from " + t + ", graph 0 to " + t + ", graph 1 nohead dt 3 lw 1.5 lc rgb " +
           (e.event.verdict == Verdict::pass ? "\"#2ca02c\"" : "\"#d62728\"") + " front\n";
  }
  return out;
}

// A figure drawn twice, from its own script: PNG for the folder and the
// text report, SVG for report.html (zoomable there).
void draw_twice(std::ofstream& gp, const std::string& name, const std::string& size, const std::string& figure,
                const std::string& dir, PlotFiles& files) {
  std::ofstream(fs::path(dir) / (name + ".gp")) << figure;
  gp << "\nset terminal pngcairo noenhanced size " << size << " font \",10\"\nset output " << gnuplot_quoted(name + ".png")
     << "\nload " << gnuplot_quoted(name + ".gp") << "\nset terminal svg noenhanced size " << size
     << " dynamic font \",10\"\nset output " << gnuplot_quoted(name + ".svg") << "\nload "
     << gnuplot_quoted(name + ".gp") << "\n";
  files.images.push_back((fs::path(dir) / (name + ".png")).string());
}

// A pair of dashed limit lines at ±value.
std::string limit_lines(double value, const std::string& color, const std::string& title) {
  if (!(value > 0)) return "";
  const std::string v = std::to_string(value);
  return ", " + v + " w l dt 2 lc rgb " + gnuplot_quoted(color) + " t " + gnuplot_quoted(title) + ", -" + v +
         " w l dt 2 lc rgb " + gnuplot_quoted(color) + " notitle";
}

}  // namespace

PlotFiles write_plot_files(const RunLog& log, const CheckReport& report, const std::string& dir) {
  if (!log.scenario) throw std::runtime_error("the log has no manifest: no axes and limits to plot");
  const MachineConfig& machine = log.scenario->machine;
  const double dt = machine.cycle_time_s();
  fs::create_directories(dir);
  PlotFiles files;
  files.script = (fs::path(dir) / "plots.gp").string();
  std::ofstream gp(files.script);
  gp << "# Draws the run's plots: gnuplot plots.gp (in this folder); each figure's own script is <name>.gp\n"
        "set datafile separator \"\\t\"\nset datafile missing \"?\"\n"
        "set termoption noenhanced\nset grid\nset key outside right top\nset xlabel \"t [s]\"\n"
        "set lmargin 18\nset rmargin 28\n";
  const std::string run_name = log.scenario->name;
  for (size_t i = 0; i < machine.axes.size() && i < log.axes.size(); ++i) {
    const AxisConfig& a = machine.axes[i];
    const std::string data = "axis_" + a.name + ".tsv";
    write_axis_data(log.axes[i], dt, (fs::path(dir) / data).string());
    std::ostringstream f;
    f << "unset object\nunset arrow\n";
    int shaded = 0;
    for (const Violation& v : report.violations)
      if (v.axis == a.name)
        f << "set object " << ++shaded << " rect from " << v.time_s - dt / 2 << ", graph 0 to "
          << v.end_time_s + dt / 2 << ", graph 1 fc rgb \"#ffb0b0\" fs solid 0.6 noborder behind\n";
    f << "set multiplot layout 4,1 title "
      << gnuplot_quoted(run_name + ": axis " + a.name + (shaded ? " (limit violations shaded red)" : "")) << "\n"
      << "set ylabel \"position [mm]\"\n"
      << "plot " << commanded_and_actual(data, 2, 5) << "\n"
      << "set ylabel \"velocity [mm/s]\"\n"
      << "plot " << commanded_and_actual(data, 3, 6) << limit_lines(a.v_max, "#808080", "v_max")
      << limit_lines(a.velocity_error_limit(), "red", "P-AXIS-00440") << "\nset ylabel \"acceleration [mm/s^2]\"\n"
      << "plot " << commanded_and_actual(data, 4, 7) << limit_lines(a.a_max, "#808080", "a_max")
      << limit_lines(a.accel_error_limit(), "red", "P-AXIS-00442") << "\nset ylabel \"following error [mm]\"\n"
      << "plot " << gnuplot_quoted(data) << " u 1:8 w l lc rgb \"#000000\" t \"following error\""
      << limit_lines(a.slep_max, "red", "P-AXIS-00168 slep_max") << "\nunset multiplot\n";
    draw_twice(gp, "axis_" + a.name, "1400,1500", f.str(), dir, files);
  }
  const int ix = machine.axis_index("X"), iy = machine.axis_index("Y");
  if (ix >= 0 && iy >= 0 && static_cast<size_t>(std::max(ix, iy)) < log.axes.size()) {
    write_xy_data(log.axes[ix], log.axes[iy], (fs::path(dir) / "xy.tsv").string());
    std::ostringstream f;
    f << "unset object\nunset arrow\nset title " << gnuplot_quoted(run_name + ": contour in the XY plane")
      << "\nset size ratio -1\nset xlabel \"X [mm]\"\nset ylabel \"Y [mm]\"\n"
      << "plot \"xy.tsv\" u 1:2 w l lw 4 lc rgb \"#801f77b4\" t \"commanded\", '' u 3:4 w l lw 1 lc rgb \"#000000\" "
         "t \"actual\"\n"
      << "set size noratio\nunset title\nset xlabel \"t [s]\"\n";
    draw_twice(gp, "xy", "1000,1000", f.str(), dir, files);
  }
  write_hli_data(log.hli, dt, (fs::path(dir) / "hli.tsv").string());
  // The stop conditions the run had, one row each where set (issue 37: the PLC's signals).
  std::vector<std::pair<int32_t, std::string>> stops;
  int32_t seen = 0;
  for (const int32_t bits : log.hli.stop_conditions) seen |= bits;
  for (const StopConditionName& c : stop_condition_names())
    if (seen & c.bit) stops.emplace_back(c.bit, c.name);
  std::ostringstream f;
  f << "unset object\nunset arrow\n" << verdict_lines(log, dt) << "set multiplot layout 5,1 title "
    << gnuplot_quoted(run_name + ": path, HLI and PLC (dotted: where an expectation was judged, green PASS, red FAIL)")
    << "\nset ylabel \"path velocity [mm/s]\"\nset y2label \"override [%]\"\nset y2tics\nset ytics nomirror\nset y2range [0:*]\n"
    << "plot \"hli.tsv\" u 1:2 w l lw 1.5 lc rgb \"#1f77b4\" t \"path_velocity\", '' u 1:7 axes x1y2 w steps lc rgb "
       "\"#9467bd\" t \"override.state_r\"\n"
    << "unset y2tics\nunset y2label\nset ytics mirror\n"
    << "set ylabel \"block_nr_r\"\nplot \"hli.tsv\" u 1:3 w steps lc rgb \"#000000\" t \"block_nr_r\"\n"
    << "set ylabel \"dist_prog_start [mm]\"\nplot \"hli.tsv\" u 1:4 w l lc rgb \"#000000\" t \"dist_prog_start\"\n"
    << "unset ylabel\nset ytics (\"READY\" 0, \"ACTIVE\" 1, \"PROGRAM_END\" 2, \"ERROR\" 3)\n"
    << "set yrange [-0.5:3.5]\nplot \"hli.tsv\" u 1:5 w steps lc rgb \"#000000\" t \"channel_state\"\n";
  f << "unset ylabel\n";
  if (stops.empty()) {
    f << "set ytics (\"none\" 0)\nset yrange [-0.5:0.5]\nplot \"hli.tsv\" u 1:(0) w l lc rgb \"#808080\" t \"stop_conditions_r: none\"\n";
  } else {
    f << "set ytics (";
    for (size_t k = 0; k < stops.size(); ++k) f << (k ? ", " : "") << gnuplot_quoted(stops[k].second) << " " << k;
    f << ")\nset yrange [-0.5:" << static_cast<double>(stops.size()) - 0.5 << "]\nplot ";
    for (size_t k = 0; k < stops.size(); ++k)
      f << (k ? ", " : "") << "\"hli.tsv\" u 1:((int($6) & " << stops[k].first << ") ? " << k << " : 1/0) w p pt 5 ps 0.3 t "
        << gnuplot_quoted("stop_conditions_r " + stops[k].second);
    f << "\n";
  }
  f << "unset multiplot\nset ytics autofreq\nset yrange [*:*]\nunset arrow\n";
  draw_twice(gp, "path", "1400,1800", f.str(), dir, files);
  return files;
}

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace hil::logger
