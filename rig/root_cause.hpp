#pragma once
// The root cause of a failed run, said first (issue 37, RIG-9): what the
// user fixes, before its consequences ("3 expectation(s) failed",
// "channel_state=PROGRAM_END: never reached").
#include <string>
#include <vector>

#include "limit_check.hpp"
#include "node_errors.hpp"
#include "run_log.hpp"
#include "scenario.hpp"

namespace hil::rig {

// In this order: each error event the scenario does not expect (its
// source, TF5200 number, message and where in the NC program: the scenario
// file's line for an inline program), each node that died, the first limit
// violation the scenario does not expect. Empty if none of these.
std::vector<std::string> root_causes(const Scenario& scenario, const logger::RunLog& log,
                                     const NodeErrors& node_errors, const logger::CheckReport* check);

// "expectations (plc_sim): 2 passed, 3 failed of 5 verdicts: the scenario's
// 4 and 1 'no unexpected error' (one per error event it does not expect)".
std::string describe_expectation_counts(const logger::LogFacts& facts);

}  // namespace hil::rig
