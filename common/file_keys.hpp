#pragma once
// The keys each mapping of a scenario or machine file may have, from the
// tables the loaders check with (ConfigMap refuses any other key): the JSON
// Schema of both files (file_schema.hpp) is made from them, so an editor
// completes exactly what the rig accepts (issue 37, RIG-5).
#include <string>
#include <vector>

namespace hil::file_keys {

const std::vector<std::string>& machine();             // machine_config.cpp
const std::vector<std::string>& axis();                // machine.axes[i]
const std::vector<std::string>& zero_offset_tables();  // machine.zero_offsets: G54 .. G59
const std::vector<std::string>& scenario();            // scenario.cpp
const std::vector<std::string>& run();
const std::vector<std::string>& plc();
const std::vector<std::string>& timeline_step();  // plc.timeline[i]
const std::vector<std::string>& control();        // plc.timeline[i].set: the HLI control fields
const std::vector<std::string>& expectation();    // expect[i]
const std::vector<std::string>& condition();      // when, since, until, never, always (condition.cpp)
const std::vector<std::string>& event_expectation();      // expect_events[i]
const std::vector<std::string>& violation_expectation();  // expect_violations[i]
const std::vector<std::string>& fault();       // faults[i]: every kind and every parameter (fault_plan.cpp)
const std::vector<std::string>& variant();     // variants[i] (scenario_set.cpp)
const std::vector<std::string>& comparison();  // compare[i]
const std::vector<std::string>& same_path();   // compare[i].same_path
const std::vector<std::string>& range();       // {min, max} (value_range.cpp)

}  // namespace hil::file_keys
