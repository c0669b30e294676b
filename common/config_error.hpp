#pragma once
// ConfigError, and the checks every reader of a scenario or machine file
// makes with it (RIG-5): the keys of each mapping, and the values' types
// and ranges. A typo must not pass silently: a key no reader knows would
// be ignored, and with it a check or a monitor (docs/SCENARIOS.md).
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace hil {

// A scenario or machine file that cannot be used; the message names the
// file and the key's path ("machine.axes[1].slep_max").
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "machine.axes" + "slep_max" -> "machine.axes.slep_max"; "" + "run" -> "run".
std::string key_path(const std::string& parent, const std::string& key);
// "expect" + 2 -> "expect[2]".
std::string index_path(const std::string& parent, size_t index);

// The known key nearest to `key` (edit distance with transpositions, case
// ignored, or one the other begins with); "" when none is near.
std::string closest_key(const std::string& key, const std::vector<std::string>& known);
// "<where>.<key>: unknown key, did you mean slep_max?" (or the known keys
// when none is near); `noun` says what the keys are ("key", "HLI field").
ConfigError unknown_key(const std::string& where, const std::string& key, const std::vector<std::string>& known,
                        const std::string& noun = "key");

// The range a number must lie in; a bound may be open ("> 0"). `unit`, if
// any, follows the range in messages ("within 0.1 .. 1e+09 mm/s^3").
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  const char* unit = "";
};
inline constexpr Bounds any_finite{};
inline constexpr Bounds positive{0, std::numeric_limits<double>::infinity(), true};
inline constexpr Bounds non_negative{0, std::numeric_limits<double>::infinity(), false};

// One mapping of a file as a reader sees it. The constructor refuses what
// the reader would otherwise ignore: a key not in `known`, a key given twice
// (YAML keeps the first), a node that is no mapping. The getters read a
// key's value with its type and range checked (yaml-cpp reads .nan and .inf
// as numbers, so a number must also be finite; 1e-320 and 1e-400 as a
// subnormal and 0, so it must not underflow), naming the key's path.
class ConfigMap {
 public:
  ConfigMap(const YAML::Node& node, std::string where, const std::vector<std::string>& known,
            const std::string& noun = "key");

  bool has(const std::string& key) const;
  YAML::Node operator[](const std::string& key) const { return node_[key]; }
  std::string path(const std::string& key) const { return key_path(where_, key); }

  // Required: a missing key is an error.
  double number(const std::string& key, Bounds bounds = any_finite) const;
  int64_t whole(const std::string& key, int64_t min, int64_t max) const;
  std::string text(const std::string& key) const;
  // Optional: `value` keeps its default when the key is absent; true if present.
  bool get(const std::string& key, double& value, Bounds bounds = any_finite) const;
  bool get(const std::string& key, bool& value) const;
  bool get(const std::string& key, std::string& value) const;
  template <typename Int>
  bool get(const std::string& key, Int& value, int64_t min = std::numeric_limits<Int>::min(),
           int64_t max = std::numeric_limits<Int>::max()) const {
    if (!has(key)) return false;
    value = static_cast<Int>(whole(key, min, max));
    return true;
  }

 private:
  YAML::Node node_;
  std::string where_;
};

// A value on its own (a list item, a map entry), `where` its path.
double config_number(const YAML::Node& node, const std::string& where, Bounds bounds = any_finite);
int64_t config_whole(const YAML::Node& node, const std::string& where, int64_t min, int64_t max);
bool config_bool(const YAML::Node& node, const std::string& where);
std::string config_text(const YAML::Node& node, const std::string& where);

}  // namespace hil
