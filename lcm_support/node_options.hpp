#pragma once
// Command-line options every node shares, and the guard around its main():
// a node reports bad input as a clear error and an exit status, never a crash.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace hil::lcm_support {

struct NodeOptions {
  std::string scenario_file;  // resolved scenario (machine and NC program inline)
  std::string url;            // LCM URL of the rig
  int64_t run_id = 0;         // the run's id (hil run chooses it): messages of other runs are refused
};

void add_node_options(CLI::App& app, NodeOptions& options);

// Runs body() and turns exceptions into an error line on stderr and exit 1.
int guarded_main(const std::string& node_name, const std::function<int()>& body);

}  // namespace hil::lcm_support
