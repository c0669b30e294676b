#pragma once
// The text a person reads after a run or an offline check (RIG-4, RIG-5).
#include <optional>
#include <string>

#include "limit_check.hpp"
#include "run_log.hpp"

namespace hil::rig {

// Per-axis table, violations, events and the PLC's expectation results.
std::string format_check(const logger::RunLog& log, const logger::CheckReport& report);

// Number of error events in the log (from any node).
int count_errors(const logger::RunLog& log);

}  // namespace hil::rig
