#include "report.hpp"

#include <cstdio>
#include <sstream>

namespace hil::rig {
namespace {

std::string fmt(const char* format, double a, double b) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

}  // namespace

int count_errors(const logger::RunLog& log) {
  int errors = 0;
  for (const auto& e : log.events) errors += e.event.severity == Severity::error ? 1 : 0;
  return errors;
}

std::string format_check(const logger::RunLog& log, const logger::CheckReport& report) {
  std::ostringstream out;
  out << "axis | cmd |v| / v_max [mm/s] | cmd |a| / a_max [mm/s^2] | cmd |j| / j_max [mm/s^3]"
         " | act |v| / P-AXIS-00440 limit | act |a| / P-AXIS-00442 limit | max |FE| / P-AXIS-00168 [mm]\n";
  for (const auto& a : report.axes) {
    out << a.axis << "    | " << fmt("%9.3f / %-9.3f", a.cmd_v, a.v_max) << "| "
        << fmt("%10.2f / %-10.2f", a.cmd_a, a.a_max) << "| " << fmt("%11.1f / %-11.1f", a.cmd_j, a.j_max)
        << "| " << fmt("%9.3f / %-9.3f", a.act_v, a.v_err_limit) << "| " << fmt("%10.2f / %-10.2f", a.act_a, a.a_err_limit) << "| "
        << fmt("%8.5f / %-8.5f", a.following_error, a.slep_max)
        << (a.slep_max > 0 ? "" : "(none)") << '\n';
  }
  int64_t violating_cycles = 0;
  for (const auto& v : report.violations) violating_cycles += v.cycles;
  out << "limit violations: " << report.violations.size() << " (" << violating_cycles << " cycles)\n";
  for (const auto& v : report.violations)
    out << "  t=" << fmt("%.4f", v.time_s, 0) << ".." << fmt("%.4f s", v.end_time_s, 0) << " (" << v.cycles
        << " cycles) axis " << v.axis << ": " << v.quantity << " up to " << v.value << " at t="
        << fmt("%.4f s", v.worst_time_s, 0) << ", limit " << v.limit << '\n';
  int warnings = 0;
  for (const auto& e : log.events) warnings += e.event.severity == Severity::warning ? 1 : 0;
  out << "events: " << count_errors(log) << " errors, " << warnings << " warnings\n";
  for (const auto& e : log.events)
    out << "  cycle " << e.cycle << " [" << e.source << "] " << describe(e.event) << '\n';
  return out.str();
}

}  // namespace hil::rig
