#pragma once
// The rig's LCM channel names (docs/ARCHITECTURE.md).
#include <string>

namespace hil::channels {

inline const std::string hli_control = "HLI_CONTROL";
inline const std::string hli_state = "HLI_STATE";
inline const std::string event = "HIL_EVENT";
inline const std::string manifest = "HIL_MANIFEST";
inline const std::string participant = "HIL_PARTICIPANT";

inline std::string axis_command(const std::string& axis) { return "AXIS_" + axis + "_CMD"; }
inline std::string axis_state(const std::string& axis) { return "AXIS_" + axis + "_STATE"; }

}  // namespace hil::channels
