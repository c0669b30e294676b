#include "tools.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <vector>

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

int exec(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  ::execvp(args[0], args.data());
  std::cerr << "hil: cannot start " << argv[0] << ": " << std::strerror(errno) << '\n';
  return 127;
}

std::string number(double value) {
  std::string s = std::to_string(value);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

std::string types_jar(const std::string& bin_dir) {
  return (fs::path(bin_dir).parent_path() / "share" / "java" / "hil_types.jar").lexically_normal().string();
}

int exec_spy(const std::string& bin_dir, const std::string& source, double speed) {
  const std::string jar = types_jar(bin_dir);
  if (!fs::exists(jar)) {
    std::cerr << "hil: no types jar at " << jar << " (build the project first)\n";
    return 2;
  }
  const char* classpath = std::getenv("CLASSPATH");
  ::setenv("CLASSPATH", (jar + (classpath && *classpath ? ":" + std::string(classpath) : "")).c_str(), 1);
  ::setenv("JDK_JAVA_OPTIONS", "-XX:+IgnoreUnrecognizedVMOptions", 1);
  std::string url = source;
  if (fs::is_regular_file(source)) url = "file://" + fs::absolute(source).string() + "?speed=" + number(speed);
  std::cout << "lcm-spy on " << url << '\n' << std::flush;
  return exec({"lcm-spy", "--lcm-url=" + url});
}

int exec_logplayer(const std::string& log, const std::string& url) {
  ::setenv("JDK_JAVA_OPTIONS", "-XX:+IgnoreUnrecognizedVMOptions", 1);
  std::cout << "lcm-logplayer-gui: " << log << " onto " << url << " (watch it with hil spy " << url << ")\n"
            << std::flush;
  return exec({"lcm-logplayer-gui", "--lcm-url=" + url, log});
}

int exec_replay(const std::string& log, const std::string& url, double speed) {
  std::cout << "playing " << log << " onto " << url << " at speed " << number(speed) << '\n' << std::flush;
  return exec({"lcm-logplayer", "-s", number(speed), "-l", url, log});
}

int exec_rerun(const std::string& bin_dir, const std::string& log) {
  return exec({(fs::path(bin_dir) / "cnc").string(), "--rerun", log});
}

}  // namespace hil::rig
