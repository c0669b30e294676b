#pragma once
// A child process of the rig, its output in a file; it dies with the rig.
#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace hil::rig {

// Where and how a process runs, if the system lets it.
struct Placement {
  int cpu = -1;           // this CPU only if >= 0
  int fifo_priority = 0;  // SCHED_FIFO at this priority if > 0
};

// The last line of a child's output file that is not blank ("" if none):
// what it said before it ended.
std::string last_line_of(const std::string& output_file);

class Process {
 public:
  // Starts argv[0] (a path, or a name on PATH) with its stdout and stderr
  // appended to output_file, placed as asked where the system allows.
  Process(std::string name, const std::vector<std::string>& argv, const std::string& output_file,
          Placement placement = {});
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;
  ~Process();

  const std::string& name() const { return name_; }
  // Why SCHED_FIFO was refused (strerror), empty if it was applied or not asked.
  const std::string& fifo_refused() const { return fifo_refused_; }
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
  std::string fifo_refused_;
};

}  // namespace hil::rig
