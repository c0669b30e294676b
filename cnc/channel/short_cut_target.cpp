#include "short_cut_target.hpp"

namespace hil::cnc {

std::optional<size_t> short_cut_target(const std::vector<Block>& blocks, size_t interrupted, uint32_t activation) {
  if (activation == 0) {
    for (size_t i = interrupted + 1; i < blocks.size(); ++i)
      if (blocks[i].has_motion) return i;
    return std::nullopt;
  }
  for (size_t i = interrupted + 1; i < blocks.size(); ++i) {
    if (!blocks[i].ddtg_end_marker || (*blocks[i].ddtg_end_marker & activation) == 0) continue;
    size_t target = i - 1;
    while (target > interrupted && !blocks[target].has_motion) --target;
    return target;
  }
  return std::nullopt;
}

}  // namespace hil::cnc
