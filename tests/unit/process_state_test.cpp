// RIG-6: the lock-step CNC tells a participant that is slow (its process
// alive and running: a loaded host, waited for) from one that is gone or
// stopped (lost at its watchdog).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <thread>

#include "lock_step.hpp"
#include "process_state.hpp"
#include "test_machine.hpp"

using namespace hil;
using cnc_node::ProcessState;

namespace {

// Polls until `pid` is in `state` (a signal takes effect asynchronously).
bool becomes(int pid, ProcessState state) {
  for (int i = 0; i < 500; ++i) {
    if (cnc_node::process_state(pid) == state) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

}  // namespace

TEST_CASE("RIG-6 process state: running, stopped, gone, from /proc", "[RIG-6][process_state]") {
  CHECK(cnc_node::process_state(::getpid()) == ProcessState::running);
  CHECK(cnc_node::process_state(0) == ProcessState::unknown);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    for (;;) ::pause();
  }
  CHECK(becomes(child, ProcessState::running));
  ::kill(child, SIGSTOP);
  CHECK(becomes(child, ProcessState::stopped));
  ::kill(child, SIGCONT);
  CHECK(becomes(child, ProcessState::running));
  ::kill(child, SIGKILL);
  CHECK(becomes(child, ProcessState::gone));  // a zombie until reaped
  ::waitpid(child, nullptr, 0);
  CHECK(cnc_node::process_state(child) == ProcessState::gone);
  // The name may hold spaces and parentheses; the state follows the last ')'.
  CHECK(cnc_node::process_state_of_stat("42 (axis_sim (X) t) T 1 42") == ProcessState::stopped);
  CHECK(cnc_node::process_state_of_stat("42 (cnc) Z 1") == ProcessState::gone);
  CHECK(cnc_node::process_state_of_stat("42 (cnc) D 1") == ProcessState::running);
  CHECK(cnc_node::process_state_of_stat("garbage") == ProcessState::gone);
}

TEST_CASE("RIG-6 lock-step: at the watchdog a participant whose process runs is waited for, one gone or stopped "
          "lost",
          "[RIG-6][process_state]") {
  cnc_node::LockStep lock_step(test::xyz_machine(), true, 5000, 2000);
  lock_step.logger_alive(1'000'000, -1);
  ProcessState y = ProcessState::running, plc = ProcessState::running;
  auto liveness = [&](const std::string& name) {
    return name == "axis_sim Y" ? y : name == "plc_sim" ? plc : ProcessState::running;
  };
  lock_step.begin(7);
  lock_step.take_axis(0, 7, 0);
  lock_step.take_axis(2, 7, 0);
  CHECK(lock_step.lose_silent(liveness) == std::vector<std::string>{"axis_sim Y", "plc_sim"});
  CHECK_FALSE(lock_step.complete());
  CHECK(lock_step.take().lost.empty());  // nobody lost: both are slow, not gone
  y = ProcessState::gone;
  plc = ProcessState::stopped;
  CHECK(lock_step.lose_silent(liveness).empty());
  CHECK(lock_step.complete());
  const auto lost = lock_step.take().lost;
  REQUIRE(lost.size() == 2);
  CHECK(lost[0].name == "axis_sim Y");
  CHECK(lost[1].name == "plc_sim");
  CHECK(lost[1].what == "no answer to cycle 7 within 5000 ms");

  // The logger: silent for longer than its timeout, but running — waited for.
  lock_step.begin(8);
  CHECK(lock_step.check_logger(3'500'000, [](const std::string&) { return ProcessState::running; }));
  CHECK(lock_step.take().lost.empty());
  CHECK_FALSE(lock_step.check_logger(3'600'000, [](const std::string&) { return ProcessState::stopped; }));
  const auto logger = lock_step.take().lost;
  REQUIRE(logger.size() == 1);
  CHECK(logger[0].what == "no heartbeat for 2600 ms at cycle 8: the run is no longer recorded");
}
