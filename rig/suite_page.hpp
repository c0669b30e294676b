#pragma once
// A suite's report.html (RIG-5, RIG-9): summary.txt for a browser, each
// scenario linking to its run folder's report.html.
#include <string>

#include "suite_run.hpp"

namespace hil::rig {

// <suite.out_dir>/report.html: the counts, the wall time, and per scenario
// its verdict, simulated time, x real time and first failure. Links are
// relative (the suite folder can be moved or served as it is) and only to
// pages that exist (a scenario the loader refused has none).
void write_suite_page(const SuiteResult& suite, const std::string& suite_name);

}  // namespace hil::rig
