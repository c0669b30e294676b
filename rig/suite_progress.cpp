#include "suite_progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace hil::rig {

std::string format_elapsed(double seconds) {
  const long s = static_cast<long>(seconds);
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

SuiteProgress::SuiteProgress(std::ostream& out, size_t total, bool terminal)
    : out_(out), total_(total), terminal_(terminal) {}

void SuiteProgress::started(const std::string& file) {
  running_.insert(file);
  if (terminal_) draw();
}

void SuiteProgress::finished(const RunSummary& run) {
  running_.erase(run.scenario_file);
  ++done_;
  const bool bad = run.outcome == Outcome::failed || run.outcome == Outcome::error;
  failed_ += bad ? 1 : 0;
  std::ostringstream line;
  line << '[' << done_ << '/' << total_ << "] " << outcome_name(run.outcome) << ' ' << run.scenario_file;
  if (run.outcome == Outcome::passed || run.outcome == Outcome::failed)
    line << " (" << std::fixed << std::setprecision(1) << run.simulated_s << " s simulated, "
         << run.real_time_factor() << "x real time)";
  if (!run.first_failure.empty()) line << ": " << run.first_failure;
  if (!terminal_) {
    out_ << line.str() << '\n' << std::flush;
    return;
  }
  if (bad) out_ << "\r\033[K" << line.str() << '\n';  // stays above the progress line
  draw();
}

void SuiteProgress::waiting() {
  const long second =
      static_cast<long>(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  if (terminal_ && second != drawn_second_) draw();
}

void SuiteProgress::draw() {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  drawn_second_ = static_cast<long>(elapsed);
  std::string now;
  for (const std::string& file : running_) now += (now.empty() ? "" : ", ") + file;
  std::ostringstream line;
  line << done_ << '/' << total_ << " done, " << running_.size() << " running, " << failed_ << " failed, "
       << format_elapsed(elapsed) << (now.empty() ? "" : "  " + now);
  // A line longer than the terminal wraps, and \r no longer returns to its start.
  winsize size{};
  const size_t width = ::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0 ? size.ws_col : 80;
  out_ << "\r\033[K" << line.str().substr(0, width - 1) << std::flush;
}

void SuiteProgress::close() {
  if (terminal_) out_ << "\r\033[K" << std::flush;
}

}  // namespace hil::rig
