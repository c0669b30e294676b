// Where the interpolator is in the program (BlockCursors): what a short cut
// may do to it, by intent, and what always holds of it.
#include <string>

#include "path_interpolator.hpp"

namespace hil::cnc {

std::string PathInterpolator::check_invariants() const {
  const BlockCursors& c = program_.cursors();
  auto text = [](size_t i) { return i == past_program_end ? std::string("past the end") : std::to_string(i); };
  const bool backward = program_.backward();
  if (backward && c.next_backward < c.lowest_stored)
    return "backward: the next block back " + text(c.next_backward) + " below the lowest stored " +
           text(c.lowest_stored);
  // The motions pushed come from the blocks the look-ahead has passed, in
  // the order of travel.
  size_t previous = backward ? past_program_end : 0;
  for (const MotionPiece& p : pushed_) {
    if (backward ? p.block > previous : p.block < previous)
      return "a motion of block " + text(p.block) + " pushed after one of block " + text(previous);
    previous = p.block;
    if (!backward && p.block >= c.next_to_look_ahead)
      return "forward: a motion of block " + text(p.block) + " pushed, the look-ahead's next block " +
             text(c.next_to_look_ahead);
    if (backward && p.block < c.next_backward)
      return "backward: a motion of block " + text(p.block) + " pushed, the next block back " + text(c.next_backward);
  }
  return "";
}

}  // namespace hil::cnc
