#pragma once
// The lift function in the decoder (TF5200_lift_function.txt 3, LIFT-1,
// LIFT-5, LIFT-6): Z[LIFT_START ..], Z[LIFT_END], Z[LIFT ..], #FLUSH and
// the open range decoding carries from line to line. The lift planner
// (cnc/path) moves the lift axis; here a range's blocks keep it where it
// stood at LIFT_START, and after the range it stands at POS.
#include <optional>
#include <string>
#include <vector>

#include "block.hpp"
#include "decoder_state.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {

// The axis command handlers (nc_commands.cpp's table): what follows the
// keyword, upper case, single blanks.
void decode_lift_start(int axis, const std::string& arguments, DecoderState& state, Block& block);
void decode_lift_end(int axis, const std::string& arguments, DecoderState& state, Block& block);
void decode_lift(int axis, const std::string& arguments, DecoderState& state, Block& block);
// #FLUSH, #FLUSH WAIT (LIFT-5): inside a range LIFT_END and LIFT_START at
// once; outside one nothing (no block: nothing waits to be flushed).
// #FLUSH WAIT also marks its block as not searchable (DPS-3, nc_commands.cpp).
void decode_flush(const std::string& arguments, DecoderState& state, Block& block);
// #ROTATION, #TRAFO: not in this rig; inside a range error 120606 (LIFT-6).
void refuse_rotation(const std::string& keyword, const DecoderState& state);

// A line of words once its motion is decoded, before its block is kept:
// the lift axis is not programmed in a range (LIFT-6), Z[LIFT ..] needs a
// motion, M30 ends an open range (LIFT-5), lift blocks are not skippable
// (DDTG-8). `axis_words`: the line's axis words per machine axis.
void finish_lift_block(const std::vector<Word>& words, const std::vector<std::optional<double>>& axis_words,
                       bool position_preset, const DecoderState& state, Block& block);

// After `blocks.back()` was kept: a range it ends or begins. A range that
// ends where the next begins (#FLUSH) ends at its POS_LIMIT (LIFT-5).
void record_lift_block(DecoderState& state, std::vector<Block>& blocks);

// A decode error inside an open range: its lift axis parks at POS_LIMIT
// where the decoded blocks end (LIFT-5 special case 2).
void park_lift_at_error(const DecoderState& state, std::vector<Block>& blocks);

}  // namespace hil::cnc::decoding
