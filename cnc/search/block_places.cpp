#include "block_places.hpp"

namespace hil::cnc {

std::vector<double> position_at_start(const std::vector<Block>& blocks, size_t k) {
  for (size_t i = k; i < blocks.size(); ++i)
    if (blocks[i].has_motion) return blocks[i].motion.start;
  for (size_t i = k; i-- > 0;)
    if (blocks[i].has_motion) return blocks[i].motion.end;
  return {};
}

bool in_lift_range(const std::vector<Block>& blocks, size_t k, bool at_start) {
  bool open = false;  // a range has begun before the block and not ended
  for (size_t i = 0; i < k && i < blocks.size(); ++i) {
    const Block& block = blocks[i];
    if (block.lift_start)
      open = open || !block.lift_end;  // #FLUSH goes on; Z[LIFT ..] is its own block
    else if (block.lift_end)
      open = false;
  }
  return open || (!at_start && k < blocks.size() && blocks[k].lift_start.has_value());
}

}  // namespace hil::cnc
