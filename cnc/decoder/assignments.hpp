#pragma once
// The assignments of an NC line (KRN-8): P<n> = <expression> (a decoder
// variable), V.G.M_FCT[<m>].PRE_OUTP_PATH = <mm> (P-CHAN-00070 for M<m>
// from here on), V.G.NP[<1..6>].V.<axis> = <mm> (G54..G59's entry), each
// after an optional N number. Decoder work: no block.
#include <cstddef>
#include <string_view>

#include "decoder_state.hpp"

namespace hil::cnc::decoding {

// `equals`: where the line's '=' is (find_assignment). Throws LineError.
void assign_parameter(std::string_view code, size_t equals, DecoderState& state);

}  // namespace hil::cnc::decoding
