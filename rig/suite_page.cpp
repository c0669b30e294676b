#include "suite_page.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "html.hpp"
#include "suite_progress.hpp"
#include "suite_results.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

}  // namespace

void write_suite_page(const SuiteResult& suite, const std::string& suite_name) {
  const std::string verdict = suite.passed() ? "PASSED" : "FAILED";
  std::ostringstream b;
  b << "<h1>" << escape_markup(suite_name) << "</h1>\n<p><span class=\"verdict " << verdict << "\">" << verdict
    << "</span></p>\n<p>" << describe_counts(suite) << "; <a href=\"summary.txt\">summary.txt</a></p>\n"
    << "<table>\n<tr><th>scenario</th><th>verdict</th><th>simulated</th><th>x real</th><th>first failure</th></tr>\n";
  for (const RunSummary* run : failures_first(suite)) {
    const RunSummary& r = *run;
    const bool ran = r.outcome == Outcome::passed || r.outcome == Outcome::failed;
    const fs::path page = fs::path(r.run_dir) / "report.html";
    std::string name = escape_markup(r.scenario_file);
    std::error_code ec;
    if (!r.run_dir.empty() && fs::exists(page, ec))
      name = "<a href=\"" + escape_markup(page.lexically_relative(suite.out_dir).generic_string()) + "\">" + name +
             "</a>";
    const std::string v = outcome_name(r.outcome);
    b << "<tr><td>" << name << "</td><td class=\"" << v << "\">" << v << "</td><td class=\"num\">"
      << (ran ? format_fixed(r.simulated_s, 2) + " s" : "-") << "</td><td class=\"num\">"
      << (ran ? format_fixed(r.real_time_factor(), 1) : "-") << "</td><td>" << escape_markup(r.first_failure)
      << "</td></tr>\n";
  }
  b << "</table>\n";
  std::ofstream(fs::path(suite.out_dir) / "report.html") << html_page(suite_name, b.str());
}

}  // namespace hil::rig
