#include "node_options.hpp"

#include <spdlog/spdlog.h>

#include <exception>

#include "authenticated_bus.hpp"
#include "run_secret.hpp"

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
  add_key_file_option(app, options.key_file);
}

CLI::Option* add_key_file_option(CLI::App& app, std::string& key_file) {
  return app
      .add_option("--key-file", key_file,
                  "the run's secret (RIG-12; hil run writes run.key into the run folder): every message sent is signed "
                  "with it, every message of the run without its MAC refused")
      ->check(CLI::ExistingFile);
}

std::unique_ptr<Bus> run_bus(const std::string& url, const std::string& key_file, int64_t run_id,
                             UdpmReceive receive) {
  std::unique_ptr<Bus> bus = node_bus(url, receive);
  if (key_file.empty()) return bus;
  return std::make_unique<AuthenticatedBus>(std::move(bus), RunSecret::read(key_file), run_id);
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
