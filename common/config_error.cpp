#include "config_error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

namespace hil {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// Optimal string alignment distance: insertions, deletions, substitutions
// and swaps of neighbours ("slpe_max") each count 1.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// What a value was, for messages: its text, or what kind of node it is.
std::string shown(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string range_text(Bounds b) {
  const bool has_min = std::isfinite(b.min), has_max = std::isfinite(b.max);
  const std::string low = (b.min_open ? "> " : ">= ") + number_text(b.min);
  if (has_min && has_max)
    return b.min_open ? low + " and <= " + number_text(b.max)
                      : "within " + number_text(b.min) + " .. " + number_text(b.max);
  if (has_min) return low;
  if (has_max) return "<= " + number_text(b.max);
  return "";
}

std::string bounds_text(Bounds b) { return range_text(b) + (*b.unit ? std::string(" ") + b.unit : ""); }

// A number written non-zero that a double cannot hold as a normal number:
// 1e-320 reads as a subnormal, 1e-400 as 0. No quantity of a rig is that
// small; such a value is a slip (a lost exponent sign, a unit far off), and
// subnormal arithmetic is many times slower, in every cycle.
bool underflows(const std::string& text, double value) {
  if (std::fpclassify(value) == FP_SUBNORMAL) return true;
  return value == 0 && text.substr(0, text.find_first_of("eE")).find_first_of("123456789") != std::string::npos;
}

ConfigError bad_value(const std::string& where, const std::string& wanted, const YAML::Node& node) {
  return ConfigError(where + ": must be " + wanted + ", not " + shown(node));
}

}  // namespace

std::string key_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string index_path(const std::string& parent, size_t index) { return parent + "[" + std::to_string(index) + "]"; }

std::string closest_key(const std::string& key, const std::vector<std::string>& known) {
  const std::string wanted = lower(key);
  std::string best;
  size_t best_distance = std::string::npos;
  for (const std::string& candidate : known) {
    const size_t distance = edit_distance(wanted, lower(candidate));
    if (distance < best_distance) best = candidate, best_distance = distance;
  }
  // Near: a slip of two characters, or of a third of the key.
  if (!best.empty() && (best_distance <= 2 || best_distance <= key.size() / 3)) return best;
  // "expectations" for "expect": a known key the unknown one begins with (or the reverse).
  for (const std::string& candidate : known) {
    const std::string c = lower(candidate);
    if (std::min(c.size(), wanted.size()) >= 3 &&
        (wanted.compare(0, c.size(), c) == 0 || c.compare(0, wanted.size(), wanted) == 0))
      return candidate;
  }
  return "";
}

ConfigError unknown_key(const std::string& where, const std::string& key, const std::vector<std::string>& known,
                        const std::string& noun) {
  const std::string nearest = closest_key(key, known);
  if (!nearest.empty())
    return ConfigError(key_path(where, key) + ": unknown " + noun + ", did you mean " + nearest + "?");
  std::string names;
  for (const std::string& name : known) names += (names.empty() ? "" : ", ") + name;
  return ConfigError(key_path(where, key) + ": unknown " + noun + " (known: " + names + ")");
}

ConfigMap::ConfigMap(const YAML::Node& node, std::string where, const std::vector<std::string>& known,
                     const std::string& noun)
    : node_(node), where_(std::move(where)) {
  if (!node_.IsMap()) throw bad_value(where_.empty() ? "the file" : where_, "a mapping", node_);
  std::set<std::string> seen;
  for (const auto& item : node_) {
    if (!item.first.IsScalar()) throw ConfigError(where_ + ": a key must be a name, not " + shown(item.first));
    const std::string& key = item.first.Scalar();
    if (std::find(known.begin(), known.end(), key) == known.end()) throw unknown_key(where_, key, known, noun);
    if (!seen.insert(key).second) throw ConfigError(path(key) + ": given twice (YAML would keep the first)");
  }
}

bool ConfigMap::has(const std::string& key) const { return static_cast<bool>(node_[key]); }

double ConfigMap::number(const std::string& key, Bounds bounds) const {
  if (!has(key)) throw ConfigError(path(key) + ": missing");
  return config_number(node_[key], path(key), bounds);
}

int64_t ConfigMap::whole(const std::string& key, int64_t min, int64_t max) const {
  if (!has(key)) throw ConfigError(path(key) + ": missing");
  return config_whole(node_[key], path(key), min, max);
}

std::string ConfigMap::text(const std::string& key) const {
  if (!has(key)) throw ConfigError(path(key) + ": missing");
  return config_text(node_[key], path(key));
}

bool ConfigMap::get(const std::string& key, double& value, Bounds bounds) const {
  if (!has(key)) return false;
  value = number(key, bounds);
  return true;
}

bool ConfigMap::get(const std::string& key, bool& value) const {
  if (!has(key)) return false;
  value = config_bool(node_[key], path(key));
  return true;
}

bool ConfigMap::get(const std::string& key, std::string& value) const {
  if (!has(key)) return false;
  value = text(key);
  return true;
}

double config_number(const YAML::Node& node, const std::string& where, Bounds bounds) {
  const std::string wanted =
      std::isfinite(bounds.min) || std::isfinite(bounds.max) ? "a number " + bounds_text(bounds) : "a finite number";
  double value = 0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value) || value < bounds.min ||
      (bounds.min_open && value == bounds.min) || value > bounds.max)
    throw bad_value(where, wanted, node);
  if (underflows(node.Scalar(), value))
    throw ConfigError(where + ": must be " + wanted + ", not " + node.Scalar() +
                      " (below the smallest normal double, 2.2e-308: write 0 for none)");
  return value;
}

int64_t config_whole(const YAML::Node& node, const std::string& where, int64_t min, int64_t max) {
  const std::string wanted = "a whole number within " + std::to_string(min) + " .. " + std::to_string(max);
  int64_t value = 0;
  double real = 0;
  if (!node.IsScalar()) throw bad_value(where, wanted, node);
  if (!YAML::convert<int64_t>::decode(node, value)) {
    // 1e3 or 5.0 are whole too; 2^63 and beyond are not int64_t.
    if (!YAML::convert<double>::decode(node, real) || !std::isfinite(real) || real != std::floor(real) ||
        std::fabs(real) >= 9.2e18)
      throw bad_value(where, wanted, node);
    value = static_cast<int64_t>(real);
  }
  if (value < min || value > max) throw bad_value(where, wanted, node);
  return value;
}

bool config_bool(const YAML::Node& node, const std::string& where) {
  bool value = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) throw bad_value(where, "true or false", node);
  return value;
}

std::string config_text(const YAML::Node& node, const std::string& where) {
  if (!node.IsScalar()) throw bad_value(where, "text", node);
  return node.Scalar();
}

}  // namespace hil
