#include "real_time_process.hpp"

#include <hil/event_t.hpp>
#include <sched.h>
#include <spdlog/spdlog.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "channels.hpp"
#include "messages.hpp"

namespace hil::lcm_support {
namespace {

// Whether mlockall may lock whatever the process will allocate.
bool may_lock_all(std::string& why_not) {
  rlimit limit{};
  if (::geteuid() == 0 || (::getrlimit(RLIMIT_MEMLOCK, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY)) return true;
  why_not = "RLIMIT_MEMLOCK " + std::to_string(limit.rlim_cur / 1024) + " KiB and not root";
  return false;
}

}  // namespace

RealTimeProcess enter_real_time(int priority) {
  RealTimeProcess p;
  if (::sched_getscheduler(0) == SCHED_FIFO) {
    sched_param now{};
    ::sched_getparam(0, &now);
    p.fifo = true;
    p.what = "SCHED_FIFO " + std::to_string(now.sched_priority);
  } else {
    sched_param fifo{};
    fifo.sched_priority = priority;
    if (::sched_setscheduler(0, SCHED_FIFO, &fifo) == 0) {
      p.fifo = true;
      p.what = "SCHED_FIFO " + std::to_string(priority);
    } else {
      p.what = "normal scheduling (SCHED_FIFO refused: " + std::string(std::strerror(errno)) + ")";
      // A normal task's sleeps end up to 50 us late by default (timer slack); SCHED_FIFO has none.
      ::prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    }
  }
  std::string why_not;
  if (may_lock_all(why_not)) {
    if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) p.locked = true;
    else why_not = std::strerror(errno);
  }
  p.what += p.locked ? ", memory locked" : ", memory not locked (" + why_not + ")";
  if (!p.fifo || !p.locked) spdlog::warn("real time: {}", p.what);
  else spdlog::info("real time: {}", p.what);
  return p;
}

Event real_time_event(const RealTimeProcess& process) {
  Event e;
  e.severity = process.fifo && process.locked ? Severity::info : Severity::warning;
  e.message = real_time_event_prefix + process.what;
  return e;
}

void publish_real_time(Inbox& inbox, const RealTimeProcess& process, const std::string& source) {
  hil::event_t m = to_message(real_time_event(process), 0, 0, source);
  m.run_id = inbox.run_id();
  inbox.bus().publish(channels::event, m);
}

}  // namespace hil::lcm_support
