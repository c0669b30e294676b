#pragma once
// The decoder tests' checks (KRN-1, KRN-2): a program decoded on the test
// machine, and a refusal that names its line and block.
#include <catch2/catch.hpp>

#include <string>

#include "decoder.hpp"
#include "test_machine.hpp"

namespace hil::test {

inline cnc::DecodedProgram decode(const std::string& text) {
  return cnc::decode_program(text, xyz_machine(), {0, 0, 0});
}

// `line` (N30) after two good blocks is refused naming line 3 and N30;
// the two blocks before it are kept (KRN-2). Returns the message.
inline std::string refused_as_line_3(const std::string& line) {
  const cnc::DecodedProgram p = decode("N10 G01 X1 F100\nN20 #TIME 1\n" + line + "\nN40 X50\n");
  REQUIRE(p.error);
  CHECK(p.error->nc_line == 3);
  CHECK(p.error->block_nr == 30);
  CHECK(p.blocks.size() == 2);
  return p.error->message;
}

// ... with exactly `message`.
inline void check_refused_as_line_3(const std::string& line, const std::string& message) {
  INFO(line);
  CHECK(refused_as_line_3(line) == message + " in '" + line + "'");
}

// ... with a message that starts with `message`.
inline void check_refused_as_line_3_with(const std::string& line, const std::string& message) {
  INFO(line.substr(0, 200));
  CHECK_THAT(refused_as_line_3(line), Catch::StartsWith(message));
}

}  // namespace hil::test
