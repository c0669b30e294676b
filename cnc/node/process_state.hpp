#pragma once
// RIG-6: what became of a participant's process, from the host's process
// table (every participant runs on this host: udpm with ttl 0). In
// lock-step a participant whose process is alive and not stopped is slow —
// a loaded host — and is waited for; one that died or was stopped is lost
// at its watchdog.
#include <string>

namespace hil::cnc_node {

enum class ProcessState {
  running,  // alive and not stopped (running, sleeping, in I/O)
  stopped,  // stopped by a signal or a tracer
  gone,     // exited (a zombie, or no such process)
  unknown,  // no process id announced
};

// /proc/<pid>/stat's state; unknown for pid <= 0.
ProcessState process_state(int pid);
// The state read from a /proc/<pid>/stat line.
ProcessState process_state_of_stat(const std::string& stat_line);

const char* to_string(ProcessState state);

}  // namespace hil::cnc_node
