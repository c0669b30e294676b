#pragma once
// One scenario run as several variants (RIG-5): each its own run, with its
// own machine, or PLC timeline, or more expectations; the rest of the file is
// shared; `compare:` checks the variants against each other
// (docs/SCENARIOS.md, "Variants").
#include <string>
#include <vector>

#include "scenario.hpp"

namespace hil {

struct ScenarioVariant {
  std::string name;   // "" for a scenario without variants
  Scenario scenario;  // with this variant's machine, timeline, expectations; named <scenario>.<variant>
};

// axis_max_mm / axis_min_mm: "the highest (lowest) commanded position of
// `axis` in variant `greater` exceeds that of `than` by more than by_at_least_mm".
// same_path (DPS-3): "`variant`'s commanded positions over dist_prog_start,
// beyond from_dist_mm, are those of `reference` within tolerance_mm"
// (logger/same_path.hpp).
struct VariantComparison {
  std::string key;
  std::string axis;
  std::string greater, than;
  double by_at_least_mm = 0;
  std::string reference, variant;
  double from_dist_mm = 0, tolerance_mm = 0.001;
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
