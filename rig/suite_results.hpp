#pragma once
// A suite's results for people and for CI systems (RIG-9): the summary
// table, JUnit XML (one testcase per scenario, as Jenkins, GitLab and GitHub
// test reporters read it) and JSON.
#include <string>
#include <vector>

#include "html.hpp"
#include "suite_run.hpp"

namespace hil::rig {

struct Counts {
  size_t passed = 0, failed = 0, errors = 0, skipped = 0;
};
Counts count(const SuiteResult& suite);

// "4 scenario(s): 2 passed, 1 failed, 1 error(s), 0 skipped in 0:01 (1.6 s wall)"
std::string describe_counts(const SuiteResult& suite);

// `value` with `digits` decimals, as the table, the page and the result files write numbers.
std::string format_fixed(double value, int digits);

// The runs for people: FAILED, then ERROR, SKIPPED, PASSED, each in the
// suite's order (issue 37: the one failure of 75 is not row 74).
std::vector<const RunSummary*> failures_first(const SuiteResult& suite);

// scenario, verdict, simulated time, x real time, first failure (failures
// first); then the counts.
std::string format_summary_table(const SuiteResult& suite);

// `suite_name` names the <testsuite> ("hil run scenarios/", "... shard 2/4").
// The failure text of a testcase is its first failed expectation or error;
// its report.txt (if there is one) goes into the failure's body.
void write_junit(const SuiteResult& suite, const std::string& suite_name, const std::string& path);

void write_json(const SuiteResult& suite, const std::string& suite_name, const std::string& path);

}  // namespace hil::rig
