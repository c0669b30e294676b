#pragma once
// Plots of a run (RIG-4): writes the traces of a RunLog as tab-separated
// data and a gnuplot script that draws, per axis, position, velocity,
// acceleration (with their limit lines) and following error, and the path
// velocity and HLI signals (block_nr_r, dist_prog_start). Episodes of limit
// violations are shaded. Running gnuplot is the caller's business.
#include <string>
#include <vector>

#include "limit_check.hpp"
#include "run_log.hpp"

namespace hil::logger {

struct PlotFiles {
  std::string script;               // gnuplot script, run from its folder
  std::vector<std::string> images;  // the PNGs it draws: axis_<X>.png ..., path.png
};

// Writes into `dir` (created if needed). Throws std::runtime_error if the
// log has no manifest (nothing to name the axes and limits).
PlotFiles write_plot_files(const RunLog& log, const CheckReport& report, const std::string& dir);

// A text as a gnuplot string literal ("..", with \" and \\ escaped).
std::string gnuplot_quoted(const std::string& text);

}  // namespace hil::logger
