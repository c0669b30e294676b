// DPS-3: block search (cnc/search) over decoded programs: type 1 and type 4
// (block number plus covered distance), the text's examples, the phase-2
// errors, the warning, what is collected on the way and the continued
// program.
#include <catch2/catch.hpp>

#include <cmath>
#include <tuple>

#include "block_search.hpp"
#include "channel.hpp"
#include "channel_runner.hpp"
#include "collected_commands.hpp"
#include "decoder.hpp"
#include "dps_example_program.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

std::vector<Block> decoded(const std::string& text, const MachineConfig& machine = test::xyz_machine()) {
  const DecodedProgram p = decode_program(text, machine, std::vector<double>(machine.axes.size(), 0.0));
  INFO(text);
  REQUIRE_FALSE(p.error);
  return p.blocks;
}

BlockSearchOutcome search(const std::vector<Block>& blocks, int64_t block_nr, double distance_mm, int type = 4,
                          const MachineConfig& machine = test::xyz_machine()) {
  return search_block(blocks, BlockSearchRequest{type, block_nr, distance_mm}, machine);
}

Continuation found(const BlockSearchOutcome& outcome) {
  if (outcome.error) FAIL(outcome.error->message);
  REQUIRE(outcome.continuation);
  return *outcome.continuation;
}

void check_position(const std::vector<double>& actual, const std::vector<double>& expected) {
  REQUIRE(actual.size() == expected.size());
  for (size_t i = 0; i < actual.size(); ++i) {
    INFO("axis " << i);
    CHECK(actual[i] == Approx(expected[i]).margin(1e-9));
  }
}

std::vector<int> m_numbers(const std::vector<MFunction>& m_functions) {
  std::vector<int> numbers;
  for (const MFunction& m : m_functions) numbers.push_back(m.nr);
  return numbers;
}

// Where a run of the program stands when dist_prog_start first reaches
// `distance_mm` (the rig's own count, DPS-1), and the block number there.
std::pair<std::vector<double>, int64_t> run_reaching(const std::string& program, double distance_mm,
                                                     const MachineConfig& machine = test::xyz_machine()) {
  Channel channel(machine, program);
  std::pair<std::vector<double>, int64_t> at;
  test::run_program(channel, nullptr, [&](int64_t, const HliState& s, HliControl& c) {
    c.m_function_ack = {s.m_function_request_r && !c.m_function_ack.command_w, true};
    if (!at.first.empty() || s.dist_prog_start < distance_mm * hli_units_per_mm) return;
    for (const AxisSetpoint& p : channel.setpoints()) at.first.push_back(p.position);
    at.second = s.block_nr_r;
  });
  return at;
}

// N30 [10, 30] on the way; N50 [220, 260] (the text's two examples).
const char* example =
    "N10 G01 X5 F1000\n"       // [0, 5]
    "N20 Y5 M3\n"              // [5, 10]
    "N30 X25\n"                // [10, 30]
    "N40 Y45 M8\n"             // [30, 70]
    "N45 X100\n"               // [70, 145]
    "N46 Y90\n"                // [145, 190]
    "N47 X70\n"                // [190, 220]
    "N50 X30\n"                // [220, 260]
    "N60 Y0\n"                 // [260, 350]
    "M30\n";

}  // namespace

TEST_CASE("DPS-3 the text's example: type 4, N30, 16 mm: the continuation lies inside N30", "[DPS-3]") {
  const std::vector<Block> blocks = decoded(example);
  const Continuation c = found(search(blocks, 30, 16));
  CHECK(blocks[c.block].block_nr == 30);
  CHECK_FALSE(c.at_block_start);
  check_position(c.position, {11, 5, 0});
  CHECK(c.distance_mm == 16);
  CHECK(c.distance_counting);
  CHECK_FALSE(c.warning);
  CHECK(m_numbers(c.m_functions) == std::vector<int>{3});
  // Where a run stands at 16 mm: one cycle's travel (1000 mm/min) at most.
  const auto run = run_reaching(example, 16);
  CHECK(run.second == 30);
  for (size_t i = 0; i < 3; ++i) CHECK(run.first[i] == Approx(c.position[i]).margin(0.02));
}

TEST_CASE("DPS-3 the text's example: type 4, N30, 234.79 mm: over several blocks into N50", "[DPS-3]") {
  const std::vector<Block> blocks = decoded(example);
  const Continuation c = found(search(blocks, 30, 234.79));
  CHECK(blocks[c.block].block_nr == 50);
  CHECK_FALSE(c.at_block_start);
  check_position(c.position, {70 - 14.79, 90, 0});
  CHECK(c.distance_mm == 234.79);
  CHECK(m_numbers(c.m_functions) == std::vector<int>{3, 8});
  const auto run = run_reaching(example, 234.79);
  CHECK(run.second == 50);
  for (size_t i = 0; i < 3; ++i) CHECK(run.first[i] == Approx(c.position[i]).margin(0.02));
}

TEST_CASE("DPS-3 type 1 and a distance at the block's start: the continuation is the block's start", "[DPS-3]") {
  const std::vector<Block> blocks = decoded(example);
  for (const BlockSearchOutcome& outcome : {search(blocks, 30, 0, 1), search(blocks, 30, 10)}) {
    const Continuation c = found(outcome);
    CHECK(blocks[c.block].block_nr == 30);
    CHECK(c.at_block_start);
    check_position(c.position, {5, 5, 0});
    CHECK(c.distance_mm == 10);
    CHECK_FALSE(c.warning);
    CHECK(m_numbers(c.m_functions) == std::vector<int>{3});
  }
  // The block's end is the continuation's place inside it, not the next block's start.
  const Continuation end = found(search(blocks, 30, 30));
  CHECK(blocks[end.block].block_nr == 30);
  CHECK_FALSE(end.at_block_start);
  check_position(end.position, {25, 5, 0});
}

TEST_CASE("DPS-3 a distance before the searched block: a warning, the continuation at the block's start",
          "[DPS-3]") {
  const std::vector<Block> blocks = decoded(example);
  const Continuation c = found(search(blocks, 30, 2));
  REQUIRE(c.warning);
  CHECK(c.warning->severity == Severity::warning);
  CHECK(c.warning->nc_line == 3);
  CHECK(c.warning->block_nr == 30);
  CHECK_THAT(c.warning->message, Catch::Contains("lies before block N30") && Catch::Contains("start of N30"));
  CHECK(blocks[c.block].block_nr == 30);
  CHECK(c.at_block_start);
  check_position(c.position, {5, 5, 0});
  CHECK(c.distance_mm == 10);
}

TEST_CASE("DPS-3 a distance a round-off below the searched block's start is its start, no warning", "[DPS-3]") {
  const std::vector<Block> blocks = decoded(example);
  const Continuation c = found(search(blocks, 30, 10 - 1e-10));
  CHECK_FALSE(c.warning);
  CHECK(c.at_block_start);
  CHECK(blocks[c.block].block_nr == 30);
}

TEST_CASE("DPS-3 G74, G100, #FLUSH WAIT between the searched block and the continuation: error naming its line",
          "[DPS-3]") {
  MachineConfig machine = test::xyz_machine();
  machine.axes[0].reference_position = 25;  // G74 X1 after N30 does not move: the distances stay
  for (const std::string command : {"G74 X1", "G100 Y5 F500", "#FLUSH WAIT"}) {
    INFO(command);
    std::string text = example;
    text.insert(text.find("N40"), "N35 " + command + "\n");
    const std::vector<Block> blocks = decoded(text, machine);
    const BlockSearchOutcome outcome = search(blocks, 30, 234.79, 4, machine);
    CHECK_FALSE(outcome.continuation);
    REQUIRE(outcome.error);
    CHECK(outcome.error->severity == Severity::error);
    CHECK(outcome.error->nc_line == 4);
    CHECK(outcome.error->block_nr == 35);
    const std::string name = command.substr(0, command.find(' ', command[0] == '#' ? 7 : 0));
    CHECK(outcome.error->message ==
          name + " in line 4 (N35) lies between block N30 and the continuation point: G74, G100 and #FLUSH WAIT "
                 "cannot be simulated in a search by distance (DPS-3)");
    // Type 1, a continuation before it, or one at its block's start: no phase 2 passes it.
    CHECK(found(search(blocks, 30, 0, 1, machine)).at_block_start);
    CHECK(found(search(blocks, 30, 16, 4, machine)).position[0] == Approx(11));
    CHECK(blocks[found(search(blocks, 30, 30, 4, machine)).block].block_nr == 30);
    // Searched from a block after it: phase 1 simulates it.
    CHECK(blocks[found(search(blocks, 40, 234.79, 4, machine)).block].block_nr == 50);
  }
}

TEST_CASE("DPS-3 G74 before the searched block is phase 1; on the searched block its motion is phase 2",
          "[DPS-3]") {
  // N20 homes X from 100 to 0 [100, 200], N30 X50 [200, 250], N50 Y10 [250, 260].
  const std::vector<Block> blocks = decoded("N10 G01 X100 F1000\nN20 G74 X1\nN30 X50\nN40 #FLUSH WAIT\nN50 Y10\n");
  const Continuation c = found(search(blocks, 30, 220));
  CHECK(blocks[c.block].block_nr == 30);
  check_position(c.position, {20, 0, 0});
  // Searched at the G74 block: its start is phase 1, its motion phase 2.
  CHECK(found(search(blocks, 20, 0, 1)).at_block_start);
  CHECK(found(search(blocks, 20, 100)).at_block_start);
  const BlockSearchOutcome inside = search(blocks, 20, 120);
  REQUIRE(inside.error);
  CHECK(inside.error->nc_line == 2);
  CHECK_THAT(inside.error->message, Catch::StartsWith("G74 in line 2 (N20) lies between block N20"));
  // #FLUSH WAIT acts where its block is reached: on the searched block, phase 1.
  const Continuation after_flush = found(search(blocks, 40, 255));
  CHECK(blocks[after_flush.block].block_nr == 50);
  check_position(after_flush.position, {50, 5, 0});
  const BlockSearchOutcome across = search(blocks, 30, 255);
  REQUIRE(across.error);
  CHECK(across.error->nc_line == 4);
}

TEST_CASE("DPS-3 DPS-2 the text's #DISTANCE PROG START program: distance 450 lies in N230 at X50", "[DPS-3]") {
  const std::string text = std::string("%example\n") + test::dps_example_program;
  const std::vector<Block> blocks = decoded(text);
  // G92 offsets (additive, KRN-8): the first part at (33, 55), the second at (600, 700) in machine coordinates.
  for (const int64_t from : {10, 130, 230}) {
    INFO("N" << from);
    const Continuation c = found(search(blocks, from, 450));
    CHECK(blocks[c.block].block_nr == 230);
    check_position(c.position, {50 + 600, 700, 0});
    CHECK(c.distance_counting);
  }
  const Continuation n140 = found(search(blocks, 140, 100));
  CHECK(n140.at_block_start);
  CHECK(n140.distance_mm == 100);
  const Continuation n210 = found(search(blocks, 210, 0, 1));
  CHECK(n210.distance_mm == 400);
  CHECK_FALSE(n210.distance_counting);
  const Continuation n230 = found(search(blocks, 230, 0, 1));
  CHECK(n230.distance_mm == 400);
  CHECK(n230.distance_counting);
  // 400 is where N160 ends and N230 begins: inside N160, at its end.
  const Continuation at_400 = found(search(blocks, 130, 400));
  CHECK(blocks[at_400.block].block_nr == 160);
  check_position(at_400.position, {33, 55, 0});
  // Beyond the program's 800 mm.
  const BlockSearchOutcome beyond = search(blocks, 130, 800.5);
  REQUIRE(beyond.error);
  CHECK_THAT(beyond.error->message, Catch::Contains("beyond the program's end"));
  // The run gives the same: at 450 mm in N230 at program X50.
  const auto run = run_reaching(text, 450);
  CHECK(run.second == 230);
  CHECK(run.first[0] == Approx(50 + 600).margin(0.1));  // one cycle at F6000
}

TEST_CASE("DPS-3 #DISTANCE PROG START CLEAR: the count starts again from 0", "[DPS-3]") {
  const std::vector<Block> blocks =
      decoded("N10 G01 X100 F1000\nN20 #DISTANCE PROG START CLEAR\nN30 X150\nN40 X200\n");
  const Continuation before = found(search(blocks, 10, 30));
  check_position(before.position, {30, 0, 0});
  const Continuation after = found(search(blocks, 30, 30));
  CHECK(blocks[after.block].block_nr == 30);
  check_position(after.position, {130, 0, 0});
  // N10 [0, 100], N30 [0, 50], N40 [50, 100]: the first block whose span holds the distance.
  CHECK(blocks[found(search(blocks, 10, 80)).block].block_nr == 10);
  CHECK(blocks[found(search(blocks, 30, 80)).block].block_nr == 40);
  CHECK(search(blocks, 10, 130).error);  // beyond what the program counts after the CLEAR
}

TEST_CASE("DPS-3 G91 sections and $FOR loops: the first block with the N, positions as decoded", "[DPS-3]") {
  const std::string text =
      "N10 G01 G91 F1000\n"
      "N20 $FOR P1 = 1, 3, 1\n"
      "N30 X10\n"
      "N40 Y5\n"
      "N50 $ENDFOR\n"
      "N60 G90 X0 Y0\n";
  const std::vector<Block> blocks = decoded(text);
  REQUIRE(blocks.size() == 7);
  const Continuation c = found(search(blocks, 40, 20));  // N40 first at [10, 15], the second N30 [15, 25]
  CHECK(c.block == 2);
  CHECK(blocks[c.block].block_nr == 30);
  check_position(c.position, {15, 5, 0});
  const Continuation n40 = found(search(blocks, 40, 0, 1));
  CHECK(n40.block == 1);
  check_position(n40.position, {10, 0, 0});
  const auto run = run_reaching(text, 20);
  for (size_t i = 0; i < 3; ++i) CHECK(run.first[i] == Approx(c.position[i]).margin(0.02));
}

TEST_CASE("DPS-3 arcs and helices: the continuation on the arc; a block without main axis motion", "[DPS-3]") {
  const double quarter = 10 * M_PI / 2;
  const std::vector<Block> arc = decoded("N10 G01 X10 F1000\nN20 G03 X0 Y10 I-10 J0\n");
  check_position(found(search(arc, 10, 10 + quarter / 2)).position,
                 {10 * std::cos(M_PI / 4), 10 * std::sin(M_PI / 4), 0});
  const std::vector<Block> helix = decoded("N10 G01 X10 F1000\nN20 G03 X0 Y10 Z10 I-10 J0\n");
  const double helix_length = std::hypot(quarter, 10.0);
  const Continuation h = found(search(helix, 10, 10 + helix_length / 3));
  check_position(h.position, {10 * std::cos(M_PI / 6), 10 * std::sin(M_PI / 6), 10.0 / 3});
  const auto run = run_reaching("N10 G01 X10 F1000\nN20 G03 X0 Y10 Z10 I-10 J0\n", 10 + helix_length / 3);
  for (size_t i = 0; i < 3; ++i) CHECK(run.first[i] == Approx(h.position[i]).margin(0.02));
  // Only C moves: its travel is the distance (DPS-1).
  const MachineConfig xyzc = test::xyzc_machine();
  const std::vector<Block> rotary = decoded("N10 G01 X10 F1000\nN20 C90\nN30 X20\n", xyzc);
  const Continuation r = found(search(rotary, 20, 10 + 30, 4, xyzc));
  check_position(r.position, {10, 0, 0, 30});
}

TEST_CASE("DPS-3 M functions on the way: the last of each group, others once at their last, in program order",
          "[DPS-3]") {
  MachineConfig machine = test::xyz_machine();
  machine.m_pre_output_mm[50] = 2;
  const std::string text =
      "N10 G01 X10 F1000 M3 M8\n"
      "N20 X20 M50\n"
      "N30 X30 M5 M9 M00\n"
      "N35 #TIME 0.1\n"
      "N36 #INSERT CMD [DIST=5 ABS]\n"
      "N40 X40 M4 M50 M51\n"
      "N45 #INSERT CMD OFF\n"
      "N50 X50 M7\n";
  const std::vector<Block> blocks = decoded(text, machine);
  const Continuation in_n50 = found(search(blocks, 10, 45, 4, machine));
  CHECK(m_numbers(in_n50.m_functions) == std::vector<int>{4, 50, 51, 7});
  for (const MFunction& m : in_n50.m_functions) CHECK(m.pre_output_mm == 0);
  REQUIRE(in_n50.insert_cmd);
  CHECK(in_n50.insert_cmd->off);
  const Continuation in_n40 = found(search(blocks, 10, 35, 4, machine));
  CHECK(m_numbers(in_n40.m_functions) == std::vector<int>{9, 4, 50, 51});
  REQUIRE(in_n40.insert_cmd);
  CHECK_FALSE(in_n40.insert_cmd->off);
  const Continuation at_n40 = found(search(blocks, 40, 0, 1, machine));
  CHECK(m_numbers(at_n40.m_functions) == std::vector<int>{50, 5, 9});
  CHECK(found(search(blocks, 10, 0, 1, machine)).m_functions.empty());
  CHECK(m_function_groups[0] == std::array<int, 3>{3, 4, 5});
  CHECK(m_function_groups[1] == std::array<int, 3>{7, 8, 9});
}

TEST_CASE("DPS-3 search errors: no such N, beyond the end, type 2, a bad distance, into a lift range",
          "[DPS-3]") {
  const std::vector<Block> blocks = decoded(example);
  const BlockSearchOutcome none = search(blocks, 35, 0, 1);
  REQUIRE(none.error);
  CHECK(none.error->message == "block search: no block N35 in the program");
  CHECK(none.error->nc_line == 0);
  CHECK(search(blocks, 0, 0, 1).error);
  const BlockSearchOutcome beyond = search(blocks, 30, 350.001);
  REQUIRE(beyond.error);
  CHECK_THAT(beyond.error->message, Catch::Contains("beyond the program's end"));
  CHECK(blocks[found(search(blocks, 30, 350)).block].block_nr == 60);
  const BlockSearchOutcome type2 = search(blocks, 30, 16, 2);
  REQUIRE(type2.error);
  CHECK_THAT(type2.error->message, Catch::Contains("type 2 is not supported"));
  CHECK(search(blocks, 30, std::nan(""), 4).error);
  CHECK(search(blocks, 30, -1, 4).error);

  const MachineConfig lift = test::xyz_lift_machine();
  const std::vector<Block> ranged = decoded(
      "N10 G01 Z5 F1000\nN20 Z[LIFT_START POS=5 POS_LIMIT=30]\nN30 X10\nN40 X20\nN50 Z[LIFT_END]\nN60 X30\n", lift);
  for (const auto& [n, d, type] : std::vector<std::tuple<int64_t, double, int>>{{30, 0, 1}, {50, 0, 1}, {10, 10, 4}}) {
    INFO("N" << n << " " << d);
    const BlockSearchOutcome into = search(ranged, n, d, type, lift);
    REQUIRE(into.error);
    CHECK(into.error->message == "block search into a lift range is not supported (LIFT-1)");
  }
  CHECK(found(search(ranged, 20, 0, 1, lift)).at_block_start);  // its start is before the range
  CHECK(found(search(ranged, 60, 0, 1, lift)).at_block_start);
  check_position(found(search(ranged, 10, 30, 4, lift)).position, {25, 0, 5});
}

TEST_CASE("DPS-3 continued program: the approach, Z down last and up first, at the continuation's feed",
          "[DPS-3]") {
  const MachineConfig machine = test::xyz_machine();
  const std::vector<Block> blocks =
      decoded("N10 G00 X10 Y10 Z5\nN20 G01 Z-2 F600\nN30 X80 F3000 M8\nN40 Y40\nM30\n");
  // N10 15 mm, N20 7 mm, N30 [22, 92]: 52 mm is X40 in N30.
  const Continuation c = found(search(blocks, 30, 52));
  check_position(c.position, {40, 10, -2});
  const std::vector<Block> down = continued_program(blocks, c, {0, 0, 50}, machine);
  REQUIRE(down.size() == 5);
  const Block& xy = down[0];
  const Block& z = down[1];
  CHECK(xy.motion.start == std::vector<double>{0, 0, 50});
  check_position(xy.motion.end, {40, 10, 50});
  check_position(z.motion.end, {40, 10, -2});
  for (const Block& leg : {xy, z}) {
    CHECK(leg.has_motion);
    CHECK(leg.motion.type == MotionType::linear);
    CHECK(leg.motion.feed == Approx(50));
    CHECK(leg.transition == BlockTransition::exact_stop);
    CHECK(leg.nc_line == 3);
    CHECK(leg.block_nr == 30);
    CHECK(leg.block_count == blocks[c.block].block_count);
  }
  CHECK(xy.distance_prog_start == DistanceProgStart::off);
  CHECK_FALSE(z.distance_prog_start);
  CHECK(m_numbers(xy.m_functions) == std::vector<int>{8});  // N30's own: the continuation lies inside it
  CHECK(z.m_functions.empty());
  const Block& rest = down[2];
  CHECK(rest.block_nr == 30);
  check_position(rest.motion.start, {40, 10, -2});
  CHECK(rest.motion.end == std::vector<double>{80, 10, -2});
  CHECK(rest.m_functions.empty());
  CHECK(rest.distance_prog_start == DistanceProgStart::on);
  CHECK(down[3].block_nr == 40);
  CHECK(down[4].program_end);

  const std::vector<Block> up = continued_program(blocks, c, {0, 0, -10}, machine);
  REQUIRE(up.size() == 5);
  check_position(up[0].motion.end, {0, 0, -2});
  check_position(up[1].motion.end, {40, 10, -2});

  // A leg that does not move is left out; G00 where the program goes on with G00.
  const Continuation rapid = found(search(blocks, 10, 7.5));
  check_position(rapid.position, {5, 5, 2.5});
  const std::vector<Block> z_only = continued_program(blocks, rapid, {5, 5, 0}, machine);
  REQUIRE(z_only.size() == 1 + 5);
  CHECK(z_only[0].motion.type == MotionType::rapid);
  check_position(z_only[0].motion.end, {5, 5, 2.5});
  CHECK(z_only[0].distance_prog_start == DistanceProgStart::off);
  CHECK(z_only[1].motion.type == MotionType::rapid);
  check_position(z_only[1].motion.start, {5, 5, 2.5});
}

TEST_CASE("DPS-3 continued program: no approach, M functions first, the block's own commands at its start",
          "[DPS-3]") {
  const MachineConfig machine = test::xyz_machine();
  const std::vector<Block> blocks = decoded(
      "N10 G01 X10 F1000 M3\nN20 #INSERT CMD [DIST=5 ABS]\nN25 #DISTANCE PROG START OFF\nN30 X20 M8\n"
      "N35 #DISTANCE PROG START ON\nN40 X30 M9 M00\nN50 #TIME 1\nN60 X40 M30\n");
  // At N30's start: M3 and the #INSERT CMD on a block of their own, then N30 with its M8, not counting.
  const Continuation at = found(search(blocks, 30, 0, 1));
  CHECK_FALSE(at.distance_counting);
  const std::vector<Block> from_start = continued_program(blocks, at, {10, 0, 0}, machine);
  REQUIRE(from_start.size() == 6);
  CHECK_FALSE(from_start[0].has_motion);
  CHECK(m_numbers(from_start[0].m_functions) == std::vector<int>{3});
  CHECK(from_start[0].insert_cmd);
  CHECK(from_start[0].block_nr == 30);
  CHECK(m_numbers(from_start[1].m_functions) == std::vector<int>{8});
  CHECK_FALSE(from_start[1].distance_prog_start);  // not counting: nothing to switch on
  // Inside N40: its M9 and M00 ran on the way; M30 (with motion) stays.
  const Continuation inside = found(search(blocks, 10, 15));
  CHECK(blocks[inside.block].block_nr == 40);
  check_position(inside.position, {25, 0, 0});
  CHECK(m_numbers(inside.m_functions) == std::vector<int>{3, 9});  // M8 replaced; M00 is no M function output
  const std::vector<Block> rest = continued_program(blocks, inside, inside.position, machine);
  REQUIRE(rest.size() == 4);
  CHECK(m_numbers(rest[0].m_functions) == std::vector<int>{3, 9});
  CHECK_FALSE(rest[0].has_motion);
  CHECK(rest[1].block_nr == 40);
  CHECK(rest[1].m_functions.empty());
  CHECK_FALSE(rest[1].programmed_stop);
  CHECK(rest[1].distance_prog_start == DistanceProgStart::on);
  check_position(rest[1].motion.start, inside.position);
  CHECK(rest[1].motion.end == std::vector<double>{30, 0, 0});
  CHECK(rest[2].dwell_s == 1);
  CHECK(rest[3].program_end);
  // The block's own CLEAR at the continuation is already in the distance (0): counting goes on.
  const std::vector<Block> cleared = decoded("N10 G01 X10 F1000\nN20 #DISTANCE PROG START CLEAR\nN30 X20\n");
  const Continuation at_clear = found(search(cleared, 20, 0, 1));
  CHECK(at_clear.distance_mm == 0);
  const std::vector<Block> after_clear = continued_program(cleared, at_clear, {0, 0, 0}, machine);
  REQUIRE(after_clear.size() == 3);
  CHECK(after_clear[0].distance_prog_start == DistanceProgStart::off);
  CHECK(after_clear[1].distance_prog_start == DistanceProgStart::on);
  CHECK(after_clear[0].motion.type == MotionType::linear);  // the program goes on with N30's G01
  CHECK(after_clear[0].motion.feed == Approx(1000.0 / 60));
}
