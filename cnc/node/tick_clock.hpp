#pragma once
// RIG-6 real-time mode: the CNC's tick on an absolute clock, free of LCM.
// Tick k is due at start + k · period (never drifting with the cycle's own
// duration); the CNC sleeps until it is due and measures how late it woke
// (the jitter). A tick woken for after the next one was already due is an
// overrun: counted, the cycle runs at once, no cycle is ever skipped (the
// simulated time of cycle k stays k · period). The clock is an interface,
// so tests run it on a fake.
#include <cstdint>
#include <vector>

namespace hil::cnc_node {

class TickClock {
 public:
  virtual ~TickClock() = default;
  virtual int64_t now_ns() = 0;
  // Returns at `due_ns` or later, never before.
  virtual void sleep_until_ns(int64_t due_ns) = 0;
};

// CLOCK_MONOTONIC, slept on with clock_nanosleep(TIMER_ABSTIME).
class MonotonicClock : public TickClock {
 public:
  int64_t now_ns() override;
  void sleep_until_ns(int64_t due_ns) override;
};

// Wake-up lateness in 1 µs bins (fixed memory: nothing is allocated while
// the run ticks): percentiles exact to 1 µs below the last bin, the
// maximum exact.
class JitterStats {
 public:
  static constexpr int64_t bins = 20000;  // 0 .. 20 ms
  void add(int64_t late_ns);
  int64_t count() const { return count_; }
  // The q-quantile (0 < q <= 1) in µs: the upper edge of its bin, or the
  // maximum when it lies beyond the last bin; 0 with no sample.
  double quantile_us(double q) const;
  double max_us() const { return static_cast<double>(max_ns_) / 1000.0; }

 private:
  std::vector<int64_t> histogram_ = std::vector<int64_t>(bins, 0);
  int64_t beyond_ = 0;
  int64_t count_ = 0;
  int64_t max_ns_ = 0;
};

class Ticker {
 public:
  Ticker(TickClock& clock, int64_t period_ns) : clock_(clock), period_ns_(period_ns) {}
  // Tick 0 is now.
  void start() { start_ns_ = clock_.now_ns(); }
  int64_t due_ns(int64_t tick) const { return start_ns_ + tick * period_ns_; }

  struct Tick {
    int64_t late_ns = 0;   // woke this long after the tick was due
    bool overrun = false;  // the next tick was due already
  };
  // Sleeps until tick `tick` is due (at once if it is past) and counts it.
  Tick wait(int64_t tick);

  const JitterStats& jitter() const { return jitter_; }
  int64_t overruns() const { return overruns_; }
  int64_t period_ns() const { return period_ns_; }

 private:
  TickClock& clock_;
  int64_t period_ns_;
  int64_t start_ns_ = 0;
  JitterStats jitter_;
  int64_t overruns_ = 0;
};

}  // namespace hil::cnc_node
