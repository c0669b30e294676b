#include "hli_client.hpp"

#include <utility>

namespace hil::plc {
namespace {

// The control units the CNC implements, by their TF5200 names.
const std::vector<std::pair<std::string, ControlUnitBool HliControl::*>> units = {
    {"program_start", &HliControl::program_start},
};

}  // namespace

bool* control_field(HliControl& control, const std::string& name) {
  for (const auto& [unit_name, member] : units) {
    ControlUnitBool& unit = control.*member;
    if (name == unit_name + ".command_w") return &unit.command_w;
    if (name == unit_name + ".enable_w") return &unit.enable_w;
  }
  return nullptr;
}

std::vector<std::string> control_field_names() {
  std::vector<std::string> names;
  for (const auto& unit : units) {
    names.push_back(unit.first + ".command_w");
    names.push_back(unit.first + ".enable_w");
  }
  return names;
}

}  // namespace hil::plc
