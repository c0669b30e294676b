#pragma once
// A seeded random source for the channel fuzz whose draws are the same on
// every standard library: mt19937_64's output is specified, the
// std::*_distribution classes are not, so the draws are made here.
#include <cmath>
#include <cstdint>
#include <random>

namespace hil::fuzz {

// splitmix64: derives independent seeds (program, PLC) from a run's seed.
inline uint64_t mix_seed(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(mix_seed(seed)) {}

  // [0, 1)
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // lo * (hi / lo)^u: lengths, feeds and times over decades.
  double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }
  // [lo, hi], both included.
  int64_t integer(int64_t lo, int64_t hi) {
    const uint64_t span = static_cast<uint64_t>(hi - lo) + 1;
    return lo + static_cast<int64_t>(engine_() % span);  // the bias is < 2^-50 for the spans used
  }
  bool chance(double p) { return unit() < p; }
  // One of n weights, by weight.
  template <size_t N>
  size_t pick(const double (&weights)[N]) {
    double total = 0;
    for (double w : weights) total += w;
    double u = unit() * total;
    for (size_t i = 0; i < N; ++i) {
      if (u < weights[i]) return i;
      u -= weights[i];
    }
    size_t last = N - 1;  // rounding left u at the total: the last one that has a weight
    while (last > 0 && !(weights[last] > 0)) --last;
    return last;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace hil::fuzz
