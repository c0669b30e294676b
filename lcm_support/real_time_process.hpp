#pragma once
// RIG-6 real-time mode: a node's process locks its memory (no page fault
// in a cycle) and runs under SCHED_FIFO, where the system allows it, and
// says what it got. hil run starts the lock-step nodes under SCHED_FIFO
// already (--fifo-priority); a node started by hand tries it itself.
#include <string>

#include "event.hpp"
#include "inbox.hpp"

namespace hil::lcm_support {

struct RealTimeProcess {
  bool fifo = false;    // runs under SCHED_FIFO
  bool locked = false;  // mlockall(MCL_CURRENT | MCL_FUTURE) took
  std::string what;     // "SCHED_FIFO 10, memory locked", or what was refused and why
};

// SCHED_FIFO at `priority` unless the process runs under it already, and
// the memory locked if the process may lock all it will use (root, or
// CAP_IPC_LOCK, or no RLIMIT_MEMLOCK): under a limit MCL_FUTURE would make
// later allocations fail, so it is not tried. Logs a warning on a fallback.
RealTimeProcess enter_real_time(int priority = 10);

// The same as an event for the log: info "real time: SCHED_FIFO 10, memory
// locked", or a warning naming the fallback. The report reads it.
Event real_time_event(const RealTimeProcess& process);
// The prefix of that event's message.
inline const std::string real_time_event_prefix = "real time: ";

// Publishes it on HIL_EVENT from `source` (once the run has begun: events
// before the manifest are not this run's in the log).
void publish_real_time(Inbox& inbox, const RealTimeProcess& process, const std::string& source);

}  // namespace hil::lcm_support
