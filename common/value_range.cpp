#include "value_range.hpp"
#include "file_keys.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace hil {
namespace {

const std::vector<std::string> range_keys = {"min", "max"};

template <typename Read>
ValueRange parse_range(const YAML::Node& node, const std::string& where, Read read) {
  if (!node.IsMap()) throw ConfigError(where + ": must be a number or a range {min: .., max: ..}");
  const ConfigMap m(node, where, range_keys);
  ValueRange r;
  if (m.has("min")) r.min = read(m, "min");
  if (m.has("max")) r.max = read(m, "max");
  // A range without bounds holds always; one no value fits, never: both are
  // mistakes in the file, not checks.
  if (!r.min && !r.max) throw ConfigError(where + ": a range needs 'min' and/or 'max'");
  if (r.min && r.max && *r.min > *r.max)
    throw ConfigError(where + ": min " + number_text(*r.min) + " is more than max " + number_text(*r.max));
  return r;
}

}  // namespace

std::string number_text(double value) {
  std::ostringstream out;
  if (std::abs(value) < 1e15 && value == std::floor(value)) out << static_cast<int64_t>(value);
  else out << std::setprecision(10) << value;  // 0.1 um in a position of metres
  return out.str();
}

std::string ValueRange::describe(const std::string& name) const {
  if (min && max && *min == *max) return name + "=" + number_text(*min);
  if (min && max) return number_text(*min) + "<=" + name + "<=" + number_text(*max);
  if (min) return name + ">=" + number_text(*min);
  return name + "<=" + number_text(max.value_or(0));
}

ValueRange parse_value_range(const YAML::Node& node, const std::string& where, Bounds bounds) {
  return parse_range(node, where, [&](const ConfigMap& m, const char* key) { return m.number(key, bounds); });
}

ValueRange parse_whole_range(const YAML::Node& node, const std::string& where, int64_t lo, int64_t hi) {
  return parse_range(node, where,
                     [&](const ConfigMap& m, const char* key) { return static_cast<double>(m.whole(key, lo, hi)); });
}

const std::vector<std::string>& file_keys::range() { return range_keys; }

}  // namespace hil
