#pragma once
// The lift function's path preparation (TF5200_lift_function.txt): finds
// the lift ranges of a decoded program, plans what can be planned before
// the path runs, and caps the path in each range where the lift needs it.
#include <cstddef>
#include <optional>
#include <vector>

#include "block.hpp"
#include "lift_profile.hpp"
#include "machine_config.hpp"

namespace hil::cnc {

// Lifting (path-based) looks at most this many internal blocks ahead
// between the start and the end of a lift (LIFT-3).
constexpr size_t lift_look_ahead_blocks = 20;

struct LiftRange {
  size_t start = 0;  // the block with lift_start
  size_t end = 0;    // the range's last block (lift_end, or the program's last)
  bool end_has_motion = false;  // the path has run the range once it reaches the block after `end`, else `end`
  LiftStart command;
  double z0 = 0;     // mm, where the lift axis stands at the start
  // mm, the summit aimed for: POS_LIMIT, or POS or z0 where they lie beyond
  // it (LIFT-5: the limit has no effect); max(z0, POS) when suppressed.
  double peak = 0;
  double length = 0;  // mm, the range's path on the dist_prog_start scale (DPS-1)
  size_t internal_blocks = 0;  // motion blocks and blocks with M functions
  bool suppressed = false;     // LIFT-4: length < P-CHAN-00244
  bool positioning = false;    // no path motion: the lift axis positions while the path waits
  // Lifting (path-based, LIFT-3): the profile, run at path parameter q over
  // q / v_plan, and the path velocity it was planned for.
  LiftProfile profile;
  double v_plan = 0;
  // Advanced Lifting (LIFT-2): for each block of the range from the start,
  // the highest velocity the path is programmed to from there to the end
  // (what bounds the time the path can take to the range's end from below).
  std::vector<double> v_ahead;

  bool contains(size_t block) const { return block >= start && block <= end; }
  // Reaching block `index`, the path has run the range.
  bool passed_by(size_t index) const { return index > end || (index == end && !end_has_motion); }
};

// The ranges of `blocks` (positions of the axes at program start:
// `start_position`), with their motions' path caps set, ranges without
// path motion marked (Block::lift_positioning) and contouring into and out
// of them suppressed where the text says. `next_motion`: the motion block
// that follows `blocks`, if one does.
std::vector<LiftRange> prepare_lift_ranges(std::vector<Block>& blocks, const MachineConfig& machine,
                                           const std::vector<double>& start_position,
                                           const Block* next_motion = nullptr);

}  // namespace hil::cnc
