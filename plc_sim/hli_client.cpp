#include "hli_client.hpp"

#include <utility>

namespace hil::plc {
namespace {

// The control units the CNC implements, by their TF5200 names.
const std::vector<std::pair<std::string, ControlUnitBool HliControl::*>> bool_units = {
    {"program_start", &HliControl::program_start},
    {"feedhold", &HliControl::feedhold},
    {"delete_distance_to_go", &HliControl::delete_distance_to_go},
    {"m_function_ack", &HliControl::m_function_ack},
    {"backward_motion", &HliControl::backward_motion},
};
const std::vector<std::pair<std::string, ControlUnitValue HliControl::*>> value_units = {
    {"override", &HliControl::override},
    {"delete_distance_to_go_activation", &HliControl::delete_distance_to_go_activation},
};

bool write_bool(bool& field, int32_t value) {
  if (value != 0 && value != 1) return false;
  field = value != 0;
  return true;
}

}  // namespace

bool write_control_field(HliControl& control, const std::string& name, int32_t value) {
  for (const auto& [unit_name, member] : bool_units) {
    ControlUnitBool& unit = control.*member;
    if (name == unit_name + ".command_w") return write_bool(unit.command_w, value);
    if (name == unit_name + ".enable_w") return write_bool(unit.enable_w, value);
  }
  for (const auto& [unit_name, member] : value_units) {
    ControlUnitValue& unit = control.*member;
    if (name == unit_name + ".command_w") {
      unit.command_w = value;
      return true;
    }
    if (name == unit_name + ".enable_w") return write_bool(unit.enable_w, value);
  }
  return false;
}

std::vector<std::string> control_field_names() {
  std::vector<std::string> names;
  for (const auto& unit : bool_units) {
    names.push_back(unit.first + ".command_w");
    names.push_back(unit.first + ".enable_w");
  }
  for (const auto& unit : value_units) {
    names.push_back(unit.first + (unit.first == "override" ? ".command_w (0.1 %)" : ".command_w (mask)"));
    names.push_back(unit.first + ".enable_w");
  }
  return names;
}

}  // namespace hil::plc
