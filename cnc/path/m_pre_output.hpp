#pragma once
// Path-related pre-output of M functions (P-CHAN-00070, MVS_SVS): an M
// function with a pre-output path d goes out d mm along the path before the
// start of its block's motion, as if it had been programmed there without
// motion. The motion block where that point lies is split in two
// (Block::continues_block on the second part), the M function goes between.
// The search goes back at most P-CHAN-00603's default of 10 motion blocks;
// it stops at the start of the program or there, and the M function goes
// out at that point, with a warning appended to `warnings`.
//
// Streamed (issue 17): MPreOutput holds the blocks from the earliest of the
// last 10 motion blocks on (and the blocks without motion between them),
// the only ones a later pre-output can still split or insert into.
#include <cstddef>
#include <utility>
#include <vector>

#include "block.hpp"
#include "block_source.hpp"
#include "event.hpp"
#include "machine_config.hpp"
#include "ring_queue.hpp"

namespace hil::cnc {

class MPreOutput : public BlockSource {
 public:
  MPreOutput(BlockSource& upstream, const MachineConfig& machine) : upstream_(upstream), machine_(machine) {}
  bool next(Block& block) override;
  // Pre-output paths that reached past what is searched, since the last call.
  std::vector<Event> take_warnings() { return std::exchange(warnings_, {}); }
  size_t blocks_held() const { return held_.size(); }

 private:
  // The next block from upstream into held_; false at its end.
  bool take_next();
  void add(Block&& block);
  void release_final();

  BlockSource& upstream_;
  const MachineConfig& machine_;
  RingQueue<Block> held_;
  size_t motion_held_ = 0;  // motion blocks in held_
  size_t final_ = 0;        // held_'s first blocks no pre-output can change any more
  bool ended_ = false;
  std::vector<Event> warnings_;
};

// The same over a whole program (tests).
std::vector<Block> apply_m_pre_output(std::vector<Block> blocks, const MachineConfig& machine,
                                      std::vector<Event>& warnings);

}  // namespace hil::cnc
