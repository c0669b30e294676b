#pragma once
// What Debian 12's Java LCM tools (lcm-spy, lcm-logplayer-gui) print that
// is no news to the user (issue 37): the JVM's note about the option hil
// itself sets, lcm-java's "Invalid key-value pair in URL : ttl" for the
// rig's own URL (ttl=0 holds all the same: "TTL set to zero"), its IPv6
// notes, the EOFException trace lcm-spy prints at a log's end; and the
// HeadlessException trace without a display, said in one line instead.
#include <optional>
#include <string>

namespace hil::rig {

class JavaToolOutput {
 public:
  explicit JavaToolOutput(std::string tool) : tool_(std::move(tool)) {}
  // The line as the user sees it; none: left out.
  std::optional<std::string> line(const std::string& text);
  // The tool found no display: it cannot go on (lcm-logplayer-gui would hang).
  bool headless() const { return headless_; }

 private:
  std::string tool_;
  bool in_trace_ = false;  // the lines of a trace left out follow
  bool headless_ = false;
};

}  // namespace hil::rig
