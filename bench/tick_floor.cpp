// RIG-6: the floor under the real-time figures: the CNC's tick alone
// (cnc_node::Ticker on CLOCK_MONOTONIC, the same code the cnc runs), with
// nothing to do between ticks, under SCHED_FIFO with locked memory where
// allowed. Prints the wake-up jitter (p50, p99, max) and the overruns.
// Usage: tick_floor [SECONDS] [PERIOD_US] [CPU]   (as root for SCHED_FIFO)
#include <sched.h>

#include <cstdio>
#include <cstdlib>

#include "real_time_process.hpp"
#include "tick_clock.hpp"

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 10;
  const int64_t period_us = argc > 2 ? std::atoll(argv[2]) : 1000;
  const int cpu = argc > 3 ? std::atoi(argv[3]) : -1;
  if (seconds <= 0 || period_us <= 0) return std::fprintf(stderr, "usage: tick_floor [SECONDS] [PERIOD_US] [CPU]\n"), 2;
  if (cpu >= 0) {
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    sched_setaffinity(0, sizeof one, &one);
  }
  const hil::lcm_support::RealTimeProcess process = hil::lcm_support::enter_real_time();
  hil::cnc_node::MonotonicClock clock;
  hil::cnc_node::Ticker ticker(clock, period_us * 1000);
  const auto ticks = static_cast<int64_t>(seconds * 1e6 / static_cast<double>(period_us));
  ticker.start();
  for (int64_t k = 1; k <= ticks; ++k) ticker.wait(k);
  const hil::cnc_node::JitterStats& j = ticker.jitter();
  std::printf("tick alone: %lld ticks of %lld us on CPU %d, %s: overruns %lld, jitter p50 %.0f us, p99 %.0f us, "
              "max %.0f us\n",
              static_cast<long long>(j.count()), static_cast<long long>(period_us), sched_getcpu(),
              process.what.c_str(), static_cast<long long>(ticker.overruns()), j.quantile_us(0.5),
              j.quantile_us(0.99), j.max_us());
  return 0;
}
