#pragma once
// A scenario's variants side by side (RIG-5, docs/SCENARIOS.md "Variants"):
// per variant the extremes of each axis, the path time and the largest
// lifting |a|; the `compare:` checks (same_path: logger/same_path.hpp); one
// plot overlaying an axis of all.
#include <optional>
#include <string>
#include <vector>

#include "limit_check.hpp"
#include "run_log.hpp"
#include "same_path.hpp"
#include "scenario_set.hpp"

namespace hil::rig {

struct VariantFigures {
  std::string name;
  bool passed = false;
  std::vector<std::string> axes;
  std::vector<double> max_mm, min_mm;  // commanded position, per axis
  std::vector<double> lift_a;          // largest commanded |a| while lift_active, per axis
  std::vector<double> a_max, a_err_limit;
  std::optional<double> path_time_s;   // first ACTIVE to first PROGRAM_END
  // For the plot: per commanded sample, time and dist_prog_start, and each axis' position.
  std::vector<double> t_s, dist_mm;
  std::vector<std::vector<double>> position;
  // For same_path: the cycles with the HLI state and every setpoint.
  logger::PathTrace path;
};

VariantFigures figures_of(const std::string& name, bool passed, const logger::RunLog& log,
                          const logger::CheckReport* check);

// One line per comparison, "holds" or "FAILS"; `all_hold` false if one fails.
std::string check_comparisons(const std::vector<VariantFigures>& variants,
                              const std::vector<VariantComparison>& comparisons, bool& all_hold);

// The table of the figures, variants side by side.
std::string format_variants(const std::vector<VariantFigures>& variants);

// compare_<axis>.png in `dir`: the axis over time and over dist_prog_start,
// one curve per variant; the axes named by `comparisons`, or all without any.
// Returns the report's line; `drawn` (if given) gets the PNGs gnuplot drew.
std::string draw_comparison_plots(const std::string& scenario_name, const std::vector<VariantFigures>& variants,
                                  const std::vector<VariantComparison>& comparisons, const std::string& dir,
                                  std::vector<std::string>* drawn = nullptr);

}  // namespace hil::rig
