#pragma once
// The ranges of the numbers the decoder takes (KRN-1, KRN-2). A number
// outside them is an error naming its line, so no block carries a value
// the path cannot compute with (inf, NaN, 1e308 mm) and no conversion to an
// integer overflows. Why these bounds: docs/ARCHITECTURE.md, "Decoder
// limits".
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "axis_values.hpp"
#include "machine_config.hpp"

namespace hil::cnc::decoding {

// Coordinates (axis words, G92 values, end points after G91, G92 and #CS),
// arc centres and radii, I/J, #CS offsets, PRE_OUTP_PATH: |value| <= 1 km.
// G70: inch. Lengths of the linear axes, I J K R and F (inch/min) scale;
// rotary axes (A B C) keep degrees.
constexpr double mm_per_inch = 25.4;
constexpr double max_length_mm = 1e6;
constexpr double min_feed_mm_min = 1e-3;  // F
constexpr double max_feed_mm_min = 1e7;
constexpr double max_dwell_s = 1e6;       // #TIME
constexpr double max_cs_angle_deg = 360;  // #CS φ1, φ2, φ3
constexpr int64_t max_block_nr = 4294967295;  // N: block_nr_r is a UDINT, [0, MAX_UNS32]
constexpr int64_t max_g_code = 999;
constexpr int64_t max_m_function = 2147483647;  // M: m_function_nr_r is a DINT
constexpr int64_t max_p_parameter = 99999;      // P<n>
constexpr double max_spindle_speed = 1e6;       // S, rpm
constexpr int max_skip_level = 10;              // /1 .. /10 (TF5200 "Skipping of NC blocks")

// `value` if |value| <= max_length_mm; else throws LineError naming `what`.
double checked_length(double value, std::string_view what);

// Every axis of `position` (machine axis order) within max_length_mm;
// `what` names the point ("end point", "arc centre").
void check_position(const AxisValues& position, const MachineConfig& machine, std::string_view what);

// The number the decimal digits `digits` write if it is at most `max`;
// none for an empty text, any other character or a larger number.
std::optional<int64_t> whole_number(std::string_view digits, int64_t max);

}  // namespace hil::cnc::decoding
