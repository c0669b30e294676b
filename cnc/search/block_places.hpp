#pragma once
// Places in a streamed program for block search (DPS-3): where the axes
// stand when a block is reached, and whether a continuation point lies in
// a lift range. The search passes the program once (issue 17): what it
// needs of the blocks it has passed, it keeps here.
#include <cstddef>
#include <vector>

#include "block.hpp"
#include "block_window.hpp"

namespace hil::cnc {

class PassedBlocks {
 public:
  void pass(const Block& block) {
    if (block.has_motion) last_end_ = block.motion.end;
    if (block.lift_start)
      open_range_ = open_range_ || !block.lift_end;  // #FLUSH goes on; Z[LIFT ..] is its own block
    else if (block.lift_end)
      open_range_ = false;
  }
  // Where the axes stand when the next block `k` is reached: the start of
  // the first motion from it on (blocks without motion do not move the
  // path; after a lift range the next motion starts with the lift axis at
  // POS), else the end of the last motion passed; empty in a program
  // without motion.
  std::vector<double> position_at_start(const BlockWindow& blocks, size_t k) const {
    for (size_t i = k; blocks.has(i); ++i)
      if (blocks[i].has_motion) return blocks[i].motion.start;
    return std::vector<double>(last_end_);
  }
  // Whether the point at the start of the next block `k` (`at_start`) or
  // inside it lies in a lift range (LIFT-1): a range begins with its
  // LIFT_START block (its motion lies in it) and ends after its LIFT_END
  // block (M30 acts as LIFT_END, #FLUSH ends one and begins the next, a
  // range without an end ends with the program). The start of the
  // LIFT_START block is outside.
  bool in_lift_range(const BlockWindow& blocks, size_t k, bool at_start) const {
    return open_range_ || (!at_start && blocks.has(k) && blocks[k].lift_start.has_value());
  }

 private:
  AxisValues last_end_;
  bool open_range_ = false;  // a range has begun before the next block and not ended
};

}  // namespace hil::cnc
