#include "tools.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "java_tool_output.hpp"
#include "retimed_log.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

std::string number(double value) {
  std::string s = std::to_string(value);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::vector<char*> c_args(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  return args;
}

int exec(const std::vector<std::string>& argv) {
  std::vector<char*> args = c_args(argv);
  ::execvp(args[0], args.data());
  std::cerr << "hil: cannot start " << argv[0] << ": " << std::strerror(errno) << '\n';
  return 127;
}

// Runs argv to its end, its status as a shell gives it.
int run(const std::vector<std::string>& argv) {
  const pid_t pid = ::fork();
  if (pid < 0) return 127;
  if (pid == 0) ::_exit(exec(argv));
  int raw = 0;
  while (::waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

// The log in simulated time, in a temporary file that goes with this object.
class SimulatedTimeCopy {
 public:
  explicit SimulatedTimeCopy(const std::string& log)
      : dir_(fs::temp_directory_path() / ("hil-play-" + std::to_string(::getpid()))),
        path_((dir_ / fs::path(log).filename()).string()) {
    fs::create_directories(dir_);
    const logger::RetimedLog r = logger::retime_to_simulated(log, path_);
    std::cout << log << ": " << r.messages << " messages, " << number(r.simulated_s) << " s simulated (recorded in "
              << number(r.recorded_s) << " s wall)" << (r.retimed ? "" : "; no manifest: played as recorded") << '\n';
  }
  ~SimulatedTimeCopy() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  fs::path dir_;  // the copy keeps the log's name: the player shows it
  std::string path_;
};

}  // namespace

std::string types_jar(const std::string& bin_dir) {
  return (fs::path(bin_dir).parent_path() / "share" / "java" / "hil_types.jar").lexically_normal().string();
}

bool prepare_java_tools(const std::string& bin_dir) {
  const std::string jar = types_jar(bin_dir);
  if (!fs::exists(jar)) {
    std::cerr << "hil: no types jar at " << jar << " (build the project first)\n";
    return false;
  }
  const char* classpath = std::getenv("CLASSPATH");
  ::setenv("CLASSPATH", (jar + (classpath && *classpath ? ":" + std::string(classpath) : "")).c_str(), 1);
  ::setenv("JDK_JAVA_OPTIONS", "-XX:+IgnoreUnrecognizedVMOptions", 1);
  return true;
}

std::vector<std::string> spy_command(const std::string& url) {
  const char* stand_in = std::getenv("HIL_LCM_SPY");
  return {stand_in && *stand_in ? stand_in : "lcm-spy", "--lcm-url=" + url};
}

int run_java_tool(const std::string& tool, const std::vector<std::string>& argv) {
  int fds[2];
  if (::pipe(fds) != 0) return exec(argv);
  const pid_t pid = ::fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    ::close(fds[0]);
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    ::close(fds[1]);
    ::_exit(exec(argv));
  }
  ::close(fds[1]);
  JavaToolOutput output(tool);
  std::string pending;
  char buf[4096];
  bool stopped = false;
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buf, static_cast<size_t>(n));
    for (size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1)) {
      if (const std::optional<std::string> shown = output.line(pending.substr(0, end)))
        (output.headless() && !stopped ? std::cerr : std::cout) << *shown << '\n' << std::flush;
      if (output.headless() && !stopped) {
        ::kill(pid, SIGTERM);  // its window will never open
        stopped = true;
      }
    }
  }
  if (!pending.empty())
    if (const std::optional<std::string> shown = output.line(pending)) std::cout << *shown << '\n';
  ::close(fds[0]);
  int raw = 0;
  while (::waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
  }
  if (stopped) return 2;
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

int run_spy(const std::string& bin_dir, const std::string& source, double speed) {
  if (!prepare_java_tools(bin_dir)) return 2;
  std::error_code ec;
  if (!fs::is_regular_file(source, ec)) {
    std::cout << "lcm-spy on " << source << '\n' << std::flush;
    return run_java_tool("hil spy", spy_command(source));
  }
  const SimulatedTimeCopy copy(source);
  const std::string url = "file://" + fs::absolute(copy.path()).string() + "?speed=" + number(speed);
  std::cout << "lcm-spy on " << source << " at " << number(speed) << " x simulated time (" << url << ")\n"
            << std::flush;
  return run_java_tool("hil spy", spy_command(url));
}

int run_logplayer(const std::string& log, const std::string& url) {
  ::setenv("JDK_JAVA_OPTIONS", "-XX:+IgnoreUnrecognizedVMOptions", 1);
  const SimulatedTimeCopy copy(log);
  std::cout << "lcm-logplayer-gui: " << log << " onto " << url << " (watch it with hil spy " << url << ")\n"
            << std::flush;
  return run_java_tool("hil logplayer", {"lcm-logplayer-gui", "--lcm-url=" + url, copy.path()});
}

int run_replay(const std::string& log, const std::string& url, double speed) {
  const SimulatedTimeCopy copy(log);
  std::cout << "playing " << log << " onto " << url << " at " << number(speed) << " x simulated time\n" << std::flush;
  return run({"lcm-logplayer", "-s", number(speed), "-l", url, copy.path()});
}

int exec_rerun(const std::string& bin_dir, const std::string& log) {
  return exec({(fs::path(bin_dir) / "cnc").string(), "--rerun", log});
}

}  // namespace hil::rig
