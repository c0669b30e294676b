#pragma once
// The debugging tools `hil` starts (RIG-2, RIG-7): lcm-spy with every rig
// type decodable, lcm-logplayer (and its GUI) onto a URL, and `cnc --rerun`. Each replaces
// the hil process (exec); they return only if the tool cannot be started.
#include <string>

namespace hil::rig {

// LCM's default URL: where `hil replay` plays and `hil spy` listens unless told.
inline const std::string default_lcm_url = "udpm://239.255.76.67:7667?ttl=0";

// lcm-spy on `source`: an LCM URL, or a log file (played at `speed`).
// Debian 12's lcm-spy needs JDK_JAVA_OPTIONS=-XX:+IgnoreUnrecognizedVMOptions
// under Java 17 (its script passes -Xincgc) and the types jar on CLASSPATH.
int exec_spy(const std::string& bin_dir, const std::string& source, double speed);

// lcm-logplayer-gui on `log`, playing onto `url` (random access, speed,
// channel filters); needs the same Java flag as lcm-spy.
int exec_logplayer(const std::string& log, const std::string& url);

// lcm-logplayer: plays `log` onto `url` at `speed` (1 = as recorded).
int exec_replay(const std::string& log, const std::string& url, double speed);

// cnc --rerun: the CNC build next to hil against the recorded PLC inputs.
int exec_rerun(const std::string& bin_dir, const std::string& log);

// The types jar the build makes (share/java/hil_types.jar next to bin/).
std::string types_jar(const std::string& bin_dir);

}  // namespace hil::rig
