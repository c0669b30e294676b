#pragma once
// The machine the unit tests run on: the shipped config/xyz_machine.yaml.
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>
#include <string>

#include "machine_config.hpp"

namespace hil::test {

// The text of a file of the source tree, by its path from the tree's root.
inline std::string source_text(const std::string& relative) {
  std::ifstream in(std::string(HIL_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline MachineConfig xyz_machine() {
  return parse_machine_config(YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml"));
}

// X Y Z and a modulo rotary table C (KRN-7): config/xyzc_machine.yaml.
inline MachineConfig xyzc_machine() {
  return parse_machine_config(YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyzc_machine.yaml"));
}

// config/xyz_machine.yaml with Advanced Lifting (LIFT-2): config/xyz_lift_machine.yaml.
inline MachineConfig xyz_lift_machine() {
  return parse_machine_config(YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_lift_machine.yaml"));
}

// ... with Lifting (path-based, LIFT-3): config/xyz_lifting_machine.yaml.
inline MachineConfig xyz_lifting_machine() {
  return parse_machine_config(YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_lifting_machine.yaml"));
}

// ... with Advanced Lifting on a stiff Z (j_max 90,000, P-AXIS-00442 1600):
// config/xyz_lift_stiff_machine.yaml.
inline MachineConfig xyz_lift_stiff_machine() {
  return parse_machine_config(YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_lift_stiff_machine.yaml"));
}

}  // namespace hil::test
