#pragma once
// Where a motion block goes (KRN-1): its end point and its arc centre in
// machine coordinates, from the programmed words through G90/G91, the G92
// offsets and the active #CS.
#include <optional>
#include <vector>

#include "block.hpp"
#include "decoder_state.hpp"

namespace hil::cnc::decoding {

// The end point of a block with these axis words (one per machine axis).
AxisValues programmed_target(const std::vector<std::optional<double>>& axis_words,
                             const DecoderState& state);
// The same with G90 (`absolute`) or G91 given, not the modal one (the
// lift function's [G90|G91], LIFT-1).
AxisValues programmed_target(const std::vector<std::optional<double>>& axis_words,
                             const DecoderState& state, bool absolute);

// What an arc block programs besides its end point: the centre words and
// the radius.
struct ArcWords {
  std::optional<double> i, j, k, r;
  bool any() const { return i || j || k || r; }
};

// The plane (G17 / G18 / G19) and centre of the G02/G03 motion `m` (start
// and end set) from I J K (G161/G162, G165) or R; throws LineError if the
// end is not on the circle within P-CHAN-00089 (machine file
// circle_end_point_tolerance).
void set_arc_centre(Motion& m, const ArcWords& words, const DecoderState& state);

}  // namespace hil::cnc::decoding
