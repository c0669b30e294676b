#pragma once
// The stop the interpolator is asked for (insert stop marks, ISC-3), on
// its two scales: asked while the path stands, it is a distance from
// program start (DPS-1, covered distance) until the look-ahead reaches it
// and places it; placed, or asked while moving, it is a path length
// travelled (either direction) where the path comes to rest.
#include <optional>
#include <vector>

namespace hil::cnc {

// Where the stop lies once the look-ahead has reached it, and how much of
// the asked-for distance lies before it (less if it was moved to the end).
struct PlacedStop {
  std::vector<double> position;
  double covered = 0;  // from where the stop was asked for
};

class PathStop {
 public:
  // While moving: at path length `at` (in place of any asked before).
  void ask_at_length(double at);
  // While standing: `distance` of covered distance after `from`, placed
  // as the look-ahead reaches it.
  void ask_covered(double from, double distance);
  void release();
  // The look-ahead reached it: at path length `at`, at `position`, where
  // `pushed_covered` has been pushed on the covered scale.
  void place(double at, std::vector<double> position, double pushed_covered);
  // Not closer than where the path can stop braking now.
  void not_before(double p);

  // On the covered scale, while not placed.
  const std::optional<double>& unplaced() const { return covered_; }
  // On path length.
  const std::optional<double>& at() const { return at_; }
  const std::optional<PlacedStop>& placed() const { return placed_; }

 private:
  std::optional<double> at_;
  std::optional<double> covered_;
  double covered_from_ = 0;
  std::optional<PlacedStop> placed_;
};

}  // namespace hil::cnc
