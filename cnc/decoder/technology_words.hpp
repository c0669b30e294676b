#pragma once
// The technology words of a block for the PLC (KRN-8): M functions (M00 /
// M01 and M30 the channel's own), S, T, D, H, in the block's order,
// before its motion (MVS_SVS); the spindle's state for S.
#include "block.hpp"
#include "decoder_state.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {

// M<m>. Throws LineError.
void add_m_function(const Word& w, DecoderState& state, Block& block);
// S<rpm>, T<tool>, D<offset>, H<nr>. Throws LineError.
void add_technology_word(const Word& w, DecoderState& state, Block& block);

}  // namespace hil::cnc::decoding
