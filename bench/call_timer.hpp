#pragma once
// Times short calls (a few hundred ns) for the benchmarks: the mean from
// batches of 1000 calls between two clock reads, the distribution (p50, p99,
// max) from each call timed with the CPU's time-stamp counter (x86; else the
// steady clock), less the counter's own cost (the median of empty timings).
// A batch that took more than twice the median batch was preempted (the
// machine is shared): it is left out of the mean and counted.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#define HIL_BENCH_TSC 1
#endif

namespace hil::bench {

struct CallTimes {
  double mean_ns = 0, p50_ns = 0, p99_ns = 0, max_ns = 0;
  double checksum = 0;  // of the calls' results, so that none is optimised away
  int batches = 0, preempted_batches = 0;
};

class CallTimer {
 public:
  CallTimer() : ns_per_tick_(calibrate()), overhead_ticks_(empty_ticks()) {}

  // call(i) for i in [0, count) returns a double; every call runs twice
  // (batched, then one by one) after one warm-up pass.
  template <typename Call>
  CallTimes time(int count, Call call) const {
    CallTimes r;
    for (int i = 0; i < count; ++i) r.checksum += call(i);
    std::vector<double> batch_ns;
    for (int begin = 0; begin < count; begin += 1000) {
      const int end = std::min(count, begin + 1000);
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = begin; i < end; ++i) r.checksum += call(i);
      batch_ns.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() /
                         (end - begin));
    }
    std::vector<double> sorted = batch_ns;
    std::sort(sorted.begin(), sorted.end());
    const double limit = 2 * sorted[sorted.size() / 2];
    double sum = 0;
    for (double b : batch_ns) {
      if (b > limit) {
        ++r.preempted_batches;
        continue;
      }
      sum += b;
      ++r.batches;
    }
    r.mean_ns = sum / r.batches;
    std::vector<double> ns(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
      const std::uint64_t t0 = ticks();
      r.checksum += call(i);
      const std::uint64_t t1 = ticks();
      ns[i] = std::max(0.0, static_cast<double>(t1 - t0) - overhead_ticks_) * ns_per_tick_;
    }
    std::sort(ns.begin(), ns.end());
    r.p50_ns = ns[ns.size() / 2];
    r.p99_ns = ns[ns.size() * 99 / 100];
    r.max_ns = ns.back();
    return r;
  }

  double ns_per_tick() const { return ns_per_tick_; }

 private:
  static std::uint64_t ticks() {
#ifdef HIL_BENCH_TSC
    _mm_lfence();
    const std::uint64_t t = __rdtsc();
    _mm_lfence();
    return t;
#else
    return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
  }

  static double calibrate() {
#ifdef HIL_BENCH_TSC
    const auto c0 = std::chrono::steady_clock::now();
    const std::uint64_t t0 = ticks();
    while (std::chrono::steady_clock::now() - c0 < std::chrono::milliseconds(50)) {
    }
    const std::uint64_t t1 = ticks();
    const auto c1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(c1 - c0).count() / static_cast<double>(t1 - t0);
#else
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::duration(1)).count();
#endif
  }

  static double empty_ticks() {
    std::vector<std::uint64_t> t(10001);
    for (auto& x : t) {
      const std::uint64_t t0 = ticks();
      x = ticks() - t0;
    }
    std::sort(t.begin(), t.end());
    return static_cast<double>(t[t.size() / 2]);
  }

  double ns_per_tick_;
  double overhead_ticks_;
};

}  // namespace hil::bench
