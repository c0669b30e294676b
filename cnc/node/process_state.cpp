#include "process_state.hpp"

#include <fstream>

namespace hil::cnc_node {

ProcessState process_state_of_stat(const std::string& stat_line) {
  // "pid (comm) S ...": the name may hold spaces and parentheses, the
  // state follows the last ')'.
  const auto close = stat_line.rfind(')');
  if (close == std::string::npos || close + 2 >= stat_line.size()) return ProcessState::gone;
  switch (stat_line[close + 2]) {
    case 'R': case 'S': case 'D': case 'I': case 'W': case 'P': return ProcessState::running;
    case 'T': case 't': return ProcessState::stopped;
    default: return ProcessState::gone;  // Z zombie, X dead
  }
}

ProcessState process_state(int pid) {
  if (pid <= 0) return ProcessState::unknown;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return ProcessState::gone;
  return process_state_of_stat(line);
}

const char* to_string(ProcessState state) {
  switch (state) {
    case ProcessState::running: return "alive and running";
    case ProcessState::stopped: return "stopped";
    case ProcessState::gone: return "gone";
    case ProcessState::unknown: return "not known";
  }
  return "?";
}

}  // namespace hil::cnc_node
