#pragma once
// The text a person reads after a run or an offline check (RIG-4, RIG-5).
#include <optional>
#include <string>

#include "limit_check.hpp"
#include "run_log.hpp"

namespace hil::rig {

// Per-axis table, violations, events and the PLC's expectation results.
std::string format_check(const logger::RunLog& log, const logger::CheckReport& report);
// The first part of it: the per-axis table and the violations.
std::string format_limits(const logger::CheckReport& report);

// RIG-6 real-time mode: the CNC's tick jitter and overruns, each
// participant's answers (the last HIL_RT_STATS) and how each node was
// scheduled (its "real time: " event).
std::string format_real_time(const logger::RunLog& log);

// Number of error events in the log (from any node).
int count_errors(const logger::RunLog& log);

}  // namespace hil::rig
