#pragma once
// A run's identity (RIG-9): the id every rig message carries, so that
// receivers tell this run from another rig on the same port or a replay,
// and the digest of the scenario every node runs. No LCM in here.
#include <cstdint>
#include <string>
#include <string_view>

#include "scenario.hpp"

namespace hil {

// A random id > 0 for a new run.
int64_t new_run_id();

// FNV-1a, 64 bits, over the resolved scenario file's text and its NC
// program: tells runs of different scenarios apart (not a defence against
// forgery).
int64_t scenario_digest(std::string_view yaml, std::string_view nc_program);

// The scenario of a log (HIL_SCENARIO): the YAML with its NC program put in
// where it names an nc_file.
// Throws ConfigError as parse_scenario does.
Scenario scenario_from_text(const std::string& yaml, const std::string& nc_program);

// A whole file as text; throws std::runtime_error naming it.
std::string read_text(const std::string& path);

}  // namespace hil
