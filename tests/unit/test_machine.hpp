#pragma once
// The machine the unit tests run on: the shipped config/xyz_machine.yaml.
#include <yaml-cpp/yaml.h>

#include "machine_config.hpp"

namespace hil::test {

inline MachineConfig xyz_machine() {
  return parse_machine_config(YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml"));
}

}  // namespace hil::test
