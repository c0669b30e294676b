#pragma once
// report.html in a run folder (RIG-4, RIG-5): what report.txt says, for a
// browser, in one file that stands alone (the plots embedded): the verdict
// first, why, the expectations PASS/FAIL, the real-time figures, the limits,
// the events, the plots, and report.txt itself.
#include <string>
#include <vector>

#include "limit_check.hpp"
#include "run_log.hpp"
#include "run_scenario.hpp"
#include "scenario.hpp"
#include "scenario_set.hpp"
#include "variant_comparison.hpp"
#include "verdict.hpp"

namespace hil::rig {

struct PagePlots {
  std::vector<std::string> images;  // the PNGs gnuplot drew
  std::string note;                 // the report's plots line: where they are, or why there are none
};

// <result.run_dir>/report.html of one run. `log` is empty and `check` null
// when the run left no log.
void write_run_page(const Scenario& scenario, const RunResult& result, const logger::RunVerdict& verdict,
                    const logger::RunLog& log, const logger::CheckReport* check, const PagePlots& plots);

// <result.run_dir>/report.html of a scenario with variants: the verdict, the
// variants side by side (each linking to its own page), the comparisons
// (check_comparisons' lines), the comparison plots.
void write_set_page(const ScenarioSet& set, const RunResult& result, const std::vector<VariantFigures>& figures,
                    const std::string& comparisons, const PagePlots& plots);

}  // namespace hil::rig
