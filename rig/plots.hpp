#pragma once
// Draws a run's plots with gnuplot (RIG-4): the data and script from
// logger/plot_export, the PNGs next to them.
#include <string>
#include <vector>

#include "limit_check.hpp"
#include "run_log.hpp"

namespace hil::rig {

// Writes the plots into `dir`; returns one line for the report: where the
// PNGs are, or why there are none (no manifest, gnuplot missing or failed).
// `drawn` (if given) gets the PNGs' paths when gnuplot drew them.
std::string draw_plots(const logger::RunLog& log, const logger::CheckReport& report, const std::string& dir,
                       std::vector<std::string>* drawn = nullptr);

}  // namespace hil::rig
