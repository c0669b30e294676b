#pragma once
// Blocks one at a time, in program order (issue 17: programs of any
// length): the streamed decoder, and each stage after it (M function
// pre-output, block search's continuation, the lift's preparation) pulls
// from the one before and holds only what it must look back on.
#include <deque>

#include "block.hpp"

namespace hil::cnc {

class BlockSource {
 public:
  virtual ~BlockSource() = default;
  // The next block into `block`; false at the end (program end, the end of
  // the text, or a decode error: the decoder says which).
  virtual bool next(Block& block) = 0;
};

// Blocks already made (block search's approach, tests), then those of
// another source, if any.
class QueuedBlocks : public BlockSource {
 public:
  explicit QueuedBlocks(std::deque<Block> first, BlockSource* then = nullptr)
      : first_(std::move(first)), then_(then) {}
  bool next(Block& block) override {
    if (!first_.empty()) {
      block = std::move(first_.front());
      first_.pop_front();
      return true;
    }
    return then_ && then_->next(block);
  }

 private:
  std::deque<Block> first_;
  BlockSource* then_;
};

}  // namespace hil::cnc
