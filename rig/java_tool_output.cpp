#include "java_tool_output.hpp"

namespace hil::rig {
namespace {

bool begins(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }
bool has(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }

}  // namespace

std::optional<std::string> JavaToolOutput::line(const std::string& text) {
  if (in_trace_) {
    // A trace's frames, its cause, and the lines of HeadlessException's message.
    if (begins(text, "\tat ") || begins(text, "\t... ") || begins(text, "Caused by") ||
        begins(text, "No X11 DISPLAY") || begins(text, "but this program performed") ||
        (headless_ && begins(text, "Can't connect to X11")))
      return std::nullopt;
    in_trace_ = false;
  }
  if (begins(text, "NOTE: Picked up JDK_JAVA_OPTIONS") || has(text, "Disabling IPV6 support") ||
      begins(text, "Invalid key-value pair in URL"))
    return std::nullopt;
  if (has(text, "java.awt.HeadlessException") || has(text, "java.awt.AWTError: Can't connect to X11")) {
    in_trace_ = true;
    if (headless_) return std::nullopt;
    headless_ = true;
    return tool_ + ": no display to open its window on (DISPLAY is not set or cannot be reached); "
                   "without one, read a log with hil check, hil export or hil replay";
  }
  if (begins(text, "java.io.EOFException") || (has(text, "Exception in thread") && has(text, "java.io.EOFException"))) {
    in_trace_ = true;  // lcm-spy at the end of a log file: it has played it all
    return std::nullopt;
  }
  return text;
}

}  // namespace hil::rig
