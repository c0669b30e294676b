#pragma once
// Golden traces (issue 35, docs/GOLDEN.md): what a run commanded, kept
// compactly enough for git, so that a later build can be compared with it
// within a tolerance. A trace holds, per cycle, the CNC's outputs - every
// axis setpoint (AXIS_<name>_CMD), the HLI state (HLI_STATE) - and every
// event (HIL_EVENT), as the CSV export decodes them (SI units, one column
// per field), less the run id. On disk: xz-compressed text; numbers as the
// residual of an extrapolation of their column in steps a tenth of the
// tolerance, integers as the change from the previous row, texts only
// when they change.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "csv_export.hpp"

namespace hil::logger {

struct LogRecord;

struct TraceCell {
  CellKind kind = CellKind::number;
  double number = 0;    // SI (kind number)
  int64_t integer = 0;  // (kind integer)
  std::string text;     // unquoted (kind text)
};

struct TraceRow {
  int64_t cycle = 0;
  std::shared_ptr<const std::vector<std::string>> names;  // shared by a channel's rows while they do not change
  std::vector<TraceCell> cells;
};

struct TraceChannel {
  std::string name, type;
  std::vector<TraceRow> rows;  // in the order of the log (events: by cycle, then by content)
};

class GoldenTrace {
 public:
  // The message if it is one a trace keeps (by channel) and decodes.
  void add(const LogRecord& record);
  // Sorts the events of each cycle: nodes publish them in wall-clock order.
  void finish();

  const std::vector<TraceChannel>& channels() const { return channels_; }
  std::string comment;  // where it came from (one line; no temporary path, so that a trace rewritten alike is the same file)

  // The xz-compressed text; read() throws std::runtime_error naming the
  // file and line of what it cannot read.
  void write(const std::string& path) const;
  static GoldenTrace read(const std::string& path);
  std::string text() const;
  static GoldenTrace parse(const std::string& text, const std::string& source);

 private:
  TraceChannel& channel(const std::string& name, const std::string& type);
  std::vector<TraceChannel> channels_;
};

// The trace of an LCM event log: the run of its messages, whatever their
// run ids. Throws std::runtime_error if it cannot be read or is damaged.
GoldenTrace golden_trace_of_log(const std::string& path);

// Whether `path` is a golden trace (by its xz magic) rather than an LCM log.
bool is_golden_trace_file(const std::string& path);

// How far a number of `column` (a CSV export column name, SI) may lie from
// the golden one: 1e-9 mm for a length (and for a number of no unit of
// motion: a time, a ratio), for a velocity 1e-9 mm per cycle of 1 ms
// (1e-6 mm/s), for an acceleration 1e-9 mm per cycle squared (1e-3
// mm/s^2); or 1e-12 of the value, whichever is larger. Integers and texts
// agree exactly.
double golden_tolerance_of(const std::string& column, double magnitude);

struct TraceComparison {
  std::vector<std::string> differences;  // the first `max_listed`: channel, cycle, field, both values
  int64_t count = 0;                     // all of them
  bool same() const { return count == 0; }
};
TraceComparison compare_golden_traces(const GoldenTrace& golden, const GoldenTrace& now, size_t max_listed = 10);

}  // namespace hil::logger
