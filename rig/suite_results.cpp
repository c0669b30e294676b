#include "suite_results.hpp"

#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "json_text.hpp"
#include "suite_progress.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream all;
  all << in.rdbuf();
  return all.str();
}

std::string iso_time(std::time_t time) {
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", std::localtime(&time));
  return buf;
}

int rank(Outcome outcome) {
  switch (outcome) {
    case Outcome::failed: return 0;
    case Outcome::error: return 1;
    case Outcome::skipped: return 2;
    case Outcome::passed: return 3;
  }
  return 1;
}

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? name : "localhost";
}

}  // namespace

Counts count(const SuiteResult& suite) {
  Counts c;
  for (const RunSummary& r : suite.runs) {
    c.passed += r.outcome == Outcome::passed;
    c.failed += r.outcome == Outcome::failed;
    c.errors += r.outcome == Outcome::error;
    c.skipped += r.outcome == Outcome::skipped;
  }
  return c;
}

std::string format_fixed(double value, int digits) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(digits) << value;
  return o.str();
}

std::string describe_counts(const SuiteResult& suite) {
  const Counts c = count(suite);
  return std::to_string(suite.runs.size()) + " scenario(s): " + std::to_string(c.passed) + " passed, " +
         std::to_string(c.failed) + " failed, " + std::to_string(c.errors) + " error(s), " +
         std::to_string(c.skipped) + " skipped in " + format_elapsed(suite.wall_s) + " (" +
         format_fixed(suite.wall_s, 1) + " s wall)";
}

std::vector<const RunSummary*> failures_first(const SuiteResult& suite) {
  std::vector<const RunSummary*> runs;
  for (const RunSummary& r : suite.runs) runs.push_back(&r);
  std::stable_sort(runs.begin(), runs.end(),
                   [](const RunSummary* a, const RunSummary* b) { return rank(a->outcome) < rank(b->outcome); });
  return runs;
}

std::string format_summary_table(const SuiteResult& suite) {
  size_t width = std::string("scenario").size();
  for (const RunSummary& r : suite.runs) width = std::max(width, r.scenario_file.size());
  std::ostringstream out;
  out << std::left << std::setw(static_cast<int>(width)) << "scenario" << "  verdict  simulated  x real  first failure\n";
  for (const RunSummary* run : failures_first(suite)) {
    const RunSummary& r = *run;
    const bool ran = r.outcome == Outcome::passed || r.outcome == Outcome::failed;
    std::string failure = r.first_failure;
    if (failure.size() > 100) failure = failure.substr(0, 97) + "...";
    out << std::left << std::setw(static_cast<int>(width)) << r.scenario_file << "  " << std::setw(7)
        << outcome_name(r.outcome) << "  " << std::right << std::setw(8) << (ran ? format_fixed(r.simulated_s, 2) + " s" : "-")
        << "  " << std::setw(6) << (ran ? format_fixed(r.real_time_factor(), 1) : "-") << "  " << failure << '\n';
  }
  out << describe_counts(suite) << "; run folders below " << suite.out_dir << '\n'
      << "suite: " << (suite.passed() ? "PASSED" : "FAILED") << '\n';
  return out.str();
}

void write_junit(const SuiteResult& suite, const std::string& suite_name, const std::string& path) {
  const Counts c = count(suite);
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<testsuites name=\"hil\" tests=\"" << suite.runs.size() << "\" failures=\"" << c.failed << "\" errors=\""
    << c.errors << "\" skipped=\"" << c.skipped << "\" time=\"" << format_fixed(suite.wall_s, 3) << "\">\n"
    << "  <testsuite name=\"" << escape_markup(suite_name) << "\" tests=\"" << suite.runs.size() << "\" failures=\""
    << c.failed << "\" errors=\"" << c.errors << "\" skipped=\"" << c.skipped << "\" time=\""
    << format_fixed(suite.wall_s, 3) << "\" timestamp=\"" << iso_time(suite.started) << "\" hostname=\"" << escape_markup(host_name())
    << "\">\n";
  for (const RunSummary& r : suite.runs) {
    const fs::path file(r.scenario_file);
    std::string classname = file.parent_path().lexically_normal().string();
    std::replace(classname.begin(), classname.end(), '/', '.');
    x << "    <testcase classname=\"" << escape_markup(classname.empty() ? "scenarios" : classname) << "\" name=\""
      << escape_markup(file.stem().string()) << "\" file=\"" << escape_markup(r.scenario_file) << "\" time=\""
      << format_fixed(r.wall_s, 3) << "\">\n";
    const std::string report = r.run_dir.empty() ? "" : read_file((fs::path(r.run_dir) / "report.txt").string());
    if (r.outcome == Outcome::failed)
      x << "      <failure type=\"FAILED\" message=\"" << escape_markup(r.first_failure) << "\">"
        << escape_markup(report) << "</failure>\n";
    else if (r.outcome == Outcome::error)
      x << "      <error type=\"ERROR\" message=\"" << escape_markup(r.first_failure) << "\">"
        << escape_markup(report.empty() ? r.first_failure : report) << "</error>\n";
    else if (r.outcome == Outcome::skipped)
      x << "      <skipped message=\"" << escape_markup(r.first_failure) << "\"/>\n";
    x << "      <system-out>" << escape_markup("scenario " + r.name + ", run folder " + r.run_dir)
      << "</system-out>\n    </testcase>\n";
  }
  x << "  </testsuite>\n</testsuites>\n";
  std::ofstream(path) << x.str();
}

void write_json(const SuiteResult& suite, const std::string& suite_name, const std::string& path) {
  const Counts c = count(suite);
  std::ostringstream j;
  j << "{\n  \"suite\": " << json_string(suite_name) << ",\n  \"passed\": " << (suite.passed() ? "true" : "false")
    << ",\n  \"counts\": {\"scenarios\": " << suite.runs.size() << ", \"passed\": " << c.passed
    << ", \"failed\": " << c.failed << ", \"errors\": " << c.errors << ", \"skipped\": " << c.skipped
    << "},\n  \"wall_s\": " << format_fixed(suite.wall_s, 3) << ",\n  \"out_dir\": " << json_string(suite.out_dir)
    << ",\n  \"runs\": [";
  for (size_t i = 0; i < suite.runs.size(); ++i) {
    const RunSummary& r = suite.runs[i];
    j << (i ? "," : "") << "\n    {\"scenario_file\": " << json_string(r.scenario_file)
      << ", \"name\": " << json_string(r.name) << ", \"verdict\": " << json_string(outcome_name(r.outcome))
      << ", \"requirements\": [";
    for (size_t k = 0; k < r.requirements.size(); ++k) j << (k ? ", " : "") << json_string(r.requirements[k]);
    j << "], \"simulated_s\": " << format_fixed(r.simulated_s, 6) << ", \"wall_s\": " << format_fixed(r.wall_s, 3)
      << ", \"x_real_time\": " << format_fixed(r.real_time_factor(), 2)
      << ", \"first_failure\": " << json_string(r.first_failure) << ", \"run_dir\": " << json_string(r.run_dir)
      << "}";
  }
  j << "\n  ]\n}\n";
  std::ofstream(path) << j.str();
}

}  // namespace hil::rig
