#pragma once
// The HLI (PLC <-> CNC interface, KRN-4) as plain values. The CNC's channel
// library fills HliState, the PLC simulator writes HliControl; the nodes
// translate both to and from the LCM types hli_state_t / hli_control_t.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hil {

enum class ChannelState : int8_t { ready = 0, active = 1, program_end = 2, error = 3 };

const char* to_string(ChannelState state);
// "READY", "ACTIVE", "PROGRAM_END", "ERROR" (case-insensitive); false if unknown.
bool parse_channel_state(const std::string& text, ChannelState& state);

// HLI_SC_* bits of stop_conditions_r (TF5200_insert_stop_cmd.txt, table of
// stop conditions); only the ones the channel sets so far.
namespace stop_condition {
constexpr int32_t feedhold = 0x0001;          // HLI_SC_FEEDHOLD
constexpr int32_t override_zero = 0x0040;     // HLI_SC_OVERRIDE_ZERO
constexpr int32_t ipo_input_empty = 0x1000;   // HLI_SC_IPO_INPUT_EMPTY
constexpr int32_t channel_error = 0x00010000;  // HLI_SC_CHANNEL_ERROR
}  // namespace stop_condition

struct ControlUnitBool {
  bool command_w = false;
  bool enable_w = false;
};

struct ControlUnitState {
  bool request_r = false;
  bool state_r = false;
};

struct ControlUnitValue {
  int32_t command_w = 0;
  bool enable_w = false;
};

struct ControlUnitValueState {
  bool request_r = false;
  int32_t state_r = 0;
};

// Override values are in 0.1 % (1000 = 100 %).
constexpr int32_t override_full = 1000;

struct HliControl {
  int64_t cycle = -1;  // the HLI_STATE cycle this answers
  ControlUnitBool program_start;
  ControlUnitBool feedhold;
  ControlUnitValue override;
  ControlUnitBool delete_distance_to_go;
  ControlUnitValue delete_distance_to_go_activation;
  // A rising edge of command_w while enable_w acknowledges the M function
  // the CNC waits for (m_function_request_r).
  ControlUnitBool m_function_ack;
  // Backward motion on the path (bahn_mc_control.backward_motion): not built;
  // a request holds the path with a warning until withdrawn (DDTG-10).
  ControlUnitBool backward_motion;
};

struct HliState {
  int64_t cycle = 0;
  ChannelState channel_state = ChannelState::ready;
  int64_t block_nr_r = 0;
  int64_t block_count_r = 0;
  int32_t stop_conditions_r = 0;
  double dist_prog_start = 0;     // 0.1 um
  double path_velocity = 0;       // mm/s
  int32_t last_error_id = 0;
  std::vector<std::string> axis_name;
  std::vector<int64_t> axis_position_r;  // 0.1 um
  ControlUnitState program_start;
  ControlUnitState feedhold;
  ControlUnitValueState override;
  ControlUnitState delete_distance_to_go;
  ControlUnitValueState delete_distance_to_go_activation;
  bool delete_distance_to_go_active_r = false;  // a short cut runs (DDTG-4)
  // An M function is output and the path waits for the PLC's
  // acknowledgement (MVS_SVS); its number.
  bool m_function_request_r = false;
  int32_t m_function_nr_r = 0;
  ControlUnitState backward_motion;  // state_r stays FALSE: never moving backward
};

// The control units' request_r / state_r and the state flags by their
// TF5200 names ("delete_distance_to_go.state_r", "m_function_request_r"),
// for scenarios; TRUE / FALSE read as 1 / 0. None: no such field.
std::optional<int64_t> read_state_field(const HliState& state, const std::string& name);
std::vector<std::string> state_field_names();

// HLI length unit: 0.1 um.
constexpr double hli_units_per_mm = 10000.0;

}  // namespace hil
