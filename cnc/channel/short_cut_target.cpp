#include "short_cut_target.hpp"

namespace hil::cnc {

ShortCutTarget short_cut_target(const BlockWindow& blocks, size_t interrupted, uint32_t activation) {
  ShortCutTarget result;
  // The last motion block before block i, the interrupted one at least.
  auto motion_before = [&](size_t i) {
    while (--i > interrupted && !blocks[i].has_motion) {
    }
    return i;
  };
  for (size_t i = interrupted + 1; blocks.has(i); ++i) {
    if (i - interrupted > short_cut_search_blocks) {
      result.search_limit = true;
      return result;
    }
    const Block& block = blocks[i];
    switch (block.short_cut_restriction) {
      case ShortCutRestriction::not_skippable: result.not_skippable = i; return result;
      case ShortCutRestriction::channel_initialisation:
        result.channel_initialisation = i;
        result.target = motion_before(i);
        return result;
      case ShortCutRestriction::none: break;
    }
    if (activation == 0 && block.has_motion && !block.continues_block) {
      // The whole programmed block: its parts split for pre-output M
      // functions (those go out at the interruption point, DDTG-7 case C).
      result.target = i;
      for (size_t k = i + 1; blocks.has(k) && (!blocks[k].has_motion || blocks[k].continues_block); ++k)
        if (blocks[k].has_motion) result.target = k;
      return result;
    }
    if (activation != 0 && block.ddtg_end_marker && (*block.ddtg_end_marker & activation) != 0) {
      result.target = motion_before(i);
      return result;
    }
  }
  return result;
}

ShortCutTarget short_cut_target(const std::vector<Block>& blocks, size_t interrupted, uint32_t activation) {
  return short_cut_target(BlockWindow(blocks), interrupted, activation);
}

}  // namespace hil::cnc
