#include "path_stop.hpp"

#include <algorithm>

namespace hil::cnc {

// Out of line: GCC 12 takes the optional's reset, inlined, for a use of
// an uninitialised vector (-Wmaybe-uninitialized).
void PathStop::ask_at_length(double at) {
  release();
  at_ = at;
}

void PathStop::ask_covered(double from, double distance) {
  release();
  covered_from_ = from;
  covered_ = from + std::max(distance, 0.0);
}

void PathStop::release() {
  at_.reset();
  covered_.reset();
  placed_.reset();
}

void PathStop::place(double at, std::vector<double> position, double pushed_covered) {
  at_ = at;
  placed_ = PlacedStop{std::move(position), pushed_covered - covered_from_};
  covered_.reset();
}

void PathStop::not_before(double p) { at_ = std::max(*at_, p); }

}  // namespace hil::cnc
