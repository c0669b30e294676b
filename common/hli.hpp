#pragma once
// The HLI (PLC <-> CNC interface, KRN-4) as plain values. The CNC's channel
// library fills HliState, the PLC simulator writes HliControl; the nodes
// translate both to and from the LCM types hli_state_t / hli_control_t.
// Their fields are listed once, in hli_table.hpp.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hli_record.hpp"
#include "hli_table.hpp"

namespace hil {

enum class ChannelState : int8_t { ready = 0, active = 1, program_end = 2, error = 3 };

const char* to_string(ChannelState state);
// "READY", "ACTIVE", "PROGRAM_END", "ERROR" (case-insensitive); false if unknown.
bool parse_channel_state(const std::string& text, ChannelState& state);

// HLI_SC_* bits of stop_conditions_r (TF5200_insert_stop_cmd.txt, table of
// stop conditions). The channel sets FEEDHOLD, PLC_ACKNOWLEDGE and
// WAIT_TECHNO_ACK (an M function waits), OVERRIDE_ZERO, DELAY_TIME,
// IPO_INPUT_EMPTY, CHANNEL_ERROR, M00_OR_M01 with M0_STOP / M1_STOP and
// INSERT_STOP_AT_DIST (cnc/channel/path_hold.cpp); the others (the text's
// whole table, KRN-4) a scenario can name but this rig never sets. One
// list, X(NAME, name, bit): the constants below and the names scenarios write (HLI_SC_ dropped,
// stop_condition_names()) both come from it.
#define HLI_STOP_CONDITIONS(X)                                                             \
  X(FEEDHOLD, feedhold, 0x0001)                       /* path feed stop */                   \
  X(VFG, vfg, 0x0002)                                 /* no axis-specific feed enable */     \
  X(SINGLE_BLOCK, single_block, 0x0004)                                                      \
  X(M00_OR_M01, m00_or_m01, 0x0010)                                                          \
  X(PLC_ACKNOWLEDGE, plc_acknowledge, 0x0020)         /* waiting for the PLC's acknowledgement */ \
  X(OVERRIDE_ZERO, override_zero, 0x0040)                                                    \
  X(OVERRIDE_RAPID_ZERO, override_rapid_zero, 0x0080)                                        \
  X(DELAY_TIME, delay_time, 0x0200)                   /* dwell */                            \
  X(CHANNEL_SYNC, channel_sync, 0x0800)                                                      \
  X(IPO_INPUT_EMPTY, ipo_input_empty, 0x1000)                                                \
  X(IPO_INPUT_DISABLED, ipo_input_disabled, 0x2000)                                          \
  X(WAIT_FOR_AXES, wait_for_axes, 0x8000)                                                    \
  X(CHANNEL_ERROR, channel_error, 0x00010000)                                                \
  X(WAIT_TECHNO_ACK, wait_techno_ack, 0x00020000)     /* M/H/ST function acknowledgement */  \
  X(W_C_AFTER_COLLISION, w_c_after_collision, 0x00040000)                                    \
  X(SLOPE_SUPPLY_PROBLEM, slope_supply_problem, 0x00080000)                                  \
  X(BACK_INTERPOLATION, back_interpolation, 0x00100000)                                      \
  X(STOP_REVERSIBLE, stop_reversible, 0x00200000)                                            \
  X(BREAKPOINT_STOP, breakpoint_stop, 0x00400000)                                            \
  X(M0_STOP, m0_stop, 0x02000000)                                                            \
  X(M1_STOP, m1_stop, 0x04000000)                                                            \
  X(INSERT_STOP_AT_DIST, insert_stop_at_dist, 0x08000000)                                    \
  X(DEC_SYN_CHAN_EMPTY, dec_syn_chan_empty, 0x10000000)
namespace stop_condition {
#define HIL_STOP_CONDITION_CONSTANT(NAME, name, bit) constexpr int32_t name = bit;
HLI_STOP_CONDITIONS(HIL_STOP_CONDITION_CONSTANT)
#undef HIL_STOP_CONDITION_CONSTANT
}  // namespace stop_condition

// A stop condition bit by the name a scenario writes: "FEEDHOLD" (the
// HLI_SC_ prefix may be given too, case matters not).
struct StopConditionName {
  const char* name;  // without HLI_SC_
  int32_t bit;
};
const std::vector<StopConditionName>& stop_condition_names();
// The bit, or 0 if no stop condition has that name.
int32_t find_stop_condition(const std::string& name);
// "FEEDHOLD|M00_OR_M01", "0" for none; bits without a name as hex.
std::string stop_conditions_text(int32_t bits);

// The control unit types (HLI_CONTROL_UNIT_FIELDS / HLI_STATE_UNIT_FIELDS),
// by the type of command_w and state_r.
template <typename Command>
struct ControlUnit {
  HIL_RECORD(ControlUnit, HLI_CONTROL_UNIT_FIELDS)
};
template <typename State>
struct ControlUnitStateOf {
  HIL_RECORD(ControlUnitStateOf, HLI_STATE_UNIT_FIELDS)
};
using ControlUnitBool = ControlUnit<bool>;                  // MC_CONTROL_BOOL_UNIT
using ControlUnitValue = ControlUnit<int32_t>;              // DINT command (override)
using ControlUnitUns32 = ControlUnit<uint32_t>;             // MC_CONTROL_UNS32_UNIT (UDINT)
using ControlUnitState = ControlUnitStateOf<bool>;
using ControlUnitValueState = ControlUnitStateOf<int32_t>;
using ControlUnitUns32State = ControlUnitStateOf<uint32_t>;

// The insert command unit (ISC-1, ISC-2). position_at_next_stop holds the
// first three axes (ARRAY[0..HLI_CS_AXIS_MAXIDX] OF DINT in the text).
using StopPositions = std::array<int32_t, 3>;
struct InsertCmdCommand {
  HIL_RECORD(InsertCmdCommand, HLI_INSERT_CMD_COMMAND_FIELDS)
};
struct InsertCmdState {
  InsertCmdState() { distance_of_next_stop = -1; }
  HIL_RECORD(InsertCmdState, HLI_INSERT_CMD_STATE_FIELDS)
};
struct InsertCmdUnit {
  HIL_RECORD(InsertCmdUnit, HLI_INSERT_CMD_UNIT_FIELDS)
};
struct InsertCmdUnitState {
  HIL_RECORD(InsertCmdUnitState, HLI_INSERT_CMD_UNIT_STATE_FIELDS)
};
// The block search unit (DPS-3).
struct BlockSearchCommand {
  HIL_RECORD(BlockSearchCommand, HLI_BLOCK_SEARCH_COMMAND_FIELDS)
};
struct BlockSearchState {
  HIL_RECORD(BlockSearchState, HLI_BLOCK_SEARCH_STATE_FIELDS)
};
using ControlUnitBlockSearch = ControlUnit<BlockSearchCommand>;

struct ZeroOffsetCommand {
  HIL_RECORD(ZeroOffsetCommand, HLI_ZERO_OFFSET_COMMAND_FIELDS)
  bool operator==(const ZeroOffsetCommand& o) const { return group == o.group && axis_nr == o.axis_nr && value == o.value; }
};
using ControlUnitZeroOffset = ControlUnit<ZeroOffsetCommand>;
using ControlUnitBlockSearchState = ControlUnitStateOf<BlockSearchState>;
namespace block_search_state {
constexpr int32_t none = 0, repositioning = 1, continued = 2, error = 3;
}

// Override values are in 0.1 % (1000 = 100 %).
constexpr int32_t override_full = 1000;

// The members are the table's (hli_table.hpp); `cycle` belongs to the
// message, not to the HLI.
struct HliControl {
  int64_t cycle = -1;  // the HLI_STATE cycle this answers
  HIL_RECORD(HliControl, HLI_CONTROL_UNITS)
};

struct HliState {
  int64_t cycle = 0;
  HIL_RECORD(HliState, HLI_STATE_FIELDS)
};

// HLI length unit: 0.1 um.
constexpr double hli_units_per_mm = 10000.0;

}  // namespace hil
