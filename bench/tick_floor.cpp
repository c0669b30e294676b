// RIG-6: the floor under the real-time figures: the CNC's tick alone
// (cnc_node::Ticker on CLOCK_MONOTONIC, the same code the cnc runs), with
// nothing to do between ticks, under SCHED_FIFO with locked memory where
// allowed. Prints the wake-up jitter (p50, p99, max) and the overruns.
// Usage: tick_floor [SECONDS] [PERIOD_US] [CPU]   (as root for SCHED_FIFO)
#include <sched.h>

#include <cstdio>
#include <cstdlib>

#include "command_line.hpp"
#include "real_time_process.hpp"
#include "tick_clock.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tick_floor: the real-time tick alone (RIG-6), its jitter and overruns"};
  double seconds = 10;
  int64_t period_us = 1000;
  int cpu = -1;
  app.add_option("seconds", seconds, "how long")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("period_us", period_us, "tick period")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("cpu", cpu, "pinned to this CPU (-1: anywhere)")->capture_default_str();
  app.footer("Documentation: docs/PERFORMANCE.md in the source tree");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
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
