#include "technology_words.hpp"

#include <algorithm>
#include <string>

#include "value_ranges.hpp"

namespace hil::cnc::decoding {

// M03 / M04 / M05 switch the spindle (TF5200 "Spindle"): S goes out with
// M03 / M04 or while the spindle turns; under M05 it is only kept.
void add_m_function(const Word& w, DecoderState& state, Block& block) {
  const int m = static_cast<int>(integer_code(w, max_m_function));
  // TF5200 "Default M functions": M02 and M30 are both the main program's
  // end, CNC commands neither output nor synchronised (jscut and grbl
  // posts end with M2).
  if (m == 30 || m == 2) {
    block.program_end = true;
    return;
  }
  if (m == 0 || m == 1) {  // M00 / M01: the channel's own stop (ISC-5), not output to the PLC
    if (block.programmed_stop) throw LineError{"two of M00 / M01 in one block"};
    block.programmed_stop = m;
    return;
  }
  if (m == 3 || m == 4 || m == 5) {
    const bool other = std::any_of(block.m_functions.begin(), block.m_functions.end(), [](const MFunction& f) {
      return f.address == 'M' && (f.nr == 3 || f.nr == 4 || f.nr == 5);
    });
    if (other) throw LineError{"'" + w.text() + "': one of M03 / M04 / M05 in a block"};
    const bool starts = m != 5 && !state.spindle_turning;
    state.spindle_turning = m != 5;
    // The speed kept under M05 goes out with the start, before the M function.
    if (starts && state.spindle_speed &&
        std::none_of(block.m_functions.begin(), block.m_functions.end(), [](const MFunction& f) { return f.address == 'S'; }))
      block.m_functions.push_back({0, 0, 'S', *state.spindle_speed});
  }
  const auto pre_output = state.pre_output_mm.find(m);
  block.m_functions.push_back({m, pre_output == state.pre_output_mm.end() ? 0.0 : pre_output->second});
}

// S<rpm>, T<tool>, D<offset>, H<nr>: technology functions for the PLC in
// the block's order (KRN-8), before the block's motion (MVS_SVS).
void add_technology_word(const Word& w, DecoderState& state, Block& block) {
  if (w.letter == 'S') {
    if (!(w.value >= 0 && w.value <= max_spindle_speed))
      throw LineError{"'" + w.text() + "': the spindle speed S must be 0 .. " +
                      std::to_string(static_cast<int64_t>(max_spindle_speed)) + " rpm"};
    state.spindle_speed = w.value;
    if (!state.spindle_turning) return;
    // After an M03 / M04 of this block that sent the kept speed: this one instead.
    const auto sent = std::find_if(block.m_functions.begin(), block.m_functions.end(),
                                   [](const MFunction& f) { return f.address == 'S'; });
    if (sent != block.m_functions.end()) sent->value = w.value;
    else block.m_functions.push_back({0, 0, 'S', w.value});
    return;
  }
  const int nr = static_cast<int>(integer_code(w, max_m_function));
  block.m_functions.push_back({nr, 0, w.letter});
}

}  // namespace hil::cnc::decoding
