#include "report.hpp"

#include <cstdio>
#include <sstream>
#include <string>

namespace hil::rig {
namespace {

std::string fmt(const char* format, double a, double b) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

}  // namespace

std::string format_real_time(const logger::RunLog& log) {
  std::ostringstream out;
  if (!log.real_time) return "real time: no statistics (HIL_RT_STATS) in the log\n";
  const logger::RealTimeFigures& r = *log.real_time;
  char line[200];
  std::snprintf(line, sizeof line,
                "real time: %d us cycle, %lld ticks, overruns (missed ticks) %lld; tick jitter (wake-up - due) p50 "
                "%.0f us, p99 %.0f us, max %.0f us%s\n",
                r.cycle_us, static_cast<long long>(r.ticks), static_cast<long long>(r.overruns), r.jitter_p50_us,
                r.jitter_p99_us, r.jitter_max_us, r.final ? "" : " (not the final statistics: the run was cut short)");
  out << line;
  out << "  scheduling:";
  std::string nodes;
  for (const auto& e : log.events)
    if (e.event.message.rfind("real time: ", 0) == 0)
      nodes += (nodes.empty() ? " " : "; ") + e.source + " " + e.event.message.substr(11);
  out << (nodes.empty() ? " (no node said)" : nodes) << '\n';
  std::snprintf(line, sizeof line, "  %-14s %10s %8s %8s %13s %10s %13s %9s\n", "answers", "in time", "late",
                "missing", "out of order", "duplicate", "longest gap", "watchdog");
  out << line;
  for (const auto& p : r.participants) {
    std::snprintf(line, sizeof line, "  %-14s %10lld %8lld %8lld %13lld %10lld %13lld %9lld\n", p.name.c_str(),
                  static_cast<long long>(p.in_time), static_cast<long long>(p.late),
                  static_cast<long long>(p.missing), static_cast<long long>(p.out_of_order),
                  static_cast<long long>(p.duplicate), static_cast<long long>(p.longest_gap_cycles),
                  static_cast<long long>(p.watchdog_cycles));
    out << line;
  }
  return out.str();
}

int count_errors(const logger::RunLog& log) {
  int errors = 0;
  for (const auto& e : log.events) errors += e.event.severity == Severity::error ? 1 : 0;
  return errors;
}

std::vector<AxisLimits> limit_table(const logger::CheckReport& report) {
  std::vector<AxisLimits> table;
  bool lifted = false;  // any axis: then every axis shows its lift rows (LIFT-2)
  for (const auto& a : report.axes) lifted = lifted || a.lift_cycles > 0;
  for (const auto& a : report.axes) {
    AxisLimits axis{a.axis, {}, ""};
    // A, B, C are rotary axes (DIN 66025, KRN-7): degrees.
    const std::string u = a.axis.find_first_of("ABC") == 0 ? "deg" : "mm";
    auto row = [&](const std::string& quantity, double value, double limit) {
      // Round-off above a limit (within the check's tolerance) shows as 0.0 %.
      double margin = limit > 0 ? 100 * (limit - value) / limit : 0;
      if (margin < 0 && margin > -0.05) margin = 0;
      axis.rows.push_back({quantity, value, limit, margin});
    };
    row("commanded |v| [" + u + "/s] / v_max", a.cmd_v, a.v_max);
    row("commanded |a| [" + u + "/s^2] / a_max", a.cmd_a, a.a_max);
    row("commanded |j| [" + u + "/s^3] / j_max", a.cmd_j, a.j_max);
    row("actual |v| [" + u + "/s] / P-AXIS-00440", a.act_v, a.v_err_limit);
    row("actual |a| [" + u + "/s^2] / P-AXIS-00442", a.act_a, a.a_err_limit);
    row("|following error| [" + u + "] / P-AXIS-00168", a.following_error, a.slep_max);
    if (lifted) {
      // The lift's overload range: TF5200 plans the lift axis up to P-AXIS-00442;
      // its jerk stays within j_max.
      row("lifting |a| [" + u + "/s^2] / P-AXIS-00442", a.cmd_a_lift, a.a_err_limit);
      row("lifting |j| [" + u + "/s^3] / j_max", a.cmd_j_lift, a.j_max);
      char note[200];
      std::snprintf(note, sizeof note, "lift_active %lld cycles: commanded |a| up to %.2f a_max%s",
                    static_cast<long long>(a.lift_cycles), a.a_max > 0 ? a.cmd_a_lift / a.a_max : 0.0,
                    a.cmd_a_lift > a.a_max * (1 + logger::limit_tolerance) ? " (the overload range above a_max)" : "");
      axis.note = note;
    }
    table.push_back(axis);
  }
  return table;
}

std::string format_limits(const logger::CheckReport& report) {
  std::ostringstream out;
  // Per axis: the largest value of each quantity, its limit and the margin
  // left (negative: the limit was exceeded).
  for (const AxisLimits& axis : limit_table(report)) {
    char head[160];
    std::snprintf(head, sizeof head, "axis %-37s %12s %12s %10s\n", axis.axis.c_str(), "max", "limit", "margin");
    out << head;
    for (const LimitRow& r : axis.rows) {
      char buf[160];
      if (r.limit > 0)
        std::snprintf(buf, sizeof buf, "  %-40s %12.4f %12.4f %8.1f %%\n", r.quantity.c_str(), r.value, r.limit,
                      r.margin_percent);
      else
        std::snprintf(buf, sizeof buf, "  %-40s %12.4f %12s %10s\n", r.quantity.c_str(), r.value, "-", "-");
      out << buf;
    }
    if (!axis.note.empty()) out << "  " << axis.note << '\n';
  }
  int64_t violating_cycles = 0;
  for (const auto& v : report.violations) violating_cycles += v.cycles;
  out << "limit violations: " << report.violations.size() << " (" << violating_cycles << " cycles)\n";
  for (const auto& v : report.violations)
    out << "  t=" << fmt("%.4f", v.time_s, 0) << ".." << fmt("%.4f s", v.end_time_s, 0) << " (" << v.cycles
        << " cycles) axis " << v.axis << ": " << v.quantity << " up to " << v.value << " at t="
        << fmt("%.4f s", v.worst_time_s, 0) << ", limit " << v.limit << '\n';
  return out.str();
}

std::string format_check(const logger::RunLog& log, const logger::CheckReport& report) {
  std::ostringstream out;
  out << format_limits(report);
  int warnings = 0;
  for (const auto& e : log.events) warnings += e.event.severity == Severity::warning ? 1 : 0;
  out << "events: " << count_errors(log) << " errors, " << warnings << " warnings\n";
  for (const auto& e : log.events)
    out << "  cycle " << e.cycle << " [" << e.source << "] " << describe(e.event) << '\n';
  return out.str();
}

}  // namespace hil::rig
