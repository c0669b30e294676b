#pragma once
// A range a scenario compares a number with (RIG-5): `{min: 1.5, max: 2}`,
// both bounds inclusive, either may be left out. A plain number in a
// scenario is a range too: in a trigger a lower bound (the value has been
// reached), in an expectation the value itself (docs/SCENARIOS.md).
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>

#include "config_error.hpp"

namespace hil {

struct ValueRange {
  std::optional<double> min, max;

  static ValueRange at_least(double value) { return {value, std::nullopt}; }
  static ValueRange exactly(double value) { return {value, value}; }
  static ValueRange around(double value, double tolerance) { return {value - tolerance, value + tolerance}; }

  bool contains(double value) const { return (!min || value >= *min) && (!max || value <= *max); }
  // "cycle>=5", "block_nr_r=40", "1<=X<=2", "path_velocity_mm_s<=10".
  std::string describe(const std::string& name) const;
};

// A number as a scenario's messages show it: whole numbers without a
// fraction or exponent ("4294967295", not "4.29497e+09"), others with 10
// significant digits ("100.0011").
std::string number_text(double value);

// `{min: .., max: ..}` at `where`. Refused (ConfigError naming the key): no
// mapping, another key, neither bound, min > max, a bound outside `bounds`.
ValueRange parse_value_range(const YAML::Node& node, const std::string& where, Bounds bounds = any_finite);
// The same with whole-number bounds within lo .. hi (HLI integer fields).
ValueRange parse_whole_range(const YAML::Node& node, const std::string& where, int64_t lo, int64_t hi);

}  // namespace hil
