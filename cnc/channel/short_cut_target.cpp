#include "short_cut_target.hpp"

namespace hil::cnc {

ShortCutTarget short_cut_target(const std::vector<Block>& blocks, size_t interrupted, uint32_t activation) {
  ShortCutTarget result;
  // The last motion block before block i, the interrupted one at least.
  auto motion_before = [&](size_t i) {
    while (--i > interrupted && !blocks[i].has_motion) {
    }
    return i;
  };
  for (size_t i = interrupted + 1; i < blocks.size(); ++i) {
    const Block& block = blocks[i];
    switch (block.short_cut_restriction) {
      case ShortCutRestriction::not_skippable: result.not_skippable = i; return result;
      case ShortCutRestriction::channel_initialisation:
        result.channel_initialisation = i;
        result.target = motion_before(i);
        return result;
      case ShortCutRestriction::none: break;
    }
    if (activation == 0 ? block.has_motion : block.ddtg_end_marker && (*block.ddtg_end_marker & activation) != 0) {
      result.target = activation == 0 ? i : motion_before(i);
      return result;
    }
  }
  return result;
}

}  // namespace hil::cnc
