#include "program_position.hpp"

#include <algorithm>

#include "motion_parts.hpp"

namespace hil::cnc {

void ProgramPosition::mark_run_through(size_t block) {
  cursors_.next_to_run = std::max(cursors_.next_to_run, block + 1);
}

void ProgramPosition::abort_program() {
  close();
  cursors_.next_to_look_ahead = cursors_.next_to_run = past_program_end;
}

void ProgramPosition::stand_in_block(size_t block) {
  cursors_.next_backward = cursors_.lowest_stored;
  cursors_.last_finished = block;
}

std::optional<size_t> ProgramPosition::next_motion_block() {
  if (backward()) {
    for (; cursors_.next_backward > cursors_.lowest_stored; --cursors_.next_backward)
      if (blocks_[cursors_.next_backward - 1].has_motion) return cursors_.next_backward - 1;
    return std::nullopt;
  }
  for (size_t& next = cursors_.next_to_look_ahead; next != invalid_block_ && blocks_.has(next); ++next)
    if (blocks_[next].has_motion) return next;
  return std::nullopt;
}

bool ProgramPosition::exhausted() const {
  if (backward()) return cursors_.next_backward <= cursors_.lowest_stored;
  return at_read_end() || cursors_.next_to_look_ahead == invalid_block_;
}

void ProgramPosition::go_on_after(size_t block) {
  if (backward()) cursors_.next_backward = block;
  else cursors_.next_to_look_ahead = block + 1;
}

bool ProgramPosition::stops_before(size_t k) const {
  if (k < cursors_.begun) return false;  // forward again after backward motion: ran already
  for (size_t i = k + 1; i-- > blocks_.first_kept();) {
    if (i < k && blocks_[i].has_motion) break;
    if (blocks_[i].stops_path()) return true;
  }
  return false;
}

// Backward (KRN-5, KRN-6): the path leaves block k into the motion block
// below it through the corner at that block's end, contoured as forward
// unless something between stops the path there.
Corner ProgramPosition::corner_out(size_t k) const {
  if (!backward()) return corner_after(blocks_[k]);
  for (size_t i = k; i-- > cursors_.lowest_stored;) {
    if (blocks_[i + 1].stops_path()) return {};
    if (blocks_[i].has_motion) return corner_after(blocks_[i]);
  }
  return {};
}

bool ProgramPosition::begin(size_t index) {
  const bool first_time = !backward() && index >= cursors_.begun;
  if (first_time) cursors_.begun = index + 1;
  return first_time;
}

void ProgramPosition::finish(size_t index) {
  if (!backward()) cursors_.next_to_run = std::max(cursors_.next_to_run, index + 1);
  cursors_.last_finished = index;
}

void ProgramPosition::turn(size_t stored_blocks) {
  direction_ = backward() ? TravelDirection::forward : TravelDirection::backward;
  if (!backward()) return;
  size_t i = cursors_.begun, counted = 0;
  while (i > blocks_.first_kept() && counted < stored_blocks)
    if (blocks_[--i].has_motion) ++counted;
  cursors_.lowest_stored = i;
}

std::optional<size_t> ProgramPosition::next_to_run_before(size_t up_to) const {
  const size_t next = cursors_.next_to_run;
  if (next < up_to && blocks_.has(next)) return next;
  return std::nullopt;
}

void ProgramPosition::ran(size_t up_to) {
  // To the program's end (nothing moves any more, no turn): what ran is not needed.
  if (up_to == past_program_end) blocks_.forget_before(cursors_.next_to_run);
  ++cursors_.next_to_run;
}

void ProgramPosition::abandon() {
  blocks_.close();
  cursors_.next_to_look_ahead = cursors_.next_to_run = cursors_.next_backward = past_program_end;
  cursors_.lowest_stored = past_program_end;
}

void ProgramPosition::forget_history(size_t keep) {
  if (stored_contour_.keeps_all()) return;
  const BlockCursors& c = cursors_;
  const size_t stored_from = stored_contour_.first_block(blocks_, std::min(c.begun, blocks_.read_end()));
  keep = std::min({keep, stored_from, c.next_to_run, c.last_finished, c.next_to_look_ahead});
  if (backward()) keep = std::min({keep, c.lowest_stored, c.next_backward});
  blocks_.forget_before(keep);
}

void ProgramPosition::motions_ahead(std::vector<Motion>& ahead, size_t beyond_read) const {
  if (backward()) {
    for (size_t i = cursors_.next_backward; i-- > cursors_.lowest_stored;)
      if (blocks_[i].has_motion) ahead.push_back(reversed(blocks_[i].motion));
    return;
  }
  const size_t first = cursors_.next_to_look_ahead;
  for (size_t i = first; i != invalid_block_ && (i < blocks_.read_end() || i - first < beyond_read) && blocks_.has(i);
       ++i)
    if (blocks_[i].has_motion) ahead.push_back(blocks_[i].motion);
}

}  // namespace hil::cnc
