#pragma once
// Where a delete distance to go short-cuts to (DDTG-1, DDTG-5).
#include <cstdint>
#include <optional>
#include <vector>

#include "block.hpp"

namespace hil::cnc {

// The motion block whose end point the short cut from `interrupted` goes
// to: the next motion block (activation 0), or the last motion block before
// the first #DEL DIST2GO marker with END & activation != 0 (which may be
// `interrupted` itself). None: no motion block, or no valid marker, left
// before the program end (DDTG-6).
std::optional<size_t> short_cut_target(const std::vector<Block>& blocks, size_t interrupted, uint32_t activation);

}  // namespace hil::cnc
