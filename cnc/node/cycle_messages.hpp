#pragma once
// What the CNC publishes for one cycle, encoded: its events, one setpoint
// per axis, the HLI state (RIG-1), each stamped with the run's id. One
// place, so that the live node and `cnc --rerun` produce the same bytes.
#include <cstdint>
#include <string>
#include <vector>

#include "channel.hpp"
#include "cycle_loop.hpp"
#include "machine_config.hpp"

namespace hil::cnc_node {

struct EncodedMessage {
  std::string channel;
  std::vector<uint8_t> bytes;
};

std::vector<EncodedMessage> cycle_messages(const cnc::Channel& channel, const MachineConfig& machine,
                                           const std::vector<Event>& events, int64_t cycle, int64_t run_id);

// The axes' monitoring error bits answering a cycle (axis_state_t.errors,
// by machine axis) as the drive errors the channel takes (RIG-3).
std::vector<cnc::DriveError> drive_errors(const MachineConfig& machine, const std::vector<int32_t>& errors);

// An event of the CNC, encoded for HIL_EVENT.
EncodedMessage event_message(const Event& event, const MachineConfig& machine, int64_t cycle, int64_t run_id);

}  // namespace hil::cnc_node
