#include "golden_command.hpp"

#include <ostream>

#include "golden_trace.hpp"
#include "run_log.hpp"

namespace hil::rig {
namespace {

logger::GoldenTrace trace_of(const std::string& path) {
  return logger::is_golden_trace_file(path) ? logger::GoldenTrace::read(path) : logger::golden_trace_of_log(path);
}

}  // namespace

int write_golden_trace(const std::string& log, const std::string& out, const std::string& comment, std::ostream& said) {
  logger::GoldenTrace trace = logger::golden_trace_of_log(log);
  trace.comment = comment.empty() ? log : comment;
  trace.write(out);
  size_t rows = 0;
  for (const logger::TraceChannel& c : trace.channels()) rows += c.rows.size();
  said << out << ": " << trace.channels().size() << " channel(s), " << rows << " message(s)\n";
  return 0;
}

int compare_command(const std::string& a, const std::string& b, std::ostream& said) {
  if (!logger::is_golden_trace_file(a) && !logger::is_golden_trace_file(b)) {
    const std::string difference = logger::compare_run_logs(a, b);
    said << (difference.empty() ? "identical" : difference) << '\n';
    return difference.empty() ? 0 : 1;
  }
  const logger::TraceComparison c = logger::compare_golden_traces(trace_of(a), trace_of(b));
  if (c.same()) {
    said << "same within 1e-9 mm (golden trace)\n";
    return 0;
  }
  for (const std::string& d : c.differences) said << d << '\n';
  said << c.count << " difference(s) beyond 1e-9 mm";
  if (static_cast<size_t>(c.count) > c.differences.size()) said << " (the first " << c.differences.size() << " shown)";
  said << '\n';
  return 1;
}

}  // namespace hil::rig
