#pragma once
// A suite's results for people and for CI systems (RIG-9): the summary
// table, JUnit XML (one testcase per scenario, as Jenkins, GitLab and GitHub
// test reporters read it) and JSON.
#include <string>

#include "suite_run.hpp"

namespace hil::rig {

// scenario, verdict, simulated time, x real time, first failure; then the counts.
std::string format_summary_table(const SuiteResult& suite);

// `suite_name` names the <testsuite> ("hil run scenarios/", "... shard 2/4").
// The failure text of a testcase is its first failed expectation or error;
// its report.txt (if there is one) goes into the failure's body.
void write_junit(const SuiteResult& suite, const std::string& suite_name, const std::string& path);

void write_json(const SuiteResult& suite, const std::string& suite_name, const std::string& path);

// Text for XML/HTML: & < > " ' as entities; control characters XML 1.0
// does not allow (all but tab, LF, CR) become U+FFFD.
std::string escape_markup(const std::string& text);

}  // namespace hil::rig
