// KRN-1, KRN-2: what the decoder refuses (numbers out of range or not
// finite, control characters, bad starts), each naming its line; the
// blocks before it are kept.
#include <catch2/catch.hpp>

#include <initializer_list>
#include <string>

#include "decoder_checks.hpp"

using namespace hil;
using namespace hil::cnc;
using namespace hil::test;

namespace {
// `program` is refused at its line `line` with a message that contains
// `part`; the `kept` blocks before it are decoded (KRN-2).
struct Refusal {
  std::string program;
  int64_t line;
  std::string part;
  size_t kept;
};

void check_refused(const Refusal& r) {
  INFO(r.program.substr(0, 300));
  const DecodedProgram p = decode(r.program);
  REQUIRE(p.error);
  CHECK(p.error->nc_line == r.line);
  CHECK_THAT(p.error->message, Catch::Contains(r.part));
  CHECK(p.blocks.size() == r.kept);
}

void check_refused(std::initializer_list<Refusal> refusals) {
  for (const Refusal& r : refusals) check_refused(r);
}

const std::string digits_308(308, '0');  // X1<308 zeros> is 1e308 without an exponent
}  // namespace

TEST_CASE("KRN-1 KRN-2 decoder: coordinates, I/J, feed out of range are refused with their line", "[decoder]") {
  check_refused_as_line_3_with("N30 X1" + digits_308, "X 1e+308 mm is out of range (|value| <= 1000000 mm)");
  check_refused_as_line_3_with("N30 G02 Y200 J1" + digits_308, "J 1e+308 mm is out of range (|value| <= 1000000 mm)");
  check_refused_as_line_3_with("N30 X1000001", "X 1000001 mm is out of range (|value| <= 1000000 mm)");
  check_refused_as_line_3_with("N30 G03 I-1000000.5", "I -1000000.5 mm is out of range (|value| <= 1000000 mm)");
  check_refused_as_line_3_with("N30 G92 Y2000000", "Y 2000000 mm is out of range (|value| <= 1000000 mm)");
  check_refused_as_line_3_with("N30 G02 Y200 J1e308", "'J1e..': words take decimal numbers, no exponent");
  check_refused_as_line_3_with("N30 F10000001", "feed 'F10000001' is out of range 0.001 .. 10000000 mm/min");
  check_refused_as_line_3_with("N30 F0.0009", "feed 'F0.0009' is out of range 0.001 .. 10000000 mm/min");
  check_refused_as_line_3_with("N30 #TIME 1000001", "#TIME needs a dwell time > 0 and <= 1000000 s");
  check_refused_as_line_3_with("N30 V.G.M_FCT[7].PRE_OUTP_PATH = 1e7", "PRE_OUTP_PATH 10000000 mm is out of range");
  check_refused_as_line_3_with("N30 #CS ON [0,-1e7]", "#CS offset v2 -10000000 mm is out of range");
  check_refused_as_line_3_with("N30 #CS ON [0,0,0,0,0,360.5]", "#CS angle φ3 must be within ±360°");
}

TEST_CASE("KRN-1 KRN-2 decoder: end points and arcs are in range after G91, G92 and #CS", "[decoder]") {
  check_refused({
      // Every word in range, the sum not.
      {"N10 G01 G91 X600000 F1000\nN20 X600000\n", 2, "end point X 1200000 mm is out of range (|value| <= 1000000 mm)",
       1},
      {"N10 G92 X600000\nN20 G01 X600000 F1000\n", 2, "end point X 1200000 mm is out of range", 0},
      {"N10 #CS ON [900000]\nN20 G01 X900000 F1000\n", 2, "end point X 1800000 mm is out of range", 1},
      {"N10 #CS ON [0,0,0,0,0,45]\nN20 G01 X999999 Y999999 F1000\n", 2, "end point Y 1414212.", 1},
      // G161: the centre in program coordinates, shifted by G92.
      {"N10 G92 X600000\nN20 G161 G02 I600000 F1000\n", 2, "arc centre X 1200000 mm is out of range", 0},
      // Centre in range, radius not.
      {"N10 G01 X-600000 F1000\nN20 G02 I1000000 J1\n", 2, "arc radius 1000000.0000005 mm is out of range", 1},
  });
  // At the bounds: accepted.
  const DecodedProgram p = decode(
      "N10 G01 X1000000 F10000000\nN20 X-1000000 F0.001\nN30 G90 G03 I1000000\nN40 #TIME 1000000\n"
      "N50 #CS ON [1000000,0,0,0,0,-360]\nN60 G01 X0\n");
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 6);
  CHECK(p.blocks[1].motion.end[0] == -1000000);
  CHECK(p.blocks[1].motion.feed == Approx(0.001 / 60));
  CHECK(p.blocks[5].motion.end[0] == Approx(1000000));
}

TEST_CASE("KRN-1 KRN-2 decoder: P parameter arithmetic that is not finite is an error with its line", "[decoder]") {
  check_refused_as_line_3_with("N30 P1 = 1e300 * 1e300", "result of '*' out of range in expression ' 1e300 * 1e300'");
  check_refused_as_line_3_with("N30 P1 = 1e308 + 1e308", "result of '+' out of range");
  check_refused_as_line_3_with("N30 P1 = -1e308 - 1e308", "result of '-' out of range");
  check_refused_as_line_3_with("N30 P1 = 1e300 / 1e-300", "result of '/' out of range");
  check_refused_as_line_3_with("N30 P1 = 0 * [1e300 * 1e300]", "result of '*' out of range");  // 0 * inf: NaN
  check_refused_as_line_3_with("N30 P2 = 0/0", "division by zero in expression ' 0/0'");
  check_refused_as_line_3_with("N30 P1 = 1e400", "number '1e400' out of range");
  check_refused_as_line_3_with("N30 P1 = nan", "a number or P<n> expected");
  check_refused_as_line_3_with("N30 P1 = inf", "a number or P<n> expected");
  check_refused_as_line_3_with("N30 P1 = 0x10", "unexpected 'x'");  // strtod's hex floats are no NC numbers
  check_refused_as_line_3_with("N30 #TIME 1e300 * 1e300", "#TIME needs a dwell time > 0 and <= 1000000 s");
  check_refused_as_line_3_with("N30 #CS ON [1e300 * 1e300]", "result of '*' out of range");
  check_refused_as_line_3_with("N30 P1 = " + std::string(100000, '[') + "1" + std::string(100000, ']'),
                          "nested deeper than 100 levels");  // was a stack overflow
  check_refused_as_line_3_with("N30 P1 = " + std::string(100000, '-') + "1", "nested deeper than 100 levels");
}

TEST_CASE("KRN-1 KRN-2 decoder: $FOR bounds and steps that are not finite are errors, not skipped loops",
          "[decoder]") {
  check_refused({
      {"N10 G01 X1 F100\nN20 $FOR P1 = 0, 1e308 * 10, 1\nN30 X2\nN40 $ENDFOR\n", 2, "result of '*' out of range", 1},
      {"N10 G01 X1 F100\nN20 $FOR P1 = 1e300 * 1e300, 1\nN30 X2\nN40 $ENDFOR\n", 2, "result of '*' out of range", 1},
      {"N10 G01 X1 F100\nN20 $FOR P1 = 0, 1, 0/0\nN30 X2\nN40 $ENDFOR\n", 2, "division by zero", 1},
      // P1 + step past the largest double: was P1 = inf and the loop ended.
      {"N10 $FOR P1 = 1e308, 1.7e308, 1e308\nN20 G01 X1 F100\nN30 $ENDFOR\n", 3,
       "$FOR: P1 = 1e+308 + step 1e+308 is out of range", 1},
      // A step below P1's resolution: was 10,000,000 lines read, then an error.
      {"N10 $FOR P1 = 1e20, 1e21\nN20 P2 = 1\nN30 $ENDFOR\n", 3, "$FOR: P1 = 1e+20 + step 1 is no step", 0},
      {"N10 $FOR P100000 = 1, 2\nN20 $ENDFOR\n", 1, "$FOR: the P parameter number must be 0..99999", 0},
      {"N10 $FOR P1 = 1\nN20 $ENDFOR\n", 1, "$FOR needs P<n> = <start>, <end> [, <step>]", 0},
      {"N10 $FOR P1 = 1, 2\nN20 $ENDFOR X1\n", 2, "$ENDFOR must stand alone in its block", 0},
  });
  std::string nested;
  for (int i = 0; i < 20000; ++i) nested += "$FOR P1 = 1, 1\n";
  for (int i = 0; i < 20000; ++i) nested += "$ENDFOR\n";
  check_refused({nested, 101, "$FOR nested deeper than 100 levels", 0});  // took minutes
}

TEST_CASE("KRN-1 KRN-2 decoder: N, G, M and P numbers out of range are refused, never wrapped", "[decoder]") {
  // Was block_nr_r -2147483648: the N number was cast to int.
  const DecodedProgram n = decode("N10 G01 X1 F100\nN99999999999 X2\n");
  REQUIRE(n.error);
  CHECK(n.error->nc_line == 2);
  CHECK(n.error->block_nr == 0);  // not a number it could be
  CHECK_THAT(n.error->message, Catch::StartsWith("'N99999999999' needs a whole number 0..4294967295"));
  CHECK(n.blocks.size() == 1);
  check_refused({{"N10 G01 X1 F100\nN4294967296 X2\n", 2, "'N4294967296' needs a whole number 0..4294967295", 1},
                 {"N10 G01 X1 F100\nN99999999999 #TIME 1\n", 2, "'N99999999999' needs a whole number", 1}});
  check_refused_as_line_3_with("N30 G99999999999", "'G99999999999' needs a whole number 0..999");
  check_refused_as_line_3_with("N30 G1000 X1", "'G1000' needs a whole number 0..999");
  check_refused_as_line_3_with("N30 M2147483648", "'M2147483648' needs a whole number 0..2147483647");
  check_refused_as_line_3_with("N30 M1e20", "'M1e..': words take decimal numbers, no exponent");
  check_refused_as_line_3_with("N30 P100000 = 1", "'=' is only allowed in P<n> = <expression> (n 0..99999)");
  check_refused_as_line_3_with("N30 P1 = P4294967297", "P parameter numbers are 0..99999");
  check_refused_as_line_3_with("N30 $FOR P4294967297 = 1, 2", "$FOR: the P parameter number must be 0..99999");
  check_refused_as_line_3_with("N30 V.G.M_FCT[4294967303].PRE_OUTP_PATH = 1", "'=' is only allowed in P<n>");
  check_refused_as_line_3_with("N30 V.G.M_FCT P1 = 1", "'=' is only allowed in P<n>");
  // The base wrapped to 16 (4294967312 mod 2^32): END=1 was accepted.
  check_refused_as_line_3_with("N30 #DEL DIST2GO [END='4294967312#1']", "#DEL DIST2GO END: base must be 2#, 8# or 16#");
  check_refused_as_line_3_with("N30 #DEL DIST2GO [END='16#0x10']", "#DEL DIST2GO END '0X10' is not a 32-bit mask");
  check_refused_as_line_3_with("N30 #DEL DIST2GO [END=+5]", "#DEL DIST2GO END '+5' is not a 32-bit mask");

  const DecodedProgram p = decode("N4294967295 G01 X1 F100 M2147483647\nP99999 = 2\nN0 G0 X[P99999]\n");
  CHECK(p.blocks.at(0).block_nr == 4294967295);
  CHECK(p.blocks.at(0).m_functions == std::vector<MFunction>{{2147483647, 0}});
}

TEST_CASE("KRN-1 decoder: G92 keeps the M functions and M30 of its block", "[decoder]") {
  // The M7 was lost: a G92 block made no block.
  const DecodedProgram p = decode("N10 G92 X0 M7\nN20 G92 Y5 M30\nN30 G01 X1 F100\n");
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 2);  // N30 is after M30
  CHECK(p.blocks[0].block_nr == 10);
  CHECK(p.blocks[0].m_functions == std::vector<MFunction>{{7, 0}});
  CHECK_FALSE(p.blocks[0].has_motion);
  CHECK(p.blocks[1].block_nr == 20);
  CHECK(p.blocks[1].program_end);
}

TEST_CASE("KRN-1 KRN-2 decoder: #CS ON takes [..] groups and nothing else", "[decoder]") {
  check_refused_as_line_3_with("N30 #CS ONX [1]", "#CS ON: 'X' outside [v1,v2,v3,φ1,φ2,φ3]");  // was #CS ON [1]
  check_refused_as_line_3_with("N30 #CS ON [1] 2", "#CS ON: '2' outside [v1,v2,v3,φ1,φ2,φ3]");
  check_refused_as_line_3_with("N30 #CS ON [1]]", "#CS ON: ']' outside [v1,v2,v3,φ1,φ2,φ3]");
  check_refused_as_line_3_with("N30 #CS ON [[1]", "#CS ON: '[' is not closed");
  // Square brackets group the components' expressions.
  const DecodedProgram p = decode("N10 #CS ON [[1 + 2] * 2, 0, 0]\nN20 G01 X0 F100\n");
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 2);
  CHECK(p.blocks[1].motion.end[0] == Approx(6));
}

TEST_CASE("KRN-1 KRN-2 decoder: a NUL byte or other control character in a line is refused naming the line",
          "[decoder]") {
  for (const char c : {'\0', '\x01', '\x1b', '\x7f', '\f', '\v'}) {
    std::string line = "N30 X1";
    line += c;
    line += " Y2";
    INFO(static_cast<int>(c));
    const DecodedProgram p = decode("N10 G01 X1 F100\nN20 #TIME 1\n" + line + "\nN40 X50\n");
    REQUIRE(p.error);
    CHECK(p.error->nc_line == 3);
    CHECK(p.error->block_nr == 30);
    CHECK_THAT(p.error->message,
               Catch::StartsWith("control character 0x") && Catch::Contains(" in column 7: an NC program is text"));
    CHECK(p.error->message.find(c) == std::string::npos);  // quoted as \xNN
    CHECK(p.blocks.size() == 2);
  }
  // Tab and CR (CRLF files) are text.
  const DecodedProgram p = decode("N10\tG01 X1 F100\r\nN20 X2\r\n");
  REQUIRE_FALSE(p.error);
  CHECK(p.blocks.size() == 2);
}

TEST_CASE("KRN-1 decoder: lines of 100,000 characters are decoded without deep recursion", "[decoder]") {
  // std::regex overflowed the stack on these.
  const DecodedProgram p = decode("P1" + std::string(100000, ' ') + "= 1\nG01 X[P1] F100\n" + "N10 X2" +
                                  std::string(100000, ' ') + "\n");
  INFO((p.error ? p.error->message.substr(0, 300) : std::string()));
  REQUIRE(p.error);  // X[P1]: expressions in axis words are not supported yet
  CHECK(p.error->nc_line == 2);
  check_refused({"N30 $FOR P1 = 1, " + std::string(100000, '1') + ", 1\n", 1, "' out of range in expression", 0});
  // The message quotes at most 200 bytes of the line.
  const DecodedProgram q = decode("N10 X1 Y" + std::string(100000, '1') + "\n");
  REQUIRE(q.error);
  CHECK(q.error->message.size() < 600);
}

TEST_CASE("KRN-2 decoder: start positions out of range are an error before the first line", "[decoder]") {
  const DecodedProgram p = decode_program("G01 X1 F100\n", test::xyz_machine(), {0, 2e6, 0});
  REQUIRE(p.error);
  CHECK(p.error->nc_line == 0);
  CHECK_THAT(p.error->message, Catch::Contains("start position Y 2000000 mm is out of range"));
  CHECK(p.blocks.empty());
  const DecodedProgram q = decode_program("G01 X1 F100\n", test::xyz_machine(), {0, 0});
  REQUIRE(q.error);
  CHECK_THAT(q.error->message, Catch::Contains("2 start positions for 3 axes"));
}
