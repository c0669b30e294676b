#pragma once
// Path-related pre-output of M functions (P-CHAN-00070, MVS_SVS): an M
// function with a pre-output path d goes out d mm along the path before the
// start of its block's motion, as if it had been programmed there without
// motion. The motion block where that point lies is split in two
// (Block::continues_block on the second part), the M function goes between.
// The search goes back at most P-CHAN-00603's default of 10 motion blocks;
// it stops at the start of the program or there, and the M function goes
// out at that point, with a warning appended to `warnings`.
#include <vector>

#include "block.hpp"
#include "event.hpp"
#include "machine_config.hpp"

namespace hil::cnc {

std::vector<Block> apply_m_pre_output(std::vector<Block> blocks, const MachineConfig& machine,
                                      std::vector<Event>& warnings);

}  // namespace hil::cnc
