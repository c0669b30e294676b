#pragma once
// The text a person reads after a run or an offline check (RIG-4, RIG-5).
#include <optional>
#include <string>
#include <vector>

#include "limit_check.hpp"
#include "run_log.hpp"

namespace hil::rig {

// Per axis, the largest value of each quantity the offline check watches,
// its limit (0: none) and the margin left (negative: exceeded).
struct LimitRow {
  std::string quantity;  // "commanded |a| [mm/s^2] / a_max"
  double value = 0, limit = 0, margin_percent = 0;
};
struct AxisLimits {
  std::string axis;
  std::vector<LimitRow> rows;
  std::string note;  // the lift's, if any axis lifted
};
std::vector<AxisLimits> limit_table(const logger::CheckReport& report);

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
