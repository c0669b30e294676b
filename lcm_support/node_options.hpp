#pragma once
// Command-line options every node shares, and the guard around its main():
// a node reports bad input as a clear error and an exit status, never a crash.
#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>

#include "bus.hpp"
#include "udpm_bus.hpp"

namespace hil::lcm_support {

struct NodeOptions {
  std::string scenario_file;  // resolved scenario (machine and NC program inline)
  std::string url;            // LCM URL of the rig
  int64_t run_id = 0;         // the run's id (hil run chooses it): messages of other runs are refused
  std::string key_file;       // the run's secret (RIG-12, hil run writes it); none: nothing signed or checked
};

void add_node_options(CLI::App& app, NodeOptions& options);
// `--key-file`: the run's secret, as hil run hands it to each node.
CLI::Option* add_key_file_option(CLI::App& app, std::string& key_file);

// A node's bus on `url` (node_bus); with a key file authenticated for run
// `run_id` (authenticated_bus.hpp).
std::unique_ptr<Bus> run_bus(const std::string& url, const std::string& key_file, int64_t run_id,
                             UdpmReceive receive = {});
inline std::unique_ptr<Bus> run_bus(const NodeOptions& options) {
  return run_bus(options.url, options.key_file, options.run_id);
}

// Runs body() and turns exceptions into an error line on stderr and exit 1.
int guarded_main(const std::string& node_name, const std::function<int()>& body);

}  // namespace hil::lcm_support
