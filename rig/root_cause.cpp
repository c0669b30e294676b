#include "root_cause.hpp"

#include <sstream>

namespace hil::rig {
namespace {

constexpr size_t shown_error_events = 3;

bool expected(const Scenario& scenario, const Event& event) {
  if (scenario.allow_errors) return true;
  for (const EventExpectation& x : scenario.expected_events)
    if (!x.absent && x.matches(event)) return true;
  return false;
}

std::string describe_error(const Scenario& scenario, const logger::LoggedEvent& e) {
  std::ostringstream out;
  out << e.source << " error";
  if (e.event.id != 0) out << ' ' << e.event.id;
  if (!e.event.parameter.empty()) out << " (" << e.event.parameter << ')';
  if (!e.event.axis.empty()) out << " axis " << e.event.axis;
  if (e.event.nc_line > 0) out << " at " << nc_line_place(scenario, e.event.nc_line);
  if (e.event.block_nr > 0) out << " N" << e.event.block_nr;
  out << ", cycle " << e.cycle << ": " << e.event.message;
  return out.str();
}

}  // namespace

std::vector<std::string> root_causes(const Scenario& scenario, const logger::RunLog& log,
                                     const NodeErrors& node_errors, const logger::CheckReport* check) {
  std::vector<std::string> causes;
  size_t errors = 0;
  for (const logger::LoggedEvent& e : log.events) {
    // plc_sim's verdict events are the expectations' outcome, not a cause.
    if (e.event.severity != Severity::error || e.event.verdict != Verdict::none || expected(scenario, e.event))
      continue;
    if (++errors <= shown_error_events) causes.push_back(describe_error(scenario, e));
  }
  if (errors > shown_error_events)
    causes.push_back("and " + std::to_string(errors - shown_error_events) + " more error event(s) (report.txt lists all)");
  for (const std::string& node : node_errors.nodes) causes.push_back(node);
  if (check) {
    for (const logger::Violation& v : check->violations) {
      bool provoked = false;
      for (const ViolationExpectation& x : scenario.expected_violations) provoked = provoked || x.matches(v.axis, v.quantity);
      if (provoked) continue;
      std::ostringstream out;
      out << "limit violation: axis " << v.axis << " " << v.quantity << " up to " << v.value << ", limit " << v.limit
          << ", from t=" << v.time_s << " s for " << v.cycles << " cycle(s)";
      causes.push_back(out.str());
      break;
    }
  }
  return causes;
}

std::string describe_expectation_counts(const logger::LogFacts& facts) {
  const int verdicts = facts.verdict_pass + facts.verdict_fail;
  std::ostringstream out;
  out << "expectations (plc_sim): " << facts.verdict_pass << " passed, " << facts.verdict_fail << " failed";
  if (facts.expectations < 0) return out.str() + " (the log names no scenario)";
  out << " of " << verdicts << " verdict(s): the scenario's " << facts.expectations;
  if (verdicts > facts.expectations)
    out << " and " << verdicts - facts.expectations
        << " 'no unexpected error' (one per error event the scenario does not expect)";
  if (facts.verdicts_announced && *facts.verdicts_announced != verdicts)
    out << "; plc_sim published " << *facts.verdicts_announced;
  return out.str();
}

}  // namespace hil::rig
