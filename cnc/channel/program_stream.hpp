#pragma once
// A program run's blocks as the interpolator reads them (issue 17): the
// streamed decoder, M function pre-output (P-CHAN-00070), block search's
// continued program (DPS-3) and the lift's preparation (LIFT-1 .. LIFT-5),
// each a stage pulling from the one before and holding only what it must
// look back on (docs/ARCHITECTURE.md, "Programs of any length").
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "block_search.hpp"
#include "block_source.hpp"
#include "event.hpp"
#include "lift_preparation.hpp"
#include "line_source.hpp"
#include "m_pre_output.hpp"
#include "machine_config.hpp"
#include "program_decoder.hpp"

namespace hil::cnc {

class ProgramStream {
 public:
  // `start`: where the axes stand; `lift_range`: each lift range before the
  // path reaches it.
  ProgramStream(const ProgramText& text, const MachineConfig& machine, const std::vector<double>& start,
                std::function<void(LiftRange)> lift_range);

  // DPS-3: searches the program from its start; on success the stream
  // goes on with the continued program (the approach from `start`, the
  // collected commands, the rest from the continuation point), and
  // `continuation_index` is where the continuation's block lies in it.
  BlockSearchOutcome search(const BlockSearchRequest& request, size_t& continuation_index);
  // What the interpolator reads.
  BlockSource& blocks() { return *lift_; }
  // The PLC's program_block_ignore: skip levels for the lines decoded from now on (KRN-8).
  void set_block_ignore(uint32_t levels) { decoder_->set_block_ignore(levels); }
  // G54..G59's tables as the PLC has set them (KRN-8), for the lines decoded from now on.
  void set_zero_offsets(const std::vector<std::vector<double>>& tables) { decoder_->set_zero_offsets(tables); }

  // Blocks its stages hold.
  size_t blocks_held() const { return decoder_->blocks_held() + pre_output_->blocks_held() + lift_->blocks_held(); }
  // The decode error, once the stream has met it (once).
  std::optional<Event> take_error();
  // Warnings of the pre-output (P-CHAN-00070) since the last call.
  std::vector<Event> take_warnings() { return pre_output_->take_warnings(); }

 private:
  const MachineConfig& machine_;
  std::vector<double> start_;
  std::unique_ptr<ProgramDecoder> decoder_;
  std::unique_ptr<MPreOutput> pre_output_;
  std::unique_ptr<QueuedBlocks> continued_;  // block search's continued program, then the rest
  std::unique_ptr<LiftPreparation> lift_;
  std::function<void(LiftRange)> lift_range_;
  bool error_taken_ = false;
};

}  // namespace hil::cnc
