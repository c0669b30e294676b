#include "process.hpp"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace hil::rig {

Process::Process(std::string name, const std::vector<std::string>& argv, const std::string& output_file,
                 Placement placement)
    : name_(std::move(name)) {
  const int fd = ::open(output_file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot write " + output_file + ": " + std::strerror(errno));
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ < 0) {
    ::close(fd);
    throw std::runtime_error("fork failed: " + std::string(std::strerror(errno)));
  }
  if (pid_ == 0) {
    // A node never outlives the rig that started it.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(127);
    if (placement.cpu >= 0) {
      cpu_set_t one;
      CPU_ZERO(&one);
      CPU_SET(placement.cpu, &one);
      ::sched_setaffinity(0, sizeof one, &one);  // refused: it runs where the system puts it
    }
    sched_param fifo{};
    fifo.sched_priority = placement.fifo_priority;
    if (placement.fifo_priority > 0) ::sched_setscheduler(0, SCHED_FIFO, &fifo);  // before exec: every thread inherits it
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::execvp(args[0], args.data());  // a bare name is looked up on PATH
    const std::string msg = "cannot start " + argv[0] + ": " + std::strerror(errno) + "\n";
    (void)!::write(STDERR_FILENO, msg.data(), msg.size());
    ::_exit(127);
  }
  ::close(fd);
  // Again from here, so that the rig knows whether it was allowed.
  if (placement.fifo_priority > 0) {
    sched_param p{};
    p.sched_priority = placement.fifo_priority;
    if (::sched_setscheduler(pid_, SCHED_FIFO, &p) != 0) fifo_refused_ = std::strerror(errno);
  }
}

Process::~Process() {
  if (!status_) stop(std::chrono::milliseconds(500));
}

std::optional<int> Process::poll() {
  if (status_ || pid_ < 0) return status_;
  int raw = 0;
  if (::waitpid(pid_, &raw, WNOHANG) == pid_)
    status_ = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  return status_;
}

std::optional<int> Process::wait_for(std::chrono::milliseconds timeout) {
  const auto give_up = std::chrono::steady_clock::now() + timeout;
  while (!poll()) {
    if (std::chrono::steady_clock::now() >= give_up) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status_;
}

int Process::stop(std::chrono::milliseconds grace) {
  if (poll()) return *status_;
  ::kill(pid_, SIGTERM);
  if (wait_for(grace)) return *status_;
  ::kill(pid_, SIGKILL);
  while (!poll()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return *status_;
}

std::string last_line_of(const std::string& output_file) {
  std::ifstream in(output_file);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t") != std::string::npos) last = line;
  return last;
}

}  // namespace hil::rig
