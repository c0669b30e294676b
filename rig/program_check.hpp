#pragma once
// KRN-8 (issue 34): a scenario's NC program decodes as a whole before any
// process starts, so that a program the decoder refuses is a refused
// scenario (exit status 2) with its line, not a run that stops midway.
#include <string>
#include <vector>

#include "scenario.hpp"

namespace hil::rig {

// Throws ConfigError "nc_program line L column C (N..): <message>" if the
// decoder refuses the program from the axes' start positions (0). Block
// skip levels are off: every line is checked. A scenario that expects an
// error event or allows errors is a test of the error itself: not checked.
void check_nc_program(const Scenario& scenario);

// `hil validate FILE...`: each scenario file (with its variants) loaded and
// checked as `hil run` would, nothing run; "FILE: ok" or its error on
// stdout. 0 if all are valid, 2 if not.
int validate_scenario_files(const std::vector<std::string>& files);

}  // namespace hil::rig
