// run_channel_fuzz_isolated (channel_fuzz.hpp): one seed in a child
// process, so that a crash or an endless loop is that seed's failure.
#include <signal.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "channel_fuzz.hpp"

namespace hil::fuzz {
namespace {

// What a child process sends back: the run's outcome, as text.
void put(std::string& out, const std::string& text) { out += std::to_string(text.size()) + ":" + text; }
void put(std::string& out, double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g;", x);
  out += buf;
}

class Reader {
 public:
  explicit Reader(const std::string& in) : in_(in) {}
  bool ok() const { return ok_; }
  std::string text() {
    const size_t colon = in_.find(':', at_);
    if (colon == std::string::npos) return fail();
    const size_t n = std::strtoull(in_.c_str() + at_, nullptr, 10);
    if (colon + 1 + n > in_.size()) return fail();
    std::string t = in_.substr(colon + 1, n);
    at_ = colon + 1 + n;
    return t;
  }
  double number() {
    const size_t semi = in_.find(';', at_);
    if (semi == std::string::npos) return fail(), 0.0;
    const double x = std::strtod(in_.c_str() + at_, nullptr);
    at_ = semi + 1;
    return x;
  }

 private:
  std::string fail() {
    ok_ = false;
    at_ = in_.size();
    return {};
  }
  const std::string& in_;
  size_t at_ = 0;
  bool ok_ = true;
};

std::string serialise(const FuzzRun& run) {
  std::string out;
  for (double x : {static_cast<double>(run.cycles), static_cast<double>(run.finished), static_cast<double>(run.short_cut),
                   static_cast<double>(run.backward), static_cast<double>(run.m_output), static_cast<double>(run.events),
                   static_cast<double>(run.plc.feedhold_edges), static_cast<double>(run.plc.override_changes),
                   static_cast<double>(run.plc.ddtg_edges), static_cast<double>(run.plc.backward_toggles),
                   static_cast<double>(run.plc.m_acks), static_cast<double>(run.plc.insert_commands),
                   static_cast<double>(run.plc.insert_stops), static_cast<double>(run.plc.resets),
                   static_cast<double>(run.plc.searches), static_cast<double>(run.plc.search_errors),
                   static_cast<double>(run.search_error_events), static_cast<double>(run.at_stop_searches),
                   static_cast<double>(run.at_stop_moved), run.at_stop_approach_max_mm,
                   static_cast<double>(run.restart_decode_errors),
                   static_cast<double>(run.failures.size()),
                   static_cast<double>(run.event_log.size())})
    put(out, x);
  for (const std::string& e : run.event_log) put(out, e);
  for (const Failure& f : run.failures) {
    put(out, f.invariant);
    put(out, static_cast<double>(f.cycle));
    put(out, f.axis);
    put(out, f.quantity);
    put(out, f.value);
    put(out, f.limit);
    put(out, static_cast<double>(f.nc_line));
    put(out, f.detail);
  }
  return out;
}

bool deserialise(const std::string& in, FuzzRun& run) {
  Reader r(in);
  auto count = [&] { return static_cast<int64_t>(r.number()); };
  run.cycles = count();
  run.finished = count();
  run.short_cut = count();
  run.backward = count();
  run.m_output = count();
  run.events = count();
  run.plc.feedhold_edges = count();
  run.plc.override_changes = count();
  run.plc.ddtg_edges = count();
  run.plc.backward_toggles = count();
  run.plc.m_acks = count();
  run.plc.insert_commands = count();
  run.plc.insert_stops = count();
  run.plc.resets = count();
  run.plc.searches = count();
  run.plc.search_errors = count();
  run.search_error_events = count();
  run.at_stop_searches = count();
  run.at_stop_moved = count();
  run.at_stop_approach_max_mm = r.number();
  run.restart_decode_errors = count();
  const int64_t failures = count();
  const int64_t logged = count();
  run.event_log.clear();
  for (int64_t i = 0; i < logged && r.ok(); ++i) run.event_log.push_back(r.text());
  run.failures.clear();
  for (int64_t i = 0; i < failures && r.ok(); ++i) {
    Failure f;
    f.invariant = r.text();
    f.cycle = count();
    f.axis = r.text();
    f.quantity = r.text();
    f.value = r.number();
    f.limit = r.number();
    f.nc_line = count();
    f.detail = r.text();
    run.failures.push_back(f);
  }
  return r.ok();
}

}  // namespace

FuzzRun run_channel_fuzz_isolated(uint64_t seed, const FuzzOptions& options, unsigned timeout_s) {
  FuzzRun run = prepare_channel_fuzz(seed, options);
  if (!run.failures.empty()) return run;
  std::fflush(stdout);
  int fds[2];
  if (pipe(fds) != 0) return run_channel_fuzz(seed, options);
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]);
    close(fds[1]);
    return run_channel_fuzz(seed, options);
  }
  if (child == 0) {
    close(fds[0]);
    // CPU time, not wall time: on a loaded machine (ctest -j2 beside other
    // work) the longest seeds took over 120 s of wall time; an endless loop
    // still burns CPU time and ends by SIGPROF.
    itimerval limit{};
    limit.it_value.tv_sec = static_cast<time_t>(timeout_s);
    setitimer(ITIMER_PROF, &limit, nullptr);
    const std::string out = serialise(run_channel_fuzz(seed, options));
    std::fflush(stdout);
    for (size_t done = 0; done < out.size();) {
      const ssize_t n = write(fds[1], out.data() + done, out.size() - done);
      if (n <= 0) _exit(3);
      done += static_cast<size_t>(n);
    }
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string in;
  char buf[65536];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    in.append(buf, static_cast<size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    run.failures.push_back({"crash", -1, "", "", static_cast<double>(sig), 0, 0,
                            std::string("the run died of signal ") + std::to_string(sig) + " (" + strsignal(sig) + ")" +
                                (sig == SIGPROF ? ": no end within " + std::to_string(timeout_s) + " s of CPU time" : "")});
    return run;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !deserialise(in, run))
    run.failures.push_back({"crash", -1, "", "", 0, 0, 0, "the run's process ended without a result"});
  return run;
}

}  // namespace hil::fuzz
