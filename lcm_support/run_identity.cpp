#include "run_identity.hpp"

#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

#include "config_error.hpp"

namespace hil {

int64_t new_run_id() {
  std::random_device device;
  std::mt19937_64 generator((static_cast<uint64_t>(device()) << 32) ^ device());
  std::uniform_int_distribution<int64_t> id(1, INT64_MAX);
  return id(generator);
}

int64_t scenario_digest(std::string_view yaml, std::string_view nc_program) {
  uint64_t h = 14695981039346656037ull;
  for (const std::string_view text : {yaml, nc_program})
    for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return static_cast<int64_t>(h);
}

Scenario scenario_from_text(const std::string& yaml, const std::string& nc_program) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("scenario: ") + e.what());
  }
  if (!root.IsMap()) throw ConfigError("scenario: expected a mapping at the top");
  if (root["nc_file"]) {  // as hil run writes it: the program beside the YAML
    root.remove("nc_file");
    root["nc_program"] = nc_program;
  }
  return parse_scenario(root);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace hil
