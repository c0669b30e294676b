#include "node_options.hpp"

#include <spdlog/spdlog.h>

#include <exception>

namespace hil::lcm_support {

void add_node_options(CLI::App& app, NodeOptions& options) {
  app.add_option("--scenario", options.scenario_file, "resolved scenario YAML (as hil run writes it)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--url", options.url, "LCM URL of the rig, e.g. udpm://239.255.76.67:7667?ttl=0")
      ->required();
  app.add_option("--run-id", options.run_id, "the run's id: every message carries it, others are refused")
      ->required()
      ->check(CLI::PositiveNumber);
}

int guarded_main(const std::string& node_name, const std::function<int()>& body) {
  spdlog::set_pattern("[%H:%M:%S.%e] [" + node_name + "] [%l] %v");
  try {
    return body();
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}

}  // namespace hil::lcm_support
