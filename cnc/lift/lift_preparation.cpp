#include "lift_preparation.hpp"

#include <iterator>

namespace hil::cnc {

void LiftPreparation::prepare_held(const Block* next_motion) {
  if (has_range_) {
    // A part that is not the program's first begins with a motion block
    // outside any range: where it starts does not matter.
    const std::vector<double> start = first_part_ ? start_ : std::vector<double>(held_.front().motion.start);
    for (LiftRange range : prepare_lift_ranges(held_, machine_, start, next_motion)) {
      range.start += held_first_;
      range.end += held_first_;
      found_(std::move(range));
    }
  }
  held_first_ += held_.size();
  for (Block& b : held_) ready_.push_back(std::move(b));
  held_.clear();
  first_part_ = false;
  has_range_ = false;
}

bool LiftPreparation::next(Block& block) {
  if (machine_.lift_method == LiftMethod::none) return upstream_.next(block);
  while (ready_.empty()) {
    Block in;
    if (ended_ || !upstream_.next(in)) {
      ended_ = true;
      if (held_.empty()) return false;
      prepare_held(nullptr);  // a range without an end ends with the program (LIFT-5)
      break;
    }
    // A motion block outside every range: what is held before it is whole.
    if (!open_ && in.has_motion && !in.lift_start && !in.lift_end && !held_.empty()) prepare_held(&in);
    if (in.lift_start) {
      open_ = open_ || !in.lift_end;  // #FLUSH goes on; Z[LIFT ..] is its own range
      has_range_ = true;
    } else if (in.lift_end) {
      open_ = false;
    }
    held_.push_back(std::move(in));
  }
  block = std::move(ready_.front());
  ready_.pop_front();
  return true;
}

}  // namespace hil::cnc
