// issue 17: the FIFO the look-ahead and M pre-output hold their blocks in
// (no allocation per block), against std::deque as the oracle.
#include <catch2/catch.hpp>

#include <deque>
#include <memory>
#include <random>

#include "ring_queue.hpp"

namespace {
// Counts live objects, so that a leak or a double destruction shows.
struct Tracked {
  static inline int alive = 0;
  std::unique_ptr<int> value;
  explicit Tracked(int v) : value(std::make_unique<int>(v)) { ++alive; }
  Tracked(const Tracked& o) : value(std::make_unique<int>(*o.value)) { ++alive; }
  Tracked(Tracked&& o) noexcept : value(std::move(o.value)) { ++alive; }
  Tracked& operator=(Tracked&& o) noexcept = default;
  Tracked& operator=(const Tracked& o) {
    value = std::make_unique<int>(*o.value);
    return *this;
  }
  ~Tracked() { --alive; }
};
}  // namespace

TEST_CASE("RingQueue: random pushes, pops, inserts as std::deque does them", "[issue17]") {
  std::mt19937 rng(17);
  {
    hil::RingQueue<Tracked> ring;
    std::deque<int> oracle;
    for (int step = 0; step < 20000; ++step) {
      const int op = static_cast<int>(rng() % 10);
      if (op < 5) {
        ring.emplace_back(step);
        oracle.push_back(step);
      } else if (op < 8 && !oracle.empty()) {
        ring.pop_front();
        oracle.pop_front();
      } else if (op == 8) {
        const size_t at = oracle.empty() ? 0 : rng() % (oracle.size() + 1);
        const auto it = ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(at), Tracked(-step));
        oracle.insert(oracle.begin() + static_cast<std::ptrdiff_t>(at), -step);
        REQUIRE(*it->value == -step);
      } else if (!oracle.empty()) {
        ring.pop_back();
        oracle.pop_back();
      }
      REQUIRE(ring.size() == oracle.size());
      REQUIRE(Tracked::alive == static_cast<int>(oracle.size()));
      if (!oracle.empty()) {
        REQUIRE(*ring.front().value == oracle.front());
        REQUIRE(*ring.back().value == oracle.back());
      }
    }
    size_t i = 0;
    for (const Tracked& t : ring) REQUIRE(*t.value == oracle[i++]);
    REQUIRE(i == oracle.size());

    const hil::RingQueue<Tracked> copy = ring;
    REQUIRE(copy.size() == ring.size());
    REQUIRE(std::equal(copy.begin(), copy.end(), oracle.begin(), [](const Tracked& t, int v) { return *t.value == v; }));
    hil::RingQueue<Tracked> moved = std::move(ring);
    REQUIRE(moved.size() == oracle.size());
    REQUIRE(ring.empty());
    moved.clear();
    REQUIRE(moved.empty());
    REQUIRE(Tracked::alive == static_cast<int>(copy.size()));
  }
  REQUIRE(Tracked::alive == 0);
}
