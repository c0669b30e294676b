#include "program_stream.hpp"

namespace hil::cnc {

ProgramStream::ProgramStream(const ProgramText& text, const MachineConfig& machine, const std::vector<double>& start,
                             std::function<void(LiftRange)> lift_range)
    : machine_(machine),
      start_(start),
      decoder_(std::make_unique<ProgramDecoder>(text(), machine, start)),
      pre_output_(std::make_unique<MPreOutput>(*decoder_, machine)),
      continued_(std::make_unique<QueuedBlocks>(std::deque<Block>(), pre_output_.get())),
      lift_(std::make_unique<LiftPreparation>(*continued_, machine, start, lift_range)),
      lift_range_(std::move(lift_range)) {}

BlockSearchOutcome ProgramStream::search(const BlockSearchRequest& request, size_t& continuation_index) {
  BlockWindow searched(*pre_output_);
  BlockSearchOutcome outcome = search_block(searched, request, machine_);
  if (!outcome.continuation) return outcome;
  std::deque<Block> start = continued_start(searched, *outcome.continuation, start_, machine_, continuation_index);
  continued_ = std::make_unique<QueuedBlocks>(std::move(start), pre_output_.get());
  lift_ = std::make_unique<LiftPreparation>(*continued_, machine_, start_, lift_range_);
  return outcome;
}

std::optional<Event> ProgramStream::take_error() {
  if (error_taken_ || !decoder_->error()) return std::nullopt;
  error_taken_ = true;
  return decoder_->error();
}

}  // namespace hil::cnc
