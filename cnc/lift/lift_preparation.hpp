#pragma once
// The lift's path preparation on a streamed program (issue 17, LIFT-1 ..
// LIFT-5): prepare_lift_ranges needs a range whole, and the motion blocks
// before and after it (whether contouring into and out of it stays).
// Blocks pass at once while no range is near; from the last motion block
// before a LIFT_START on, they are held until the range has ended and the
// next motion block after it has come: memory grows with the longest lift
// range, not the program.
#include <cstddef>
#include <functional>
#include <vector>

#include "block_source.hpp"
#include "lift_ranges.hpp"
#include "machine_config.hpp"
#include "ring_queue.hpp"

namespace hil::cnc {

class LiftPreparation : public BlockSource {
 public:
  // `found` gets each range (block indices counted from the first block
  // this stage hands on) before any of its blocks is handed on.
  LiftPreparation(BlockSource& upstream, const MachineConfig& machine, std::vector<double> start_position,
                  std::function<void(LiftRange)> found)
      : upstream_(upstream), machine_(machine), start_(std::move(start_position)), found_(std::move(found)) {}
  bool next(Block& block) override;
  size_t blocks_held() const { return held_.size() + ready_.size(); }

 private:
  // held_ is final: its ranges are planned, its blocks ready to go;
  // `next_motion` follows it (none at the program's end).
  void prepare_held(const Block* next_motion);

  BlockSource& upstream_;
  const MachineConfig& machine_;
  std::vector<double> start_;  // where the axes stand at program start (the first part only)
  std::function<void(LiftRange)> found_;
  std::vector<Block> held_;
  size_t held_first_ = 0;  // the index of held_[0]
  bool first_part_ = true;
  bool open_ = false;  // a range has begun and not ended
  bool has_range_ = false;  // held_ has a LIFT_START
  RingQueue<Block> ready_;
  bool ended_ = false;
};

}  // namespace hil::cnc
