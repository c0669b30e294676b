#pragma once
// A child process of the rig, its output in a file; it dies with the rig.
#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace hil::rig {

class Process {
 public:
  // Starts argv[0] (a path, or a name on PATH) with its stdout and stderr
  // appended to output_file; on CPU `cpu` only if cpu >= 0 (and the system
  // lets it).
  Process(std::string name, const std::vector<std::string>& argv, const std::string& output_file, int cpu = -1);
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;
  ~Process();

  const std::string& name() const { return name_; }
  // Exit status once it has exited (128 + signal if killed), else nullopt.
  std::optional<int> poll();
  // Waits up to `timeout`; the exit status, or nullopt if still running.
  std::optional<int> wait_for(std::chrono::milliseconds timeout);
  // SIGTERM, then SIGKILL after a grace period; returns the exit status.
  int stop(std::chrono::milliseconds grace = std::chrono::milliseconds(2000));

 private:
  std::string name_;
  pid_t pid_ = -1;
  std::optional<int> status_;
};

}  // namespace hil::rig
