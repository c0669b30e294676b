#pragma once
// The PLC's side of the HLI: control unit fields by name (KRN-4).
#include <cstdint>
#include <string>
#include <vector>

#include "hli.hpp"

namespace hil::plc {

// Writes `value` to the field "unit.command_w" / "unit.enable_w" of
// `control` (a boolean field takes value != 0); false if there is no such
// field or a boolean field gets anything but 0 or 1.
bool write_control_field(HliControl& control, const std::string& name, int32_t value);

// Every field name write_control_field() knows, for messages.
std::vector<std::string> control_field_names();

}  // namespace hil::plc
