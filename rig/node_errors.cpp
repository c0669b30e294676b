#include "node_errors.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

constexpr const char* multicast_hint =
    "LCM found no multicast route: give loopback one (as root: ip link set lo multicast on; ip route add "
    "224.0.0.0/4 dev lo), run the suite in network namespaces (hil run --netns, as root), or run --in-process";

struct NodeOutput {
  std::string last_error;  // spdlog's "[error]" line, else the last non-empty line
  bool no_route = false;
};

NodeOutput read_output(const std::string& file, const std::string& node) {
  NodeOutput o;
  std::ifstream in(file);
  std::string line, last;
  const std::string tag = "[" + node + "] [error] ";
  while (std::getline(in, line)) {
    if (line.find("No route") != std::string::npos || line.find("multicast_setup") != std::string::npos)
      o.no_route = true;
    // In-process, every node writes into one file: only this node's lines.
    if (const size_t at = line.find(tag); at != std::string::npos) o.last_error = line.substr(at + tag.size());
    else if (line.find("] [error] ") != std::string::npos) continue;
    else if (line.find_first_not_of(" \t") != std::string::npos) last = line;
  }
  if (o.last_error.empty()) o.last_error = last;
  return o;
}

}  // namespace

std::string node_output_file(const std::string& run_dir, const std::string& node_name) {
  std::string file = node_name;
  std::replace(file.begin(), file.end(), ' ', '_');
  return (fs::path(run_dir) / (file + ".out")).string();
}

NodeErrors find_node_errors(const std::vector<logger::ProcessExit>& exits, const std::string& run_dir,
                            bool in_process) {
  NodeErrors errors;
  for (const logger::ProcessExit& e : exits) {
    if (e.status && *e.status == 0) continue;
    const NodeOutput o = read_output(
        in_process ? (fs::path(run_dir) / "nodes.out").string() : node_output_file(run_dir, e.name), e.name);
    if (o.no_route) errors.hint = multicast_hint;
    errors.nodes.push_back(e.name + " (" + (e.status ? "exit status " + std::to_string(*e.status) : "hung") +
                           "): " + (o.last_error.empty() ? "no output" : o.last_error));
  }
  return errors;
}

std::string NodeErrors::text() const {
  if (nodes.empty()) return "";
  std::string out = "node errors:\n";
  for (const std::string& line : nodes) out += "  " + line + '\n';
  return hint.empty() ? out : out + "  " + hint + '\n';
}

std::string NodeErrors::first() const {
  if (nodes.empty()) return "";
  return nodes.front() + (hint.empty() ? "" : "; " + hint);
}

}  // namespace hil::rig
