#include "scenario_set.hpp"
#include "file_keys.hpp"

#include <algorithm>

#include "config_error.hpp"

namespace hil {
namespace {

const std::vector<std::string> variant_keys = {"name", "machine", "plc", "expect"};
const std::vector<std::string> comparison_keys = {"axis_max_mm", "axis_min_mm", "greater", "than", "by_at_least_mm",
                                                  "same_path"};
const std::vector<std::string> same_path_keys = {"reference", "variant", "from_dist_mm", "tolerance_mm"};

bool plain_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

const ScenarioVariant* variant_named(const ScenarioSet& set, const std::string& name) {
  for (const ScenarioVariant& v : set.variants)
    if (v.name == name) return &v;
  return nullptr;
}

// Both runs must have the same axes: a path is all of them.
VariantComparison read_same_path(const ConfigMap& entry, const std::string& where, const ScenarioSet& set) {
  for (const char* other : {"axis_max_mm", "axis_min_mm", "greater", "than", "by_at_least_mm"})
    if (entry.has(other)) throw ConfigError(entry.path(other) + ": not with same_path");
  const ConfigMap m(entry["same_path"], where + ".same_path", same_path_keys);
  VariantComparison c;
  c.key = "same_path";
  c.reference = m.text("reference");
  c.variant = m.text("variant");
  m.get("from_dist_mm", c.from_dist_mm, Bounds{0, 1e9});
  m.get("tolerance_mm", c.tolerance_mm, Bounds{0, 1e9});
  const ScenarioVariant* reference = variant_named(set, c.reference);
  const ScenarioVariant* variant = variant_named(set, c.variant);
  if (!reference) throw ConfigError(m.path("reference") + ": '" + c.reference + "' is no variant of this scenario");
  if (!variant) throw ConfigError(m.path("variant") + ": '" + c.variant + "' is no variant of this scenario");
  if (c.reference == c.variant) throw ConfigError(where + ".same_path: reference and variant name the same variant");
  auto names = [](const ScenarioVariant& v) {
    std::vector<std::string> axes;
    for (const AxisConfig& a : v.scenario.machine.axes) axes.push_back(a.name);
    std::sort(axes.begin(), axes.end());
    return axes;
  };
  if (names(*reference) != names(*variant))
    throw ConfigError(where + ".same_path: the machines of " + c.reference + " and " + c.variant +
                      " have different axes (a path is all of them)");
  return c;
}

VariantComparison read_comparison(const YAML::Node& node, const std::string& where, const ScenarioSet& set) {
  const ConfigMap m(node, where, comparison_keys);
  if (m.has("same_path")) return read_same_path(m, where, set);
  VariantComparison c;
  for (const char* key : {"axis_max_mm", "axis_min_mm"}) {
    if (!m.has(key)) continue;
    if (!c.key.empty()) throw ConfigError(where + ": give one of axis_max_mm and axis_min_mm, not both");
    c.key = key;
    c.axis = m.text(key);
  }
  if (c.key.empty()) throw ConfigError(where + ": axis_max_mm, axis_min_mm (an axis name) or same_path is missing");
  c.greater = m.text("greater");
  c.than = m.text("than");
  m.get("by_at_least_mm", c.by_at_least_mm, Bounds{0, 1e9});
  auto known = [&](const std::string& name, const std::string& key) {
    const ScenarioVariant* v = variant_named(set, name);
    if (!v) throw ConfigError(m.path(key) + ": '" + name + "' is no variant of this scenario");
    if (v->scenario.machine.axis_index(c.axis) < 0)
      throw ConfigError(m.path(c.key) + ": axis '" + c.axis + "' is not on the machine of variant " + name);
  };
  known(c.greater, "greater");
  known(c.than, "than");
  if (c.greater == c.than) throw ConfigError(where + ": greater and than name the same variant");
  return c;
}

// The scenario of one variant: the file without `variants` and `compare`,
// with the variant's machine (or the file's), its plc keys in place of the
// file's, its expectations after the file's.
YAML::Node variant_scenario(const YAML::Node& root, const ConfigMap& m, const std::string& name,
                            const std::string& path) {
  YAML::Node one = YAML::Clone(root);
  one.remove("variants");
  one.remove("compare");
  if (m.has("machine")) one["machine"] = YAML::Clone(m["machine"]);
  else if (!root["machine"])
    throw ConfigError(path + ": " + m.path("machine") + ": variant " + name +
                      " has no machine: give machine: in it or beside variants");
  if (m.has("plc")) {
    if (!m["plc"].IsMap()) throw ConfigError(path + ": " + m.path("plc") + ": must be a mapping");
    if (!one["plc"] || one["plc"].IsNull()) one["plc"] = YAML::Node(YAML::NodeType::Map);
    if (one["plc"].IsMap())  // else the scenario's own plc: is refused when the variant is read
      for (const auto& entry : m["plc"]) one["plc"][entry.first.Scalar()] = YAML::Clone(entry.second);
  }
  if (m.has("expect")) {
    if (!m["expect"].IsSequence()) throw ConfigError(path + ": " + m.path("expect") + ": must be a list");
    if (!one["expect"] || one["expect"].IsNull()) one["expect"] = YAML::Node(YAML::NodeType::Sequence);
    if (one["expect"].IsSequence())
      for (const auto& e : m["expect"]) one["expect"].push_back(YAML::Clone(e));
  }
  return one;
}

}  // namespace

ScenarioSet load_scenario_set_node(const YAML::Node& root, const std::string& path) {
  ScenarioSet set;
  if (!root.IsMap() || !root["variants"]) {
    if (root.IsMap() && root["compare"]) throw ConfigError(path + ": compare: needs variants");
    set.variants.push_back({"", load_scenario_node(YAML::Clone(root), path)});
    locate_nc_program(set.variants.back().scenario, root, path);
    set.name = set.variants.front().scenario.name;
    return set;
  }
  const YAML::Node variants = root["variants"];
  if (!variants.IsSequence() || variants.size() == 0)
    throw ConfigError(path + ": variants: must be a list of {name, machine, plc, expect}");
  const std::string scenario_name = root["name"] ? config_text(root["name"], "name") : std::string("scenario");
  set.name = scenario_name;
  const YAML::Node shared_expect = root["expect"];
  const size_t shared_expectations = shared_expect && shared_expect.IsSequence() ? shared_expect.size() : 0;
  for (size_t i = 0; i < variants.size(); ++i) {
    const std::string where = index_path("variants", i);
    ConfigMap m(variants[i], where, variant_keys);
    const std::string name = m.text("name");
    if (!plain_name(name))
      throw ConfigError(path + ": " + m.path("name") + ": letters, digits, '_' and '-' only (it names a folder)");
    if (variant_named(set, name)) throw ConfigError(path + ": " + m.path("name") + ": '" + name + "' given twice");
    YAML::Node one = variant_scenario(root, m, name, path);
    one["name"] = scenario_name + "." + name;
    try {
      set.variants.push_back({name, load_scenario_node(one, path)});
      locate_nc_program(set.variants.back().scenario, root, path);
    } catch (const ConfigError& e) {
      // The variant's plc keys stand in plc, its expectations after the file's.
      std::string own;
      if (m.has("plc")) own += "; its plc: keys stand in plc";
      if (m.has("expect")) own += "; its expect: entries follow the file's " + std::to_string(shared_expectations);
      throw ConfigError(std::string(e.what()) + " (variant " + name + own + ")");
    }
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

const std::vector<std::string>& file_keys::variant() { return variant_keys; }
const std::vector<std::string>& file_keys::comparison() { return comparison_keys; }
const std::vector<std::string>& file_keys::same_path() { return same_path_keys; }

}  // namespace hil
