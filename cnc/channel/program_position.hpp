#pragma once
// Where the interpolator is in the decoded program (KRN-3, KRN-5, issue
// 17): the blocks read and not forgotten, the block cursors, the travel
// direction, the stored contour behind the path and a block that cannot be
// moved. It changes only by intent — the path begins a block, finishes it,
// turns, goes on after a block, a short cut ends the program (DDTG) —, so
// that the cursors keep their meaning (BlockCursors).
#include <cstddef>
#include <optional>
#include <vector>

#include "block.hpp"
#include "block_cursors.hpp"
#include "block_source.hpp"
#include "block_window.hpp"
#include "contour_builder.hpp"
#include "stored_contour.hpp"

namespace hil::cnc {

enum class TravelDirection { forward, backward };

class ProgramPosition {
 public:
  // Read from `source` as the look-ahead needs them; `stored_blocks`: the
  // motion blocks P-STUP-00033 keeps behind the furthest one begun.
  void load(BlockSource& source, size_t stored_blocks) {
    blocks_ = BlockWindow(source);
    stored_contour_ = StoredContour(stored_blocks);
  }
  // All at once (tests), all kept.
  void load(std::vector<Block> blocks) {
    blocks_ = BlockWindow(std::move(blocks));
    stored_contour_ = StoredContour();
  }
  const BlockWindow& blocks() const { return blocks_; }
  const Block& operator[](size_t k) const { return blocks_[k]; }
  // Nothing more is read: the program ends after the blocks read.
  void close() { blocks_.close(); }
  const BlockCursors& cursors() const { return cursors_; }
  TravelDirection direction() const { return direction_; }
  bool backward() const { return direction_ == TravelDirection::backward; }
  const std::optional<size_t>& invalid_block() const { return invalid_block_; }

  // What a short cut does (DDTG-6 .. DDTG-10): PathInterpolator's of the same names.
  void mark_run_through(size_t block);
  void abort_program();
  void end_motion_here() { cursors_.next_to_look_ahead = past_program_end; }
  void look_ahead_after(size_t block) { cursors_.next_to_look_ahead = block + 1; }
  void look_back_below(size_t block) { cursors_.next_backward = block; }
  void stand_in_block(size_t block);

  // The next motion block to enter the look-ahead the way the path travels,
  // passing the blocks without motion before it; none where the program
  // (read so far), the stored contour or the decoded blocks end.
  std::optional<size_t> next_motion_block();
  // Nothing more to enter the look-ahead this way.
  bool exhausted() const;
  // Forward, the look-ahead reached the end of the blocks read.
  bool at_read_end() const { return !blocks_.has(cursors_.next_to_look_ahead); }
  // What enters the look-ahead next comes after `block` the way the path travels.
  void go_on_after(size_t block);
  // Block k's geometry is not finite: the path stops before it.
  void set_invalid(size_t k) { invalid_block_ = k; }
  // The path must stand where motion block k starts, forward: M functions,
  // a dwell, a channel initialisation on its line or since the last motion
  // block (not where it ran already, forward again after backward motion).
  bool stops_before(size_t k) const;
  // How the path leaves block k into the next motion block the way it travels.
  Corner corner_out(size_t k) const;

  // The path begins motion block `index`: true the first time forward
  // (its commands run now).
  bool begin(size_t index);
  // The path left block `index`: nothing of it is left.
  void finish(size_t index);
  // It stands in block `index` if nothing follows.
  void stands_in(size_t index) { cursors_.last_finished = index; }
  // KRN-5: the direction changes; backward, the stored contour is
  // `stored_blocks` motion blocks below the furthest one begun.
  void turn(size_t stored_blocks);
  // The next block whose commands run, below `up_to`; ran() when they did.
  std::optional<size_t> next_to_run_before(size_t up_to) const;
  void ran(size_t up_to);
  // Nothing moves any more (a setpoint not finite).
  void abandon();
  // Drops the blocks nothing needs any more: those below `keep` (the
  // look-ahead's) and below what the cursors and the stored contour need.
  void forget_history(size_t keep);
  // The motion blocks after the look-ahead, the way the path travels, at
  // most `beyond_read` further than read so far (PathInterpolator::path_ahead).
  void motions_ahead(std::vector<Motion>& ahead, size_t beyond_read) const;

 private:
  BlockWindow blocks_;  // the program, as far as read and not forgotten
  StoredContour stored_contour_;
  BlockCursors cursors_;
  TravelDirection direction_ = TravelDirection::forward;
  std::optional<size_t> invalid_block_;
};

}  // namespace hil::cnc
