#include "scenario_set.hpp"

#include <algorithm>

#include "config_error.hpp"

namespace hil {
namespace {

const std::vector<std::string> variant_keys = {"name", "machine"};
const std::vector<std::string> comparison_keys = {"axis_max_mm", "axis_min_mm", "greater", "than", "by_at_least_mm"};

bool plain_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

VariantComparison read_comparison(const YAML::Node& node, const std::string& where, const ScenarioSet& set) {
  const ConfigMap m(node, where, comparison_keys);
  VariantComparison c;
  for (const char* key : {"axis_max_mm", "axis_min_mm"}) {
    if (!m.has(key)) continue;
    if (!c.key.empty()) throw ConfigError(where + ": give one of axis_max_mm and axis_min_mm, not both");
    c.key = key;
    c.axis = m.text(key);
  }
  if (c.key.empty()) throw ConfigError(where + ": axis_max_mm or axis_min_mm (an axis name) is missing");
  c.greater = m.text("greater");
  c.than = m.text("than");
  m.get("by_at_least_mm", c.by_at_least_mm, Bounds{0, 1e9});
  auto known = [&](const std::string& name, const std::string& key) {
    for (const ScenarioVariant& v : set.variants)
      if (v.name == name) {
        if (v.scenario.machine.axis_index(c.axis) < 0)
          throw ConfigError(m.path(c.key) + ": axis '" + c.axis + "' is not on the machine of variant " + name);
        return;
      }
    throw ConfigError(m.path(key) + ": '" + name + "' is no variant of this scenario");
  };
  known(c.greater, "greater");
  known(c.than, "than");
  if (c.greater == c.than) throw ConfigError(where + ": greater and than name the same variant");
  return c;
}

}  // namespace

ScenarioSet load_scenario_set_node(const YAML::Node& root, const std::string& path) {
  ScenarioSet set;
  if (!root.IsMap() || !root["variants"]) {
    if (root.IsMap() && root["compare"]) throw ConfigError(path + ": compare: needs variants");
    set.variants.push_back({"", load_scenario_node(YAML::Clone(root), path)});
    set.name = set.variants.front().scenario.name;
    return set;
  }
  const YAML::Node variants = root["variants"];
  if (!variants.IsSequence() || variants.size() == 0)
    throw ConfigError(path + ": variants: must be a list of {name, machine}");
  if (root["machine"]) throw ConfigError(path + ": machine: give it in each variant, not beside variants");
  for (size_t i = 0; i < variants.size(); ++i) {
    const std::string where = index_path("variants", i);
    ConfigMap m(variants[i], where, variant_keys);
    const std::string name = m.text("name");
    if (!plain_name(name))
      throw ConfigError(path + ": " + m.path("name") + ": letters, digits, '_' and '-' only (it names a folder)");
    for (const ScenarioVariant& v : set.variants)
      if (v.name == name) throw ConfigError(path + ": " + m.path("name") + ": '" + name + "' given twice");
    if (!m.has("machine")) throw ConfigError(path + ": " + m.path("machine") + ": missing");
    YAML::Node one = YAML::Clone(root);
    one.remove("variants");
    one.remove("compare");
    one["machine"] = YAML::Clone(m["machine"]);
    const std::string scenario_name = root["name"] ? config_text(root["name"], "name") : std::string("scenario");
    one["name"] = scenario_name + "." + name;
    try {
      set.variants.push_back({name, load_scenario_node(one, path)});
    } catch (const ConfigError& e) {
      throw ConfigError(std::string(e.what()) + " (variant " + name + ")");
    }
    set.name = scenario_name;
  }
  if (const YAML::Node compare = root["compare"]) {
    if (!compare.IsSequence()) throw ConfigError(path + ": compare: must be a list");
    for (size_t i = 0; i < compare.size(); ++i) {
      try {
        set.comparisons.push_back(read_comparison(compare[i], index_path("compare", i), set));
      } catch (const ConfigError& e) {
        throw ConfigError(path + ": " + e.what());
      }
    }
  }
  return set;
}

ScenarioSet load_scenario_set(const std::string& path) {
  return load_scenario_set_node(load_scenario_yaml(path), path);
}

}  // namespace hil
