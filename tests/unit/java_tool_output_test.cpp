// RIG-7 (issue 37, 8): the Java tools' output without their noise; no
// display said in one line.
#include <catch2/catch.hpp>

#include "java_tool_output.hpp"

using hil::rig::JavaToolOutput;

namespace {

std::vector<std::string> shown(JavaToolOutput& output, const std::vector<std::string>& lines) {
  std::vector<std::string> out;
  for (const std::string& line : lines)
    if (auto s = output.line(line)) out.push_back(*s);
  return out;
}

}  // namespace

TEST_CASE("RIG-7 the Java tools' noise is left out, their news kept", "[tools]") {
  JavaToolOutput output("hil logplayer");
  CHECK(shown(output, {"NOTE: Picked up JDK_JAVA_OPTIONS: -XX:+IgnoreUnrecognizedVMOptions",
                       "LC: Disabling IPV6 support", "Invalid key-value pair in URL : ttl",
                       "LCM: Disabling IPV6 support", "LCM: TTL set to zero, traffic will not leave localhost.",
                       "Found 27 LCM types"}) ==
        std::vector<std::string>{"LCM: TTL set to zero, traffic will not leave localhost.", "Found 27 LCM types"});
  CHECK_FALSE(output.headless());
}

TEST_CASE("RIG-7 no display: one line instead of HeadlessException's trace", "[tools]") {
  JavaToolOutput output("hil spy");
  const std::vector<std::string> out =
      shown(output, {"Found 27 LCM types", "Exception in thread \"main\" java.awt.HeadlessException: ",
                     "No X11 DISPLAY variable was set,", "but this program performed an operation which requires it.",
                     "\tat java.desktop/java.awt.GraphicsEnvironment.checkHeadless(GraphicsEnvironment.java:164)",
                     "\tat lcm.spy.Spy.main(Spy.java:540)"});
  REQUIRE(out.size() == 2);
  CHECK(out[0] == "Found 27 LCM types");
  CHECK_THAT(out[1], Catch::StartsWith("hil spy: no display to open its window on"));
  CHECK(output.headless());
}

TEST_CASE("RIG-7 the EOFException trace at a log's end is left out; other errors are not", "[tools]") {
  JavaToolOutput output("hil spy");
  CHECK(shown(output, {"java.io.EOFException", "\tat java.base/java.io.RandomAccessFile.readInt(RandomAccessFile.java:837)",
                       "\tat lcm.logging.Log.readNext(Log.java:94)", "\t... 2 more",
                       "java.lang.OutOfMemoryError: Java heap space", "\tat lcm.spy.Spy.main(Spy.java:540)"}) ==
        std::vector<std::string>{"java.lang.OutOfMemoryError: Java heap space", "\tat lcm.spy.Spy.main(Spy.java:540)"});
}
