#pragma once
// What a node that failed said (issue 19): its last error line from its
// output file in the run folder, so that `hil run` shows why a run could not
// even start (LCM without a multicast route, a port in use) instead of only
// "cannot open LCM log".
#include <string>
#include <vector>

#include "verdict.hpp"

namespace hil::rig {

// The output file of a node of a run folder: cnc.out, axis_sim_X.out, ...
std::string node_output_file(const std::string& run_dir, const std::string& node_name);

struct NodeErrors {
  std::vector<std::string> nodes;  // "cnc (exit status 1): cannot open LCM on udpm://..." per node that failed
  std::string hint;                // how to give the machine a multicast route, if LCM said "No route"
  // "node errors:" and a line each, the hint last; "" if every node ended well.
  std::string text() const;
  // The first node's line and the hint, for a summary's one line.
  std::string first() const;
};

// Every node that did not exit 0: its name, status and last error line
// (from its output file in the run folder, or nodes.out in-process).
NodeErrors find_node_errors(const std::vector<logger::ProcessExit>& exits, const std::string& run_dir,
                            bool in_process);

}  // namespace hil::rig
