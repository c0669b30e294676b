#pragma once
// NC commands, each found through a table from its keyword to its handler
// (KRN-1): '#' commands (#SLOPE [..], #CS ON [..], ...) and axis commands,
// an axis word with square brackets (Z[LIFT_START POS=..], Z[LIFT_END]).
// A new command is one table row and its handler in nc_commands.cpp.
#include <string>

#include "block.hpp"
#include "decoder_state.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {

// `command`: from the '#' to the end of the line, as upper_words gives it.
// Throws LineError for a command that is not in the table or malformed.
void decode_nc_command(const std::string& command, DecoderState& state, Block& block);

// `word`: an axis command (Word::is_axis_command) on machine axis `axis`.
void decode_axis_command(const Word& word, int axis, DecoderState& state, Block& block);

}  // namespace hil::cnc::decoding
