#pragma once
// NC text -> blocks, for the dialect subset of KRN-1 implemented so far:
// N, G00 G01 G02 G03 (I J centre, G161/G162, G164/G165), G90 G91, G92
// (position preset), G74 (homing) and G100 (measurement) with their
// signals simulated (line_decoder.cpp), F (mm/min), M functions, M30, P<n> = expression,
// $FOR/$ENDFOR, #DISTANCE PROG START ON|OFF|CLEAR, #SLOPE[TYPE=..], #TIME,
// #DEL DIST2GO [END=..], #CS ON [..]/OFF, #CHANNEL INIT [CMDPOS],
// #INSERT CMD, #CONTOUR MODE, G60/G61/G260/G261/G359/G360, the lift
// function's <axis>[LIFT_START ..] / [LIFT_END] / [LIFT ..], #FLUSH
// [WAIT] and V.G.LIFT_ACTIVE (docs/LIFT.md),
// `;` and `( )` comments, `%name`. A block
// whose axes do not move is no motion block. Anything else is an
// error with its line number; the blocks before it are still returned, so
// the channel can run exactly what was decoded correctly. A number outside
// the ranges of value_ranges.hpp (1 km, F, N, G, M, P, ...) is an error
// too, and so is a control character in a line: every number of a block
// is finite and in range.
//
// decode_program decodes a whole program at once (tests, tools); the
// channel streams it (program_decoder.hpp): same blocks, same error.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "block.hpp"
#include "event.hpp"
#include "machine_config.hpp"

namespace hil::cnc {

struct DecodedProgram {
  std::vector<Block> blocks;
  std::optional<Event> error;  // the first error; decoding stopped there
};

// `start` are the axis positions at program start (mm, machine axis order).
// Start positions out of range are an error with nc_line 0.
DecodedProgram decode_program(const std::string& text, const MachineConfig& machine,
                              const std::vector<double>& start);
// The same, an error once more than `max_lines_read` lines are read again
// by $FOR loops (10,000,000 above): for tests.
DecodedProgram decode_program(const std::string& text, const MachineConfig& machine, const std::vector<double>& start,
                              int64_t max_lines_read);

}  // namespace hil::cnc
