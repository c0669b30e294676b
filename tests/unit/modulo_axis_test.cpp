// KRN-7 rotary and modulo axes: the machine file, the decoder (G90 the
// short way round, G91 several revolutions), the HLI's display within the
// modulo range, and where an axis first reaches a position (ISC-4).
#include <catch2/catch.hpp>

#include <yaml-cpp/yaml.h>

#include "axis_crossing.hpp"
#include "channel.hpp"
#include "config_error.hpp"
#include "decoder.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

MachineConfig with_c_axis(const std::string& c_axis_keys) {
  return parse_machine_config(YAML::Load(
      "axes:\n"
      "  - {name: X, v_max: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002}\n"
      "  - {name: C, v_max: 360, a_max: 3600, j_max: 72000, kv: 40, velocity_lag_s: 0.002" +
      c_axis_keys + "}\n"));
}

// Where the decoder leaves axis C after each motion block.
std::vector<double> c_after_each_block(const std::string& program) {
  const MachineConfig m = test::xyzc_machine();
  const DecodedProgram p = decode_program(program, m, std::vector<double>(m.axes.size(), 0.0));
  REQUIRE(!p.error);
  std::vector<double> c;
  for (const Block& b : p.blocks)
    if (b.has_motion) c.push_back(b.motion.end[3]);
  return c;
}

}  // namespace

TEST_CASE("KRN-7 the machine file: a modulo axis needs both limits, is A, B or C, has no software limits",
          "[modulo]") {
  const MachineConfig m = with_c_axis(", modulo_lower: 0, modulo_upper: 360");
  CHECK(m.axes[1].modulo);
  CHECK(m.axes[1].modulo_range() == 360);
  CHECK_FALSE(m.axes[0].modulo);
  CHECK_THROWS_WITH(with_c_axis(", modulo_upper: 360"), Catch::Contains("needs both modulo_lower and modulo_upper"));
  CHECK_THROWS_WITH(with_c_axis(", modulo_lower: 360, modulo_upper: 0"),
                    Catch::Contains("modulo_lower must be below modulo_upper"));
  CHECK_THROWS_WITH(with_c_axis(", modulo_lower: 0, modulo_upper: 360, swe_neg: -1, swe_pos: 1"),
                    Catch::Contains("no software limit switches"));
  CHECK_THROWS_WITH(parse_machine_config(YAML::Load("axes:\n  - {name: X, v_max: 250, a_max: 2000, j_max: 40000, "
                                                    "kv: 40, velocity_lag_s: 0.002, modulo_lower: 0, "
                                                    "modulo_upper: 360}\n")),
                    Catch::Contains("only the rotary axes A, B, C"));
}

TEST_CASE("KRN-7 positions within the modulo range", "[modulo]") {
  const AxisConfig c = test::xyzc_machine().axes[3];
  CHECK(c.in_modulo_range(0) == 0);
  CHECK(c.in_modulo_range(360) == 0);
  CHECK(c.in_modulo_range(450) == Approx(90));
  CHECK(c.in_modulo_range(-60) == Approx(300));
  CHECK(c.in_modulo_range(-720) == 0);
  CHECK(c.in_modulo_range(1e-14 - 360) < 360);  // never the upper limit itself
  const AxisConfig x = test::xyzc_machine().axes[0];
  CHECK(x.in_modulo_range(450) == 450);  // a linear axis as it is
}

TEST_CASE("KRN-7 decoder: G90 on a modulo axis goes the short way round, G91 turns as programmed", "[modulo]") {
  // 0 -> 300: -60 deg; -> 90 (shown 300 -> 90): +150; C450 is 90 again:
  // no motion block.
  CHECK(c_after_each_block("N10 G01 G90 C300 F10800\nN20 C90\nN30 C450\nM30\n") == std::vector<double>{-60, 90});
  // Exactly half a revolution: the positive way.
  CHECK(c_after_each_block("N10 G01 G90 C180 F10800\nM30\n") == std::vector<double>{180});
  CHECK(c_after_each_block("N10 G01 G90 C-90 F10800\nM30\n") == std::vector<double>{-90});
  // G91: several revolutions, either way.
  CHECK(c_after_each_block("N10 G01 G91 C1080 F10800\nN20 C-450\nM30\n") == std::vector<double>{1080, 630});
}

TEST_CASE("KRN-7 the HLI shows a modulo axis within its range, the drives get it continuous", "[modulo]") {
  const MachineConfig m = test::xyzc_machine();
  Channel channel(m, "N10 G01 G91 C450 F21600\nN20 M30\n");
  HliControl control;
  control.program_start.enable_w = control.program_start.command_w = true;
  for (int64_t k = 0; k < 20000 && !channel.finished(); ++k) {
    channel.step(k, control);
    control.program_start.command_w = false;
  }
  REQUIRE(channel.finished());
  CHECK(channel.setpoints()[3].position == Approx(450));
  CHECK(channel.hli().axis_position_r[3] == 900000);  // 90 deg in 1e-4 deg
}

TEST_CASE("ISC-4 KRN-7 where a modulo axis first reaches a position: the next time, at most a revolution",
          "[modulo][insert_stop]") {
  const MachineConfig m = test::xyzc_machine();
  auto c_move = [&](double from, double to) {
    Motion mo;
    mo.type = MotionType::linear;
    mo.start = {0, 0, 0, from};
    mo.end = {0, 0, 0, to};
    mo.feed = 10800;
    return mo;
  };
  // Up from 300: 90 comes after 150 deg; as a plain position 90 never.
  CHECK(covered_until_axis_reaches({c_move(300, 1000)}, 3, 90, m, true) == Approx(150));
  CHECK(covered_until_axis_reaches({c_move(300, 1000)}, 3, 90, m, false) == std::nullopt);
  // Down from 300: 90 after 210 deg; from 90 itself at once.
  CHECK(covered_until_axis_reaches({c_move(300, -500)}, 3, 90, m, true) == Approx(210));
  CHECK(covered_until_axis_reaches({c_move(90, 500)}, 3, 90, m, true) == Approx(0).margin(1e-9));
  // Over two blocks: down 60 (never there), then up.
  CHECK(covered_until_axis_reaches({c_move(0, -60), c_move(-60, 660)}, 3, 90, m, true) == Approx(210));
  // Not reached within the motion.
  CHECK(covered_until_axis_reaches({c_move(100, 400)}, 3, 90, m, true) == std::nullopt);
}
