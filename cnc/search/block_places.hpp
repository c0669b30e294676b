#pragma once
// Places in a decoded program for block search (DPS-3): where the axes
// stand when a block is reached, and whether a continuation point lies in
// a lift range.
#include <cstddef>
#include <vector>

#include "block.hpp"

namespace hil::cnc {

// Where the axes stand when block `k` is reached: the start of the first
// motion from it on (blocks without motion do not move the path; after a
// lift range the next motion starts with the lift axis at POS), else the
// end of the last motion before it; empty in a program without motion.
std::vector<double> position_at_start(const std::vector<Block>& blocks, size_t k);

// Whether the point at the start of block `k` (`at_start`) or inside it
// lies in a lift range (LIFT-1): a range begins with its LIFT_START block
// (its motion lies in it) and ends after its LIFT_END block (M30 acts as
// LIFT_END, #FLUSH ends one and begins the next, a range without an end
// ends with the program). The start of the LIFT_START block is outside.
bool in_lift_range(const std::vector<Block>& blocks, size_t k, bool at_start);

}  // namespace hil::cnc
