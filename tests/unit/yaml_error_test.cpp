// RIG-5 (issue 37, 3): a scenario file's YAML syntax errors in plain words,
// at the line where the problem starts, that line shown.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "config_error.hpp"
#include "scenario.hpp"

using namespace hil;
namespace fs = std::filesystem;

namespace {

std::string refusal(const std::string& text) {
  const fs::path file = fs::temp_directory_path() / ("yaml_error_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(file) << text;
  std::string said;
  try {
    load_scenario_file(file.string());
  } catch (const ConfigError& e) {
    said = e.what();
  }
  fs::remove(file);
  return said;
}

}  // namespace

TEST_CASE("RIG-5 an unclosed bracket is named with the line it was opened on", "[config][yaml]") {
  const std::string said = refusal(
      "name: a\nplc:\n  timeline:\n    - {when: {cycle: 5}, set: {program_start.command_w: true}\n"
      "expect:\n  - {when: \"channel_state == PROGRAM_END\"}\n");
  CHECK_THAT(said, Catch::Contains("line 4: the '{' opened here is not closed (a '}' is missing before line"));
  CHECK_THAT(said, Catch::Contains("4 |     - {when: {cycle: 5}"));
  CHECK_THAT(said, !Catch::Contains("flow not found"));
  CHECK_THAT(refusal("name: a\nrequirements: [RIG-5, RIG-9\nmachine: m.yaml\n"),
             Catch::Contains("line 2: the '[' opened here is not closed"));
}

TEST_CASE("RIG-5 a TAB in the indentation is named as such", "[config][yaml]") {
  const std::string said = refusal("name: a\nrun:\n\tmax_time_s: 3\n");
  CHECK_THAT(said, Catch::Contains("line 3: a TAB in the indentation (YAML indents with spaces only)"));
  CHECK_THAT(said, !Catch::Contains("illegal"));
}

TEST_CASE("RIG-5 an indentation slip names the line that does not fit", "[config][yaml]") {
  CHECK_THAT(refusal("name: a\nrun:\n  max_time_s: 3\n   settle_time_s: 1\n"),
             Catch::Contains("line 4: the indentation does not fit the lines above"));
  CHECK_THAT(refusal("name: a\nrun:\n  max_time_s: 3\n settle_time_s: 1\n"),
             Catch::Contains("line 4: the indentation does not fit the lines above"));
  CHECK_THAT(refusal("name: a\nexpect:\n  - 1\n  when: 2\n"),
             Catch::Contains("line 4: the indentation does not fit the lines above"));
}

TEST_CASE("RIG-5 a second ': ' in a line asks for quotes; other errors keep line and column", "[config][yaml]") {
  CHECK_THAT(refusal("name: a\ndescription: lift: on\n"),
             Catch::Contains("line 2: a second ': ' in one line (a value holding ': ' goes in quotes)"));
  const std::string said = refusal("name: a\nb: &x 1\nc: *y\n");
  CHECK_THAT(said, Catch::Contains("line 3"));
}
