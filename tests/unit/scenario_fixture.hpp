#pragma once
// RIG-5: a one-axis machine (X) and a scenario on it from the YAML of its
// timeline and expectations, for the scenario language's tests.
#include <string>

#include "scenario.hpp"

namespace hil::test {

inline const std::string one_axis_machine_yaml = R"(
machine:
  cycle_time_us: 1000
  axes:
    - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}
)";

inline Scenario one_axis_scenario(const std::string& rest) {
  return parse_scenario(YAML::Load(one_axis_machine_yaml + "nc_program: \"G01 X1 F100\\n\"\n" + rest));
}

}  // namespace hil::test
