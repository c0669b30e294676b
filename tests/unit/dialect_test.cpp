// KRN-8: the TwinCAT dialect real part programs use (docs/DIALECT.md):
// planes and arcs by centre or radius, helices, G04, G70/G71, G94, S T D H
// with the spindle's M03/M04/M05, zero offsets G53..G59, G92's additive
// offset, block skip, the arc end point tolerance, refusals that say why.
#include <catch2/catch.hpp>

#include <cmath>
#include <yaml-cpp/yaml.h>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "collected_commands.hpp"
#include "decoder.hpp"
#include "path_segment.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {
DecodedProgram decode(const std::string& text, const MachineConfig& machine = test::xyz_machine()) {
  return decode_program(text, machine, {0, 0, 0});
}

// The last motion block of `text`, which must decode.
Block last_motion(const std::string& text, const MachineConfig& machine = test::xyz_machine()) {
  const DecodedProgram p = decode(text, machine);
  INFO(text);
  REQUIRE_FALSE(p.error);
  for (auto b = p.blocks.rbegin(); b != p.blocks.rend(); ++b)
    if (b->has_motion) return *b;
  FAIL("no motion block");
  return {};
}

std::string refusal(const std::string& text, const MachineConfig& machine = test::xyz_machine()) {
  const DecodedProgram p = decode(text, machine);
  INFO(text);
  REQUIRE(p.error);
  return p.error->message;
}

// Where the path of `b` is halfway.
std::vector<double> midpoint(const Block& b) {
  const PathSegment segment(b.motion, test::xyz_machine());
  return segment.position(segment.length() / 2);
}
}  // namespace

TEST_CASE("KRN-8 G17 / G18 / G19: the plane's axes, centre words and sense of rotation", "[decoder][dialect]") {
  SECTION("G17: X Y with I J, counter-clockwise from X to Y") {
    const Block b = last_motion("G01 X10 F1000\nG17 G03 X0 Y10 I-10 J0\n");
    CHECK(b.motion.plane == std::array<int, 2>{0, 1});
    CHECK(b.motion.center[0] == Approx(0).margin(1e-12));
    const auto m = midpoint(b);
    CHECK(m[0] == Approx(10 / std::sqrt(2.0)));
    CHECK(m[1] == Approx(10 / std::sqrt(2.0)));
  }
  SECTION("G18: Z X with K I, counter-clockwise from Z to X") {
    const Block b = last_motion("G01 Z10 F1000\nG18 G03 Z0 X10 K-10 I0\n");
    CHECK(b.motion.plane == std::array<int, 2>{2, 0});
    CHECK(b.motion.center[0] == Approx(0).margin(1e-12));  // Z
    CHECK(b.motion.center[1] == Approx(0).margin(1e-12));  // X
    const auto m = midpoint(b);
    CHECK(m[2] == Approx(10 / std::sqrt(2.0)));
    CHECK(m[0] == Approx(10 / std::sqrt(2.0)));
    CHECK(m[1] == Approx(0).margin(1e-12));
    // G02 the other way round: through negative X.
    const auto cw = midpoint(last_motion("G01 Z10 F1000\nG18 G02 Z0 X-10 K-10\n"));
    CHECK(cw[0] == Approx(-10 / std::sqrt(2.0)));
  }
  SECTION("G19: Y Z with J K, counter-clockwise from Y to Z") {
    const Block b = last_motion("G01 Y10 F1000\nG19 G03 Y0 Z10 J-10\n");
    CHECK(b.motion.plane == std::array<int, 2>{1, 2});
    const auto m = midpoint(b);
    CHECK(m[1] == Approx(10 / std::sqrt(2.0)));
    CHECK(m[2] == Approx(10 / std::sqrt(2.0)));
  }
  SECTION("G17 is the initial plane and the plane is modal") {
    CHECK(last_motion("G01 X10 F1000\nG02 X0 Y-10 I-10\n").motion.plane == std::array<int, 2>{0, 1});
    CHECK(last_motion("G18\nG01 Z10 F1000\nG02 Z0 X-10 K-10\n").motion.plane == std::array<int, 2>{2, 0});
  }
  SECTION("a centre word off the plane is refused") {
    CHECK_THAT(refusal("G01 X10 F1000\nG02 X0 Y-10 K-10\n"),
               Catch::StartsWith("'K' is no centre word in G17: its arcs take I and J"));
    CHECK_THAT(refusal("G18 G01 Z10 F1000\nG02 Z0 X-10 J-10\n"), Catch::StartsWith("'J' is no centre word in G18"));
  }
}

TEST_CASE("KRN-8 arcs by radius R: the shorter arc for R > 0, the longer for R < 0", "[decoder][dialect]") {
  // Chord 10 along X, R 10: the centre lies 8.66 mm off the chord.
  const double h = std::sqrt(75.0);
  SECTION("G02 R10: centre right of the chord, 60 degrees") {
    const Block b = last_motion("G01 F1000\nG02 X10 Y0 R10\n");
    CHECK(b.motion.center[0] == Approx(5));
    CHECK(b.motion.center[1] == Approx(-h));
    CHECK(PathSegment(b.motion, test::xyz_machine()).length() == Approx(10 * M_PI / 3));
  }
  SECTION("G02 R-10: centre left of the chord, 300 degrees") {
    const Block b = last_motion("G01 F1000\nG02 X10 Y0 R-10\n");
    CHECK(b.motion.center[1] == Approx(h));
    CHECK(PathSegment(b.motion, test::xyz_machine()).length() == Approx(10 * 5 * M_PI / 3));
  }
  SECTION("G03 R10 and R-10") {
    CHECK(last_motion("G01 F1000\nG03 X10 Y0 R10\n").motion.center[1] == Approx(h));
    CHECK(last_motion("G01 F1000\nG03 X10 Y0 R-10\n").motion.center[1] == Approx(-h));
  }
  SECTION("R in G18, and a half circle") {
    const Block b = last_motion("G18 G01 F1000\nG03 Z10 X0 R5\n");
    CHECK(b.motion.center[0] == Approx(5));
    CHECK(b.motion.center[1] == Approx(0).margin(1e-9));
  }
  SECTION("refusals") {
    CHECK_THAT(refusal("G01 F1000\nG02 X10 Y0 R3\n"),
               Catch::StartsWith("R3: the end point lies 10 mm from the start, farther than the diameter 6 mm"));
    CHECK_THAT(refusal("G01 F1000\nG02 X0 Y0 R3\n"),
               Catch::StartsWith("a full circle cannot be programmed with R: give its centre (I J K)"));
    CHECK_THAT(refusal("G01 F1000\nG02 X10 Y0 R5 I5\n"),
               Catch::StartsWith("an arc takes its centre (I J K) or its radius R, not both"));
    CHECK_THAT(refusal("G01 X10 Y0 R5 F1000\n"), Catch::StartsWith("I J K R are only allowed with G02/G03"));
  }
}

TEST_CASE("KRN-8 helices: the axis off the plane moves linearly along the arc, also a full turn",
          "[decoder][dialect]") {
  SECTION("G17 quarter turn with Z") {
    const Block b = last_motion("G01 X10 F1000\nG03 X0 Y10 Z-4 I-10\n");
    const PathSegment s(b.motion, test::xyz_machine());
    CHECK(s.length() == Approx(std::hypot(10 * M_PI / 2, 4.0)));
    CHECK(s.position(s.length() / 2)[2] == Approx(-2));
  }
  SECTION("a full turn: only Z changes") {
    const Block b = last_motion("G01 X10 F1000\nG02 Z-3 I-10\n");
    const PathSegment s(b.motion, test::xyz_machine());
    CHECK(s.length() == Approx(std::hypot(20 * M_PI, 3.0)));
    CHECK(s.position(s.length() / 2)[0] == Approx(-10));
  }
  SECTION("G18 helix along Y, G19 along X") {
    CHECK(PathSegment(last_motion("G18 G01 Z10 F1000\nG03 Z0 X10 Y5 K-10\n").motion, test::xyz_machine()).length() ==
          Approx(std::hypot(10 * M_PI / 2, 5.0)));
    CHECK(PathSegment(last_motion("G19 G01 Y10 F1000\nG03 Y0 Z10 X5 J-10\n").motion, test::xyz_machine()).length() ==
          Approx(std::hypot(10 * M_PI / 2, 5.0)));
  }
}

TEST_CASE("KRN-8 the arc end point tolerance: P-CHAN-00171 / P-CHAN-00172, error 21758", "[decoder][dialect]") {
  // Radius 10 at the start; the end 4 um / 6 um outside.
  SECTION("within the default 5 um: a spiral") {
    const Block b = last_motion("G01 X10 F1000\nG03 X-10.004 Y0 I-10\n");
    CHECK(b.motion.end[0] == Approx(-10.004));
  }
  SECTION("beyond it: an error naming both radii and the parameters") {
    const DecodedProgram p = decode("G01 X10 F1000\nG03 X-10.006 Y0 I-10\n");
    REQUIRE(p.error);
    CHECK(p.error->id == 21758);
    CHECK_THAT(p.error->message, Catch::Contains("start radius 10 mm, end radius 10.006 mm"));
    CHECK_THAT(p.error->message, Catch::Contains("P-CHAN-00171 max_radius_diff_circle"));
  }
  SECTION("the machine file sets it") {
    YAML::Node node = YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml");
    node["max_radius_diff_circle"] = 100;  // 10 um
    const MachineConfig wide = parse_machine_config(node);
    CHECK_FALSE(decode("G01 X10 F1000\nG03 X-10.009 Y0 I-10\n", wide).error);
    node["max_radius_diff_circle"] = 10;  // 1 um
    node["max_proz_radius_diff_circle"] = 1;  // 0.1 % of 10 mm = 10 um
    CHECK_FALSE(decode("G01 X10 F1000\nG03 X-10.009 Y0 I-10\n", parse_machine_config(node)).error);
    node["max_proz_radius_diff_circle"] = 0;
    CHECK(decode("G01 X10 F1000\nG03 X-10.002 Y0 I-10\n", parse_machine_config(node)).error);
  }
}

TEST_CASE("KRN-8 G04 dwell, G70 / G71, G94; G93 / G95 refused", "[decoder][dialect]") {
  SECTION("G04 X<s> and G04 <s>") {
    const DecodedProgram p = decode("N10 G04 X0.5\nN20 G04 2\nN30 G4 X.25\n");
    REQUIRE_FALSE(p.error);
    REQUIRE(p.blocks.size() == 3);
    CHECK(p.blocks[0].dwell_s == 0.5);
    CHECK(p.blocks[1].dwell_s == 2);
    CHECK(p.blocks[2].dwell_s == 0.25);
    CHECK(p.blocks[0].block_nr == 10);
  }
  SECTION("G04 alone in its block") {
    const DecodedProgram p = decode("N10 G04 X1 Y2\n");
    REQUIRE(p.error);
    CHECK(p.error->id == 20685);
    CHECK_THAT(refusal("G04\n"), Catch::StartsWith("G04 needs the dwell time"));
  }
  SECTION("G70 inch: lengths and feed; rotary axes keep degrees; G71 back to mm") {
    const DecodedProgram p = decode("G70 G01 X1 Y.5 F10\nG02 X2 Y.5 I.5\nG71 G01 X3\n");
    REQUIRE_FALSE(p.error);
    CHECK(p.blocks[0].motion.end[0] == Approx(25.4));
    CHECK(p.blocks[0].motion.end[1] == Approx(12.7));
    CHECK(p.blocks[0].motion.feed == Approx(25.4 * 10 / 60));
    CHECK(p.blocks[1].motion.center[0] == Approx(38.1));
    CHECK(p.blocks[2].motion.end[0] == Approx(3));
    const DecodedProgram c = decode_program("G70 G01 C90 X1 F10\n", test::xyzc_machine(), {0, 0, 0, 0});
    REQUIRE_FALSE(c.error);
    CHECK(c.blocks[0].motion.end[3] == Approx(90));
  }
  SECTION("G94 is the feed mode; the others are refused with their reason") {
    CHECK_FALSE(decode("G94 G01 X1 F100\n").error);
    CHECK_THAT(refusal("G95 G01 X1 F1\n"),
               Catch::StartsWith("G95 feed per spindle revolution (the rig simulates no spindle) is not supported"));
    CHECK_THAT(refusal("G93 G01 X1 F1\n"), Catch::StartsWith("G93 feed as machining time is not supported by this rig"));
  }
}

TEST_CASE("KRN-8 S T D H and the spindle's M03 / M04 / M05 go to the PLC in the block's order", "[decoder][dialect]") {
  auto functions = [](const Block& b) {
    std::string out;
    for (const MFunction& f : b.m_functions)
      out += std::string(out.empty() ? "" : " ") + f.address +
             std::to_string(f.address == 'S' ? static_cast<int>(f.value) : f.nr);
    return out;
  };
  const DecodedProgram p = decode(
      "N10 T4 M06 D4\n"
      "N20 S12000 M03 M08\n"
      "N30 S8000\n"  // the spindle turns: goes out at once
      "N40 M05 H12\n"
      "N50 S5000\n"  // stopped: kept for the next start
      "N60 M04\n"
      "N70 M09 M30\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 6);
  CHECK(functions(p.blocks[0]) == "T4 M6 D4");
  CHECK(functions(p.blocks[1]) == "S12000 M3 M8");
  CHECK(functions(p.blocks[2]) == "S8000");
  CHECK(functions(p.blocks[3]) == "M5 H12");
  CHECK(functions(p.blocks[4]) == "S5000 M4");
  CHECK(p.blocks[4].block_nr == 60);
  CHECK(functions(p.blocks[5]) == "M9");
  // M03 before S in its block: the block's S goes out, not the one kept before.
  const DecodedProgram q = decode("S100\nM03 S12000\n");
  REQUIRE_FALSE(q.error);
  CHECK(functions(q.blocks.back()) == "S12000 M3");
  CHECK_THAT(refusal("M03 M05\n"), Catch::StartsWith("'M05': one of M03 / M04 / M05 in a block"));
  CHECK_THAT(refusal("S-5 M03\n"), Catch::StartsWith("'S-5': the spindle speed S must be 0 .. 1000000 rpm"));
  CHECK_THAT(refusal("T1.5\n"), Catch::StartsWith("'T1.5' needs a whole number"));
}

TEST_CASE("KRN-8 zero offsets G54..G59 from the machine file, G53 deselects; G92 is an additive offset",
          "[decoder][dialect]") {
  YAML::Node node = YAML::LoadFile(std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml");
  node["zero_offsets"]["G54"]["X"] = 100;
  node["zero_offsets"]["G54"]["Y"] = 0;
  node["zero_offsets"]["G54"]["Z"] = -20;
  node["zero_offsets"]["G59"]["Y"] = 7;
  const MachineConfig machine = parse_machine_config(node);
  SECTION("G54 .. G59 and G53") {
    const DecodedProgram p = decode("G54 G01 X0 Y0 Z0 F1000\nX5\nG59 X0\nG53 X1 Y1\n", machine);
    REQUIRE_FALSE(p.error);
    CHECK(p.blocks[0].motion.end == std::vector<double>{100, 0, -20});
    CHECK(p.blocks[1].motion.end == std::vector<double>{105, 0, -20});
    CHECK(p.blocks[2].motion.end == std::vector<double>{0, 0, -20});  // only X programmed: G59 has no X offset
    CHECK(p.blocks[3].motion.end == std::vector<double>{1, 1, -20});
  }
  SECTION("G92 X10: X0 is X10 of the machine (TF5200 G92); G91 adds to it; on top of G54") {
    const DecodedProgram p = decode("G92 X10 Y20\nG01 X0 Y0 F1000\nG91 G92 X5\nG90 X0\nG54 X0\nG92 X0\nX0\n", machine);
    REQUIRE_FALSE(p.error);
    CHECK(p.blocks[0].motion.end == std::vector<double>{10, 20, 0});
    CHECK(p.blocks[1].motion.end == std::vector<double>{15, 20, 0});
    CHECK(p.blocks[2].motion.end == std::vector<double>{115, 20, 0});  // Z not programmed: stays
    CHECK(p.blocks[3].motion.end == std::vector<double>{100, 20, 0});
  }
  SECTION("the machine file's tables are checked") {
    node["zero_offsets"]["G60"]["X"] = 1;
    CHECK_THROWS_WITH(parse_machine_config(node), Catch::Contains("zero_offsets.G60"));
    node["zero_offsets"].remove("G60");
    node["zero_offsets"]["G55"]["Q"] = 1;
    CHECK_THROWS_WITH(parse_machine_config(node), Catch::Contains("zero_offsets.G55.Q"));
  }
  SECTION("V.G.NP[n].V.<axis> = <mm> sets a table entry from the program (TF5200 \"Zero offsets\")") {
    const DecodedProgram p = decode("G54 G01 X0 F1000\nV.G.NP[1].V.X = 40\nX0\nV.G.NP[6].V.Y=2*3\nG59 Y0\n", machine);
    REQUIRE_FALSE(p.error);
    CHECK(p.blocks[0].motion.end[0] == 100);
    CHECK(p.blocks[1].motion.end[0] == 40);  // in force at once for G54
    CHECK(p.blocks[2].motion.end[1] == 6);
    CHECK_THAT(refusal("V.G.NP[7].V.X = 1\n", machine), Catch::StartsWith("'=' is only allowed in"));
    CHECK_THAT(refusal("V.G.NP[1].V.Q = 1\n", machine), Catch::StartsWith("'=' is only allowed in"));
  }
  CHECK_THAT(refusal("G54 G55 X1\n"), Catch::StartsWith("two zero offsets G53..G59 in one block"));
}

TEST_CASE("KRN-8 channel: the PLC writes a zero offset table entry; blocks decoded after it use it",
          "[channel][dialect]") {
  // G54 X is 100 in config/xyz_machine.yaml; the PLC makes it 250 before the start.
  Channel channel(test::xyz_machine(), "G54 G01 X0 Y0 Z0 F6000\nM30\n");
  HliControl c;
  c.zero_offset = {{1, 1, 2500000}, true};  // G54, X, 250 mm in 0.1 um
  channel.step(0, c);
  c.zero_offset.command_w = {9, 1, 0};  // no G59 + 3: refused with a warning, the tables stay
  channel.step(1, c);
  const std::vector<Event> events = channel.take_events();
  REQUIRE(events.size() == 1);
  CHECK(events[0].severity == Severity::warning);
  CHECK_THAT(events[0].message, Catch::StartsWith("zero offset write refused: group 9"));
  test::run_program(channel, nullptr, nullptr, 2);
  CHECK(channel.setpoints()[0].position == Approx(250));
  CHECK(channel.setpoints()[2].position == Approx(-20));
}

TEST_CASE("KRN-8 KRN-2 a refused word's column in its line", "[decoder][dialect]") {
  const DecodedProgram p = decode("N10 G01 X1 F100\n  N20 G01 G41 X2\nN30 G01 A5\n");
  REQUIRE(p.error);
  CHECK(p.error->column == 11);
  CHECK(decode("N10 G01 X1 A5 F100\n").error->column == 12);
  CHECK(decode("n10 g01 x1 g4 g41\n").error->column == 15);  // the G41, not the G4 of it
  CHECK(decode("G01 X10 F100\nG02 X0 Y0 R3\n").error->column == 0);  // the block, not one word
}

TEST_CASE("KRN-8 block skip: /1 .. /10, a bare / is /1, switched by program_block_ignore", "[decoder][dialect]") {
  const std::string program = "N10 G01 X1 F1000\n/N20 X2\n/2 N30 X3\n/10 N40 X4\nN50 X5\n";
  auto ends = [&](uint32_t levels) {
    std::vector<double> out;
    const ProgramText text = program_text(program);
    const MachineConfig machine = test::xyz_machine();
    ProgramDecoder decoder(text(), machine, {0, 0, 0});
    decoder.set_block_ignore(levels);
    Block b;
    while (decoder.next(b)) out.push_back(b.motion.end[0]);
    REQUIRE_FALSE(decoder.error());
    return out;
  };
  CHECK(ends(0) == std::vector<double>{1, 2, 3, 4, 5});
  CHECK(ends(1) == std::vector<double>{1, 3, 4, 5});
  CHECK(ends(2) == std::vector<double>{1, 2, 4, 5});
  CHECK(ends(0x200) == std::vector<double>{1, 2, 3, 5});
  CHECK(ends(0x3FF) == std::vector<double>{1, 5});
  CHECK_THAT(refusal("/11 X1\n"), Catch::StartsWith("block skip '/11': the skip levels are /1 .. /10"));
  CHECK_THAT(refusal("/0 X1\n"), Catch::StartsWith("block skip '/0'"));
}

TEST_CASE("KRN-8 refusals say what is refused and why", "[decoder][dialect]") {
  CHECK_THAT(refusal("G01 A5 F100\n"), Catch::StartsWith("'A5': A is not an axis of this machine"));
  CHECK_THAT(refusal("G01 O5 F100\n"), Catch::StartsWith("'O5': O is not a word of the TwinCAT dialect"));
  CHECK_THAT(refusal("G01 E5 F100\n"), Catch::StartsWith("'E5': E (feed at block end) is not supported by this rig"));
  CHECK_THAT(refusal("G41 G01 X5 F100\n"),
             Catch::StartsWith("G41 tool radius compensation (left) is not supported by this rig"));
  CHECK_THAT(refusal("G21\n"), Catch::StartsWith("G21 mirroring (TwinCAT G20..G23 mirror; metric input is G71)"));
  CHECK_THAT(refusal("G81 X1\n"), Catch::StartsWith("G81 an implicit subroutine call"));
  const DecodedProgram p = decode("G28 X0\n");
  REQUIRE(p.error);
  CHECK(p.error->id == 20131);
  CHECK_THAT(p.error->message, Catch::StartsWith("G28 is not a G function of the TwinCAT CNC (TF5200)"));
  CHECK_FALSE(decode("G40 G17 G90 G94 G71 G01 X1 F100\n").error);  // what a post writes first
}

TEST_CASE("KRN-8 channel: S T H wait for their acknowledgements on the HLI, D is shown; skip levels from the PLC",
          "[channel][dialect]") {
  Channel channel(test::xyz_machine(), "N10 T7 M06 D3\nN20 S9000 M03\nN30 H5\n/N40 G01 X20 F3000\nN50 G01 X10 F3000\nM30\n");
  std::vector<std::string> seen;
  double highest_x = 0;
  HliControl c = test::start_command(true);
  c.program_block_ignore = {1, true};  // set before the start: the decoder reads ahead
  for (int64_t k = 0; k < 100000 && !channel.finished(); ++k) {
    channel.step(k, c);
    c.program_start.command_w = false;
    const HliState& s = channel.hli();
    highest_x = std::max(highest_x, channel.setpoints()[0].position);
    auto answer = [&](bool requested, ControlUnitBool& ack, const std::string& what) {
      if (requested && !ack.command_w) seen.push_back(what);
      ack = {requested && !ack.command_w, true};
    };
    answer(s.t_function_request_r, c.t_function_ack, "T" + std::to_string(s.t_function_nr_r));
    answer(s.m_function_request_r, c.m_function_ack,
           "M" + std::to_string(s.m_function_nr_r) + " D" + std::to_string(s.tool_offset_nr_r));
    answer(s.s_function_request_r, c.s_function_ack, "S" + std::to_string(static_cast<int>(s.s_function_value_r)));
    answer(s.h_function_request_r, c.h_function_ack, "H" + std::to_string(s.h_function_nr_r));
  }
  CHECK(channel.hli().channel_state == ChannelState::program_end);
  // D3 follows the M06 that came before it: shown once the M06 is acknowledged.
  CHECK(seen == std::vector<std::string>{"T7", "M6 D0", "S9000", "M3 D3", "H5"});
  CHECK(channel.hli().tool_offset_nr_r == 3);
  CHECK(channel.hli().program_block_ignore.state_r == 1);
  CHECK(highest_x == Approx(10));  // /N40 X20 skipped
}

TEST_CASE("KRN-8 DPS-3 block search collects S T D as the last of each and H by number, apart from M",
          "[decoder][dialect][DPS-3]") {
  const DecodedProgram p = decode("T1 M06 D1\nS5000 M03 H7\nT2 M06 D2\nS8000\nH7 H8 M08\nM09\n");
  REQUIRE_FALSE(p.error);
  CollectedCommands collected;
  for (const Block& b : p.blocks) collected.pass(b);
  std::string out;
  for (const MFunction& f : collected.m_functions())
    out += std::string(out.empty() ? "" : " ") + f.address +
           std::to_string(f.address == 'S' ? static_cast<int>(f.value) : f.nr);
  CHECK(out == "M3 T2 M6 D2 S8000 H7 H8 M9");
}
