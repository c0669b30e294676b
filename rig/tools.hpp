#pragma once
// The debugging tools `hil` starts (RIG-2, RIG-7): lcm-spy with every rig
// type decodable, lcm-logplayer (and its GUI) onto a URL, and `cnc --rerun`.
// A log is played in simulated time: its messages at their cycle's time, so
// that speed 1 is the machine's own pace whatever the recording's wall clock
// (a lock-step run records faster than real time; retimed_log.hpp).
#include <string>
#include <vector>

namespace hil::rig {

// LCM's default URL: where `hil replay` plays and `hil spy` listens unless told.
inline const std::string default_lcm_url = "udpm://239.255.76.67:7667?ttl=0";

// lcm-spy on `source`: an LCM URL, or a log file (played at `speed` x
// simulated time). Debian 12's lcm-spy needs
// JDK_JAVA_OPTIONS=-XX:+IgnoreUnrecognizedVMOptions under Java 17 (its
// script passes -Xincgc) and the types jar on CLASSPATH. Its noise is left
// out (java_tool_output.hpp); without a display: one line, exit status 2.
int run_spy(const std::string& bin_dir, const std::string& source, double speed);

// lcm-logplayer-gui on `log` (in simulated time), playing onto `url` (random
// access, speed, channel filters); the same Java flag and filter as lcm-spy.
int run_logplayer(const std::string& log, const std::string& url);

// lcm-logplayer: plays `log` onto `url` at `speed` x simulated time.
int run_replay(const std::string& log, const std::string& url, double speed);

// cnc --rerun: the CNC build next to hil against the recorded PLC inputs
// (replaces the hil process).
int exec_rerun(const std::string& bin_dir, const std::string& log);

// The types jar the build makes (share/java/hil_types.jar next to bin/).
std::string types_jar(const std::string& bin_dir);

// CLASSPATH with the types jar and the Java flag, for lcm-spy in this
// process and its children; false (said on stderr) if there is no jar.
bool prepare_java_tools(const std::string& bin_dir);

// The lcm-spy command line on `url` ($HIL_LCM_SPY instead of lcm-spy if set:
// a stand-in for tests).
std::vector<std::string> spy_command(const std::string& url);

// Runs a Java tool, its output through JavaToolOutput; on a headless
// machine stops it (lcm-logplayer-gui would hang) and returns 2.
int run_java_tool(const std::string& tool, const std::vector<std::string>& argv);

}  // namespace hil::rig
