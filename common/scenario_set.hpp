#pragma once
// One scenario run on several machines (RIG-5): `variants:` names a machine
// each, the rest of the file is shared; `compare:` checks the variants
// against each other (docs/SCENARIOS.md, "Variants").
#include <string>
#include <vector>

#include "scenario.hpp"

namespace hil {

struct ScenarioVariant {
  std::string name;   // "" for a scenario without variants
  Scenario scenario;  // with this variant's machine; named <scenario>.<variant>
};

// "the highest (axis_max_mm) or lowest (axis_min_mm) commanded position of
// `axis` in variant `greater` exceeds that of `than` by more than by_at_least_mm".
struct VariantComparison {
  std::string key;
  std::string axis;
  std::string greater, than;
  double by_at_least_mm = 0;
};

struct ScenarioSet {
  std::string name;
  std::vector<ScenarioVariant> variants;  // one, named "", without `variants:`
  std::vector<VariantComparison> comparisons;
  bool has_variants() const { return !variants.empty() && !variants.front().name.empty(); }
};

// Reads a scenario file with or without `variants:`. Throws ConfigError
// naming the file and the key's path, as load_scenario_file does.
ScenarioSet load_scenario_set(const std::string& path);
ScenarioSet load_scenario_set_node(const YAML::Node& root, const std::string& path);

}  // namespace hil
