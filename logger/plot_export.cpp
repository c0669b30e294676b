#include "plot_export.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

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
  out << "# t_s\tpath_velocity\tblock_nr_r\tdist_prog_start_mm\tchannel_state\n";
  for (size_t i = 0; i < h.cycle.size(); ++i)
    out << h.cycle[i] * dt << '\t' << h.path_velocity[i] << '\t' << h.block_nr_r[i] << '\t'
        << h.dist_prog_start_mm[i] << '\t' << h.channel_state[i] << '\n';
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
  gp << "# Draws the run's plots: gnuplot plots.gp (in this folder)\n"
        "set terminal pngcairo noenhanced size 1400,1500 font \",10\"\n"
        "set datafile separator \"\\t\"\nset datafile missing \"?\"\n"
        "set termoption noenhanced\nset grid\nset key outside right top\nset xlabel \"t [s]\"\n"
        "set lmargin 14\nset rmargin 28\n";
  const std::string run_name = log.scenario->name;
  for (size_t i = 0; i < machine.axes.size() && i < log.axes.size(); ++i) {
    const AxisConfig& a = machine.axes[i];
    const std::string data = "axis_" + a.name + ".tsv", image = "axis_" + a.name + ".png";
    write_axis_data(log.axes[i], dt, (fs::path(dir) / data).string());
    files.images.push_back((fs::path(dir) / image).string());
    gp << "\nset output " << gnuplot_quoted(image) << "\nunset object\n";
    int shaded = 0;
    for (const Violation& v : report.violations)
      if (v.axis == a.name)
        gp << "set object " << ++shaded << " rect from " << v.time_s - dt / 2 << ", graph 0 to "
           << v.end_time_s + dt / 2 << ", graph 1 fc rgb \"#ffb0b0\" fs solid 0.6 noborder behind\n";
    gp << "set multiplot layout 4,1 title "
       << gnuplot_quoted(run_name + ": axis " + a.name + (shaded ? " (limit violations shaded red)" : "")) << "\n"
       << "set ylabel \"position [mm]\"\n"
       << "plot " << gnuplot_quoted(data) << " u 1:2 w l lw 2 t \"commanded\", '' u 1:5 w l t \"actual\"\n"
       << "set ylabel \"velocity [mm/s]\"\n"
       << "plot " << gnuplot_quoted(data) << " u 1:3 w l lw 2 t \"commanded\", '' u 1:6 w l t \"actual\""
       << limit_lines(a.v_max, "#808080", "v_max") << limit_lines(a.velocity_error_limit(), "red", "P-AXIS-00440")
       << "\nset ylabel \"acceleration [mm/s^2]\"\n"
       << "plot " << gnuplot_quoted(data) << " u 1:4 w l lw 2 t \"commanded\", '' u 1:7 w l t \"actual\""
       << limit_lines(a.a_max, "#808080", "a_max") << limit_lines(a.accel_error_limit(), "red", "P-AXIS-00442")
       << "\nset ylabel \"following error [mm]\"\n"
       << "plot " << gnuplot_quoted(data) << " u 1:8 w l t \"following error\""
       << limit_lines(a.slep_max, "red", "P-AXIS-00168 slep_max") << "\nunset multiplot\n";
  }
  const int ix = machine.axis_index("X"), iy = machine.axis_index("Y");
  if (ix >= 0 && iy >= 0 && static_cast<size_t>(std::max(ix, iy)) < log.axes.size()) {
    write_xy_data(log.axes[ix], log.axes[iy], (fs::path(dir) / "xy.tsv").string());
    files.images.push_back((fs::path(dir) / "xy.png").string());
    gp << "\nset output \"xy.png\"\nunset object\nset terminal pngcairo noenhanced size 1000,1000 font \",10\"\n"
       << "set title " << gnuplot_quoted(run_name + ": contour in the XY plane") << "\nset size ratio -1\n"
       << "set xlabel \"X [mm]\"\nset ylabel \"Y [mm]\"\n"
       << "plot \"xy.tsv\" u 1:2 w l lw 2 t \"commanded\", '' u 3:4 w l t \"actual\"\n"
       << "set size noratio\nunset title\nset xlabel \"t [s]\"\n"
       << "set terminal pngcairo noenhanced size 1400,1500 font \",10\"\n";
  }
  write_hli_data(log.hli, dt, (fs::path(dir) / "hli.tsv").string());
  files.images.push_back((fs::path(dir) / "path.png").string());
  gp << "\nset output \"path.png\"\nunset object\n"
     << "set multiplot layout 4,1 title " << gnuplot_quoted(run_name + ": path and HLI") << "\n"
     << "set ylabel \"path velocity [mm/s]\"\nplot \"hli.tsv\" u 1:2 w l t \"path_velocity\"\n"
     << "set ylabel \"block_nr_r\"\nplot \"hli.tsv\" u 1:3 w steps t \"block_nr_r\"\n"
     << "set ylabel \"dist_prog_start [mm]\"\nplot \"hli.tsv\" u 1:4 w l t \"dist_prog_start\"\n"
     << "set ylabel \"channel_state\"\nset ytics (\"READY\" 0, \"ACTIVE\" 1, \"PROGRAM_END\" 2, \"ERROR\" 3)\n"
     << "set yrange [-0.5:3.5]\nplot \"hli.tsv\" u 1:5 w steps t \"channel_state\"\n"
     << "unset multiplot\n";
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
