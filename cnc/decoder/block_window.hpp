#pragma once
// The blocks of a program run, by their index in program order, read from
// a BlockSource as they are asked for (issue 17). It holds the blocks from
// the oldest one not forgotten up to the furthest one asked for: the
// interpolator forgets what neither the look-ahead, the blocks still to
// run, nor the contour stored for backward motion (P-STUP-00033) needs.
#include <cstddef>
#include <deque>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "block_source.hpp"

namespace hil::cnc {

// An index past every block: "to the program's end" (nothing is read for it).
constexpr size_t past_program_end = std::numeric_limits<size_t>::max();

class BlockWindow {
 public:
  BlockWindow() = default;
  explicit BlockWindow(BlockSource& source) : source_(&source) {}
  explicit BlockWindow(std::vector<Block> blocks)
      : owned_(std::make_unique<QueuedBlocks>(std::deque<Block>(std::make_move_iterator(blocks.begin()),
                                                                std::make_move_iterator(blocks.end())))),
        source_(owned_.get()) {}

  // Block i exists: reads on up to it (reading is not a change of what the
  // program is, hence const). False past the program's end.
  bool has(size_t i) const {
    if (i == past_program_end) return false;
    while (i >= first_ + blocks_.size()) {
      Block block;
      if (!source_ || closed_ || !source_->next(block)) {
        closed_ = true;
        return false;
      }
      blocks_.push_back(std::move(block));
    }
    return true;
  }
  // Block i, read and not forgotten.
  const Block& operator[](size_t i) const { return blocks_[checked(i)]; }
  Block& at(size_t i) { return blocks_[checked(i)]; }
  // The program has no block at all.
  bool empty() const { return first_ == 0 && !has(0); }
  // Blocks below i are not needed any more.
  void forget_before(size_t i) {
    while (first_ < i && !blocks_.empty()) {
      blocks_.pop_front();
      ++first_;
    }
  }
  size_t first_kept() const { return first_; }
  // Hands out every block held; reading goes on after them.
  std::deque<Block> take_all() {
    first_ += blocks_.size();
    return std::exchange(blocks_, {});
  }
  // 1 + the furthest block read.
  size_t read_end() const { return first_ + blocks_.size(); }
  size_t held() const { return blocks_.size(); }
  // Nothing more is read: the program ends after the blocks read.
  void close() { closed_ = true; }

 private:
  size_t checked(size_t i) const {
    if (i < first_ || !has(i))
      throw std::out_of_range("block " + std::to_string(i) + " is not held (held: " + std::to_string(first_) + ".." +
                              std::to_string(read_end()) + ")");
    return i - first_;
  }

  std::unique_ptr<BlockSource> owned_;
  BlockSource* source_ = nullptr;
  mutable std::deque<Block> blocks_;
  size_t first_ = 0;
  mutable bool closed_ = false;
};

}  // namespace hil::cnc
