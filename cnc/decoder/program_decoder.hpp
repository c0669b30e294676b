#pragma once
// The streamed decoder (KRN-1, issue 17): decodes an NC program's lines as
// its blocks are asked for, so that a program of any length runs in the
// same memory. It holds the decoder's modal state, the lines of the open
// $FOR loops (ForLoops), and the blocks of an open lift range (its
// LIFT_START block is completed at the range's end, LIFT-5); every other
// block leaves it as soon as it is decoded.
//
// A decode error ends the stream where it is met: the blocks before it
// came out, error() says which line (NC line, N number) and why. It is
// found when the stream reaches that line, not at program start.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "block_source.hpp"
#include "decoder_state.hpp"
#include "event.hpp"
#include "for_loops.hpp"
#include "line_source.hpp"
#include "machine_config.hpp"

namespace hil::cnc {

class ProgramDecoder : public BlockSource {
 public:
  // An endless loop is an error, not a hang: at most this many lines are
  // read again by $FOR loops (a program's own lines count once).
  static constexpr int64_t default_max_lines_read = 10000000;

  // `start`: the axis positions at program start (mm, machine axis order);
  // out of range, or not one per axis, an error with nc_line 0.
  ProgramDecoder(std::unique_ptr<LineSource> text, const MachineConfig& machine, const std::vector<double>& start,
                 int64_t max_lines_read = default_max_lines_read);
  ProgramDecoder(const ProgramDecoder&) = delete;
  ProgramDecoder& operator=(const ProgramDecoder&) = delete;

  bool next(Block& block) override;
  // Block skip levels (bit 0: /1) for the lines decoded from now on (KRN-8).
  void set_block_ignore(uint32_t levels) { state_.block_ignore = levels; }
  // G54..G59's tables (mm per axis) for the lines decoded from now on (KRN-8).
  void set_zero_offsets(const std::vector<std::vector<double>>& tables) {
    state_.zero_offset_tables = tables;
    state_.update_offset();
  }
  // The error that ended the stream; none before it is met.
  const std::optional<Event>& error() const { return error_; }
  // Decoding has ended (M30, the end of the text, or an error).
  bool finished() const { return finished_; }
  // What it holds now: NC lines and blocks (docs/ARCHITECTURE.md's bounds).
  size_t lines_held() const { return lines_.held(); }
  size_t blocks_held() const { return out_.size() - head_; }

 private:
  void decode_next_line();
  void finish();
  // The blocks decoding may still change: from an open lift range's start.
  size_t releasable() const;

  std::unique_ptr<LineSource> text_;
  LineStore lines_;
  decoding::DecoderState state_;
  decoding::ForLoops loops_;
  int64_t max_lines_read_;
  int64_t lines_read_ = 0;
  int64_t furthest_ = 0;  // 1 + the furthest line read
  size_t line_ = 0;  // the next line to decode, 0-based
  std::vector<Block> out_;  // decoded; from head_ on not handed out yet
  size_t head_ = 0;
  std::optional<Event> error_;
  bool finished_ = false;
};

}  // namespace hil::cnc
