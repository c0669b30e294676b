#pragma once
// Where the interpolator is in the decoded program: indices into its block
// list, each with one meaning (KRN-5 needs the furthest block run and the
// stored contour besides the forward cursors).
#include <cstddef>

namespace hil::cnc {

struct BlockCursors {
  size_t next_to_look_ahead = 0;  // forward: the next block to enter the look-ahead
  size_t next_to_run = 0;         // the next block whose commands the interpolator runs
  size_t begun = 0;               // 1 + the furthest block begun forward: its commands ran
  size_t next_backward = 0;       // backward: blocks below this enter the look-ahead next
  size_t lowest_stored = 0;       // the first block still stored for backward motion (P-STUP-00033)
  size_t last_finished = 0;       // the block the path left last: where it stands if nothing follows
};

}  // namespace hil::cnc
