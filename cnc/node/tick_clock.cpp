#include "tick_clock.hpp"

#include <time.h>

#include <algorithm>
#include <cerrno>

namespace hil::cnc_node {

int64_t MonotonicClock::now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

void MonotonicClock::sleep_until_ns(int64_t due_ns) {
  const timespec due{static_cast<time_t>(due_ns / 1000000000), static_cast<long>(due_ns % 1000000000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &due, nullptr) == EINTR) {
  }
}

void JitterStats::add(int64_t late_ns) {
  late_ns = std::max<int64_t>(late_ns, 0);
  const int64_t bin = late_ns / 1000;
  if (bin < bins) ++histogram_[static_cast<size_t>(bin)];
  else ++beyond_;
  ++count_;
  max_ns_ = std::max(max_ns_, late_ns);
}

double JitterStats::quantile_us(double q) const {
  if (count_ == 0) return 0;
  const auto rank = static_cast<int64_t>(q * static_cast<double>(count_) + 0.999999);  // ceil, 1-based
  int64_t seen = 0;
  for (int64_t bin = 0; bin < bins; ++bin) {
    seen += histogram_[static_cast<size_t>(bin)];
    if (seen >= rank) return std::min(static_cast<double>(bin + 1), max_us());
  }
  return max_us();
}

Ticker::Tick Ticker::wait(int64_t tick) {
  const int64_t due = due_ns(tick);
  if (clock_.now_ns() < due) clock_.sleep_until_ns(due);
  Tick t;
  const int64_t woke = clock_.now_ns();
  t.late_ns = woke - due;
  t.overrun = woke >= due_ns(tick + 1);
  jitter_.add(t.late_ns);
  overruns_ += t.overrun ? 1 : 0;
  return t;
}

}  // namespace hil::cnc_node
