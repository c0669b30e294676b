#pragma once
// The PLC's side of the HLI: control unit fields by name (KRN-4).
#include <string>
#include <vector>

#include "hli.hpp"

namespace hil::plc {

// The field "unit.command_w" / "unit.enable_w" of `control`, nullptr if
// there is no such field.
bool* control_field(HliControl& control, const std::string& name);

// Every field name control_field() knows, for messages.
std::vector<std::string> control_field_names();

}  // namespace hil::plc
