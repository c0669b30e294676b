#include "run_summary.hpp"

#include <yaml-cpp/yaml.h>

#include <array>
#include <fstream>
#include <stdexcept>

namespace hil::rig {
namespace {

constexpr std::array<std::pair<Outcome, const char*>, 4> names{
    {{Outcome::passed, "PASSED"}, {Outcome::failed, "FAILED"}, {Outcome::error, "ERROR"}, {Outcome::skipped, "SKIPPED"}}};

}  // namespace

const char* outcome_name(Outcome outcome) {
  for (const auto& [o, name] : names)
    if (o == outcome) return name;
  return "ERROR";
}

std::optional<Outcome> outcome_of(const std::string& name) {
  for (const auto& [o, n] : names)
    if (name == n) return o;
  return std::nullopt;
}

void write_run_summary(const RunSummary& s, const std::string& path) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "scenario_file" << YAML::Value << s.scenario_file << YAML::Key << "name"
      << YAML::Value << s.name << YAML::Key << "requirements" << YAML::Value << YAML::Flow << s.requirements
      << YAML::Key << "outcome" << YAML::Value << outcome_name(s.outcome) << YAML::Key << "simulated_s"
      << YAML::Value << s.simulated_s << YAML::Key << "wall_s" << YAML::Value << s.wall_s << YAML::Key
      << "first_failure" << YAML::Value << s.first_failure << YAML::Key << "run_dir" << YAML::Value << s.run_dir
      << YAML::EndMap;
  std::ofstream(path) << out.c_str() << '\n';
}

RunSummary read_run_summary(const std::string& path) {
  try {
    const YAML::Node n = YAML::LoadFile(path);
    RunSummary s;
    s.scenario_file = n["scenario_file"].as<std::string>();
    s.name = n["name"].as<std::string>();
    s.requirements = n["requirements"].as<std::vector<std::string>>();
    const std::optional<Outcome> outcome = outcome_of(n["outcome"].as<std::string>());
    if (!outcome) throw std::runtime_error("unknown outcome " + n["outcome"].as<std::string>());
    s.outcome = *outcome;
    s.simulated_s = n["simulated_s"].as<double>();
    s.wall_s = n["wall_s"].as<double>();
    s.first_failure = n["first_failure"].as<std::string>();
    s.run_dir = n["run_dir"].as<std::string>();
    return s;
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": not a run summary: " + e.what());
  }
}

}  // namespace hil::rig
