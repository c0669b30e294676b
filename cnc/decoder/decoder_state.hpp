#pragma once
// What decoding carries from one NC line to the next (KRN-1): modal G
// codes, F and #SLOPE, the position reached, P parameters, M function
// pre-output paths, G92 offsets, the active #CS and the open lift range.
#include <array>
#include <map>
#include <string>
#include <optional>
#include <utility>
#include <vector>

#include "block.hpp"
#include "coordinate_system.hpp"
#include "machine_config.hpp"
#include "parameter_expression.hpp"
#include "words.hpp"

namespace hil::cnc::decoding {

// The plane of G02/G03 (KRN-8): G17 X Y (initial), G18 Z X, G19 Y Z.
enum class Plane : uint8_t { g17, g18, g19 };

struct ModalState {
  MotionType motion = MotionType::linear;
  Plane plane = Plane::g17;
  bool absolute = true;  // G90
  double feed = 0;       // mm/s
  SlopeType slope = SlopeType::trapez;
  bool centre_absolute = false;    // G161; G162 (relative to the start) is the initial state
  bool centre_correction = false;  // G165: move the centre onto the circle through start and end; G164 off
  // G261 / #CONTOUR MODE ON: contour; G360: exact_stop; G260 and G359
  // end what they name (KRN-6).
  BlockTransition transition = BlockTransition::standard;
  ContourMode contour;  // #CONTOUR MODE [..]
  HscMode hsc;          // #HSC ON/OFF [BSPLINE ..] (KRN-9)
  bool inch = false;    // G70; G71 (mm) is the initial state (KRN-8)
};

// A lift range that has begun and not ended (LIFT-1, LIFT-5).
struct LiftRange {
  LiftStart start;          // as programmed (#FLUSH changes the block's copy, not this one)
  size_t block_index = 0;   // the block holding it among the decoded blocks
  int64_t nc_line = 0;      // its line, for messages
};

// What decode_line refills for every line, kept so that a plain block
// allocates nothing for them (issue 17: decode speed). Nothing in them
// carries over from one line to the next.
struct LineBuffers {
  std::string code;                                // a line without its comments, if it had any
  std::vector<Word> words;                         // the line's words, viewing the line or `code`
  std::vector<std::optional<double>> axis_words;   // per machine axis
  std::string dwell;                               // G04 <s> written as G04 X<s>
};

struct DecoderState {
  DecoderState(const MachineConfig& machine_config, std::vector<double> start)
      : machine(machine_config),
        position(std::move(start)),
        pre_output_mm(machine.m_pre_output_mm),
        offset(position.size(), 0.0),
        reference_point_offset(position.size(), 0.0),
        zero_offset_tables(machine.zero_offsets) {
    for (size_t a = 0; a < machine.axes.size(); ++a)
      if (machine.axes[a].name.size() == 1) {
        const char c = machine.axes[a].name[0];
        if (c >= 'A' && c <= 'Z' && letter_axis(c) < 0) axis_by_letter[static_cast<size_t>(c - 'A')] = static_cast<int>(a);
      }
  }

  // The machine axis an address letter (upper case) names, -1 if none: a
  // table, as every axis word asks it.
  int letter_axis(char upper) const { return axis_by_letter[static_cast<size_t>(upper - 'A')]; }
  int axis_of_letter(char letter) const {
    if (letter >= 'A' && letter <= 'Z') return letter_axis(letter);
    return machine.axis_index(std::string(1, letter));
  }

  const MachineConfig& machine;
  AxisValues position;                 // machine coordinates
  ParameterValues parameters;          // P parameters
  std::map<int, double> pre_output_mm;  // M function pre-output (P-CHAN-00070, V.G.M_FCT[m].PRE_OUTP_PATH), mm
  // machine - program: the zero offset G54..G59 in force and G92's
  // reference point offset (update_offset).
  AxisValues offset;
  AxisValues reference_point_offset;   // G92, mm per axis
  int zero_offset = 0;                 // 0: G53 (none, the initial state), 1..6: G54..G59
  // G54..G59's tables, mm per axis: the machine file's, as the PLC
  // (zero_offset) and the program (V.G.NP[..].V.<axis>) change them.
  std::vector<std::vector<double>> zero_offset_tables;
  bool spindle_turning = false;        // M03 / M04; M05 (initial) stops it
  std::optional<double> spindle_speed; // rpm, the last S
  uint32_t block_ignore = 0;           // the PLC's program_block_ignore: skip levels in force (bit 0: /1)
  std::optional<CoordinateSystem> cs;  // #CS ON
  ModalState modal;
  std::optional<LiftRange> lift;
  std::array<int, 26> axis_by_letter = [] {
    std::array<int, 26> table{};
    table.fill(-1);
    return table;
  }();
  LineBuffers buffers;

  void update_offset() {
    for (size_t a = 0; a < offset.size(); ++a)
      offset[a] = reference_point_offset[a] +
                  (zero_offset > 0 && a < zero_offset_tables[static_cast<size_t>(zero_offset - 1)].size()
                       ? zero_offset_tables[static_cast<size_t>(zero_offset - 1)][a]
                       : 0.0);
  }

  // The V.G. variables an expression of this line reads.
  VariableValues variables() const { return {{"V.G.LIFT_ACTIVE", lift ? 1.0 : 0.0}}; }
  double evaluate(const std::string& expression) const {
    return evaluate_expression(expression, parameters, variables());
  }
};

}  // namespace hil::cnc::decoding
