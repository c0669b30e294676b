#pragma once
// The stored contour behind the path for backward motion (KRN-5,
// P-STUP-00033): the first block of the last `stored_blocks` motion blocks
// begun, counted as the path begins them, so that the blocks below it can
// be forgotten (issue 17: a program is streamed).
#include <cstddef>

#include "block_window.hpp"

namespace hil::cnc {

class StoredContour {
 public:
  explicit StoredContour(size_t stored_blocks = past_program_end) : stored_blocks_(stored_blocks) {}

  // All blocks kept (a program loaded at once).
  bool keeps_all() const { return stored_blocks_ == past_program_end; }
  // Its first block once the blocks before `begun` have been begun.
  size_t first_block(const BlockWindow& blocks, size_t begun) {
    for (; counted_ < begun; ++counted_)
      if (counted_ >= blocks.first_kept() && blocks[counted_].has_motion) ++motion_;
    while (motion_ > stored_blocks_ && start_ < counted_) {
      if (start_ >= blocks.first_kept() && blocks[start_].has_motion) --motion_;
      ++start_;
    }
    return start_;
  }

 private:
  size_t stored_blocks_;
  // motion_ motion blocks counted in [start_, counted_).
  size_t start_ = 0, counted_ = 0, motion_ = 0;
};

}  // namespace hil::cnc
