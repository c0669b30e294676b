// KRN-1: path-related pre-output of M functions (P-CHAN-00070), which
// DDTG-7 case C builds on.
#include <catch2/catch.hpp>

#include "channel_runner.hpp"
#include "decoder.hpp"
#include "m_pre_output.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

std::vector<Block> prepared(const std::string& program, std::vector<Event>* warnings = nullptr) {
  const MachineConfig m = test::xyz_machine();
  DecodedProgram p = decode_program(program, m, {0, 0, 0});
  if (p.error) FAIL(p.error->message);
  std::vector<Event> seen;
  std::vector<Block> blocks = apply_m_pre_output(std::move(p.blocks), m, seen);
  if (warnings) *warnings = seen;
  else CHECK(seen.empty());
  return blocks;
}

// "N<nr> M<m>" for an M block, "N<nr> X<end>" (+ "'" for a continued part) for motion.
std::vector<std::string> outline(const std::vector<Block>& blocks) {
  std::vector<std::string> out;
  for (const Block& b : blocks) {
    std::string text = "N" + std::to_string(b.block_nr);
    if (b.has_motion) {
      const double x = b.motion.end[0];
      text += " X" + (x == static_cast<int>(x) ? std::to_string(static_cast<int>(x)) : std::to_string(x));
      if (b.continues_block) text += "'";
    }
    for (const MFunction& m : b.m_functions) text += " M" + std::to_string(m.nr);
    out.push_back(text);
  }
  return out;
}

}  // namespace

TEST_CASE("KRN-1 M function pre-output: the motion block where it goes out is split, the M function goes between",
          "[pre_output]") {
  // The example of P-CHAN-00070 (MVS_SVS, 25 mm): M11 goes out at X15, in N20.
  CHECK(outline(prepared("N01 V.G.M_FCT[11].PRE_OUTP_PATH = 25\nN10 G01 X10 G90 F5000\nN20 X20\nN30 X30\nN40 X40\n"
                         "N50 X80 M11\nN60 X0\nM30\n")) ==
        std::vector<std::string>{"N10 X10", "N20 X15", "N20 M11", "N20 X20'", "N30 X30", "N40 X40", "N50 X80",
                                 "N60 X0", "N0"});
  // Exactly on a block end: no split.
  CHECK(outline(prepared("V.G.M_FCT[11].PRE_OUTP_PATH = 10\nN10 G01 X10 F5000\nN20 X20\nN30 X30 M11\n")) ==
        std::vector<std::string>{"N10 X10", "N20 M11", "N20 X20", "N30 X30"});
  // Further back than the program goes: before its first motion, with a warning.
  std::vector<Event> warnings;
  CHECK(outline(prepared("V.G.M_FCT[11].PRE_OUTP_PATH = 100\nN10 G01 X10 F5000\nN20 X20 M11 M12\n", &warnings)) ==
        std::vector<std::string>{"N10 M11", "N10 X10", "N20 X20 M12"});
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].parameter == "P-CHAN-00070");
  CHECK(warnings[0].block_nr == 20);
  // Within 10 nm of an arc's end or start: no split (a sliver of an arc would be a full circle).
  CHECK(outline(prepared("V.G.M_FCT[7].PRE_OUTP_PATH = 0.0000001\nN10 G2 X20 Y0 I10 F5000\nN20 G1 X30 M7\n")) ==
        std::vector<std::string>{"N10 X20", "N20 M7", "N20 X30"});
  CHECK(outline(prepared("V.G.M_FCT[7].PRE_OUTP_PATH = 31.4159264\nN10 G2 X20 Y0 I10 F5000\nN20 G1 X30 M7\n")) ==
        std::vector<std::string>{"N10 M7", "N10 X20", "N20 X30"});
  // A block without motion: from where it stands; the line's own M functions stay on the first part.
  CHECK(outline(prepared("V.G.M_FCT[7].PRE_OUTP_PATH = 4\nN10 G01 X10 F5000 M3\nN20 M7\nN30 X20\n")) ==
        std::vector<std::string>{"N10 X6 M3", "N10 M7", "N10 X10'", "N30 X20"});
}

TEST_CASE("KRN-1 M function pre-output searches back at most 10 motion blocks (P-CHAN-00603)", "[pre_output]") {
  std::string program = "V.G.M_FCT[7].PRE_OUTP_PATH = 11.5\nG01 F5000\n";
  for (int i = 1; i <= 12; ++i) program += "N" + std::to_string(i) + " X" + std::to_string(i) + "\n";
  program += "N13 X13 M7\n";
  std::vector<Event> warnings;
  const auto blocks = outline(prepared(program, &warnings));
  CHECK(warnings.size() == 1);
  REQUIRE(blocks.size() == 14);
  CHECK(blocks[2] == "N3 M7");  // before N3, the 10th block back from N13 (11.5 mm would be in N2)
}

TEST_CASE("KRN-1 a pre-output M function stops the path where it goes out, until acknowledged", "[pre_output]") {
  const MachineConfig m = test::xyz_machine();
  Channel channel(m, "V.G.M_FCT[11].PRE_OUTP_PATH = 25\nN10 G01 X10 F3000\nN20 X20\nN30 X30\nN40 X40\nN50 X80 M11\n");
  double x_at_output = -1;
  int waited = 0;
  test::run_program(channel, nullptr, [&](int64_t, const HliState& s, HliControl& c) {
    c.m_function_ack.enable_w = true;
    if (s.m_function_request_r && s.m_function_nr_r == 11 && x_at_output < 0) x_at_output = channel.setpoints()[0].position;
    c.m_function_ack.command_w = s.m_function_request_r && ++waited > 50;
    if (!s.m_function_request_r) waited = 0;
  });
  CHECK(x_at_output == Approx(15).margin(1e-9));
  CHECK(channel.setpoints()[0].position == Approx(80).margin(1e-9));
}
