#pragma once
// One NC line into at most one block (KRN-1): a '#' command, a P parameter
// assignment, or words (N, G, F, M, I/J, axes) for a motion or G92.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "block.hpp"
#include "decoder_state.hpp"

namespace hil::cnc::decoding {

// Appends the line's block to `out` if it commands anything; false once M30
// ended the program. Throws LineError, or std::invalid_argument from an
// expression.
bool decode_line(std::string_view line, int64_t line_nr, int64_t lines_read, DecoderState& state,
                 std::vector<Block>& out);

}  // namespace hil::cnc::decoding
