#pragma once
// The progress of a suite while it runs (issue 19): on a terminal one line,
// rewritten in place (done / running / failed, elapsed, what runs), with
// each failure printed above it as it happens; elsewhere (CI logs, files)
// one plain line per finished scenario.
#include <chrono>
#include <ostream>
#include <set>
#include <string>

#include "run_summary.hpp"

namespace hil::rig {

class SuiteProgress {
 public:
  SuiteProgress(std::ostream& out, size_t total, bool terminal);
  void started(const std::string& file);
  void finished(const RunSummary& run);
  void waiting();  // redraws the elapsed time on a terminal, once a second
  void close();    // leaves the terminal's line empty for what follows

 private:
  void draw();
  std::ostream& out_;
  size_t total_;
  bool terminal_;
  size_t done_ = 0, failed_ = 0;
  std::set<std::string> running_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  long drawn_second_ = -1;
};

// "1:05" for 65 s
std::string format_elapsed(double seconds);

}  // namespace hil::rig
