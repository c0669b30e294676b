// DPS-3: the commands block search by distance cannot simulate, in the
// decoder: G74 (homing run), G100 (measurement run) and #FLUSH WAIT carry
// Block::not_searchable; G74 / G100 move as the rig simulates their signal.
#include <catch2/catch.hpp>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "config_error.hpp"
#include "decoder.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

DecodedProgram decode(const std::string& text, const MachineConfig& machine = test::xyz_machine()) {
  return decode_program(text, machine, {0, 0, 0});
}

void check_refused(const std::string& text, int64_t nc_line, const std::string& part) {
  INFO(text);
  const DecodedProgram p = decode(text);
  REQUIRE(p.error);
  CHECK(p.error->nc_line == nc_line);
  CHECK_THAT(p.error->message, Catch::Contains(part));
}

}  // namespace

TEST_CASE("DPS-3 G74: the named axes move together to their reference points as a rapid, non-modal",
          "[decoder][DPS-3]") {
  MachineConfig machine = test::xyz_machine();
  machine.axes[0].reference_position = -5;
  machine.axes[1].reference_position = 7;
  const DecodedProgram p = decode("N10 G01 X10 Y20 Z5 F600\nN20 G74 X1 Y2\nN30 X5\nN40 G74 Z1\n", machine);
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 4);
  const Block& homing = p.blocks[1];
  CHECK(homing.block_nr == 20);
  CHECK(homing.not_searchable == "G74");
  REQUIRE(homing.has_motion);
  CHECK(homing.motion.type == MotionType::rapid);
  CHECK(homing.motion.start == std::vector<double>{10, 20, 5});
  CHECK(homing.motion.end == std::vector<double>{-5, 7, 5});  // Z not named: stays
  CHECK(homing.transition == BlockTransition::exact_stop);     // the signal ends it at standstill
  // The decoder's position is the reference point; G01 is still modal.
  CHECK(p.blocks[2].motion.type == MotionType::linear);
  CHECK(p.blocks[2].motion.start == std::vector<double>{-5, 7, 5});
  CHECK(p.blocks[2].motion.end == std::vector<double>{5, 7, 5});
  CHECK(p.blocks[2].not_searchable.empty());
  CHECK(p.blocks[3].motion.end == std::vector<double>{5, 7, 0});  // default reference_position 0
}

TEST_CASE("DPS-3 G74 at the reference point keeps its block (no motion); G74 refusals", "[decoder][DPS-3]") {
  const DecodedProgram p = decode("N10 G74 X1\nN20 G01 X3 F100\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 2);
  CHECK_FALSE(p.blocks[0].has_motion);
  CHECK(p.blocks[0].not_searchable == "G74");
  check_refused("N10 G01 X1 F100\nN20 G74\n", 2, "G74 needs the axes to home");
  check_refused("N10 G74 G01 X1 F100\n", 1, "G74 cannot be combined with G00 / G01 / G02 / G03");
  check_refused("N10 G74 G100 X1 F100\n", 1, "two of G74 / G100 in one block");
  check_refused("N10 G92 G74 X1\n", 1, "G92 must not be combined with motion");
  MachineConfig far = test::xyz_machine();
  far.axes[2].reference_position = 2e6;
  const DecodedProgram q = decode("N10 G74 Z1\n", far);
  REQUIRE(q.error);
  CHECK(q.error->nc_line == 1);
}

TEST_CASE("DPS-3 G100: a linear feed motion to the programmed point, non-modal", "[decoder][DPS-3]") {
  const DecodedProgram p = decode("N10 G00 X1 Y1\nN20 G100 X50 Y10 F300\nN30 X60\nN40 G91 G100 Y-4\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 4);
  const Block& measuring = p.blocks[1];
  CHECK(measuring.not_searchable == "G100");
  CHECK(measuring.motion.type == MotionType::linear);
  CHECK(measuring.motion.feed == Approx(5.0));
  CHECK(measuring.motion.end == std::vector<double>{50, 10, 0});
  CHECK(measuring.transition == BlockTransition::exact_stop);
  CHECK(p.blocks[2].motion.type == MotionType::rapid);  // G00 still modal
  CHECK(p.blocks[2].not_searchable.empty());
  CHECK(p.blocks[3].motion.end == std::vector<double>{60, 6, 0});  // G91
  check_refused("N10 G100 X10\n", 1, "no feed F programmed for G100");
  check_refused("N10 G100 X10 I5 F100\n", 1, "I J K R are only allowed with G02/G03");
}

TEST_CASE("DPS-3 #FLUSH WAIT marks its block, also outside a lift range; #FLUSH does not", "[decoder][DPS-3]") {
  const DecodedProgram p = decode("N10 G01 X1 F100\nN20 #FLUSH\nN30 #flush  wait\nN40 X2\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 3);
  CHECK(p.blocks[1].block_nr == 30);
  CHECK(p.blocks[1].not_searchable == "#FLUSH WAIT");
  CHECK_FALSE(p.blocks[1].has_motion);
  CHECK_FALSE(p.blocks[1].lift_end);
  CHECK(p.blocks[1].short_cut_restriction == ShortCutRestriction::none);
  CHECK(p.blocks[1].has_command());
  CHECK_FALSE(p.blocks[1].stops_path());
  // In a lift range it is also #FLUSH (LIFT-5).
  const DecodedProgram r = decode_program(
      "N10 G01 Z5 F1000\nN20 Z[LIFT_START POS=5 POS_LIMIT=30]\nN30 X10\nN40 #FLUSH WAIT\nN50 X20\nN60 Z[LIFT_END]\n",
      test::xyz_lift_machine(), {0, 0, 0});
  REQUIRE_FALSE(r.error);
  REQUIRE(r.blocks.size() == 6);
  CHECK(r.blocks[3].not_searchable == "#FLUSH WAIT");
  CHECK(r.blocks[3].lift_end);
  CHECK(r.blocks[3].lift_start);
}

TEST_CASE("DPS-3 a run passes G74, G100 and #FLUSH WAIT blocks as the decoder moves them, within the limits",
          "[channel][DPS-3]") {
  MachineConfig m = test::xyz_machine();
  m.axes[0].reference_position = 20;
  Channel channel(m, "N10 G01 X10 Y5 F3000\nN20 #FLUSH WAIT\nN30 G74 X1 Z2\nN40 G100 Y30 F1200\nN50 X0\nM30\n");
  logger::LimitChecker checker(m);
  test::run_program(channel, &checker);
  CHECK(channel.hli().channel_state == ChannelState::program_end);
  CHECK(channel.setpoints()[0].position == Approx(0));
  CHECK(channel.setpoints()[1].position == Approx(30));
  for (const Event& e : channel.take_events()) CHECK(e.severity == Severity::info);
  CHECK(checker.finish().violations.empty());
  // 10 + 5 (N10, as one line: sqrt(125)), 10 (N30 to X20), 25 (N40), 20 (N50).
  CHECK(channel.hli().dist_prog_start == Approx((std::sqrt(125.0) + 10 + 25 + 20) * 1e4).epsilon(1e-9));
}

TEST_CASE("DPS-3 machine file: reference_position per axis, 0 by default", "[config][DPS-3]") {
  const std::string axes =
      "axes:\n  - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002, "
      "reference_position: -12.5}\n  - {name: Z, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}\n";
  const MachineConfig m = parse_machine_config(YAML::Load(axes));
  CHECK(m.axes[0].reference_position == -12.5);
  CHECK(m.axes[1].reference_position == 0);
  CHECK_THROWS_WITH(parse_machine_config(YAML::Load(
                        "axes:\n  - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002, "
                        "reference_position: .nan}\n")),
                    Catch::Contains("reference_position"));
}
