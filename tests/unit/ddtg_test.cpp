// DDTG-1 .. DDTG-4, DDTG-6: delete distance to go on the channel, cycle by
// cycle as the rig runs it; every run goes through the offline checker.
#include <catch2/catch.hpp>

#include <cmath>

#include "channel_runner.hpp"
#include "decoder.hpp"
#include "short_cut_target.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;
using hil::test::run_program;

namespace {

struct Sample {
  int64_t cycle;
  double x, y, v;
  bool active;
  int64_t block_nr;
};

// Runs `program`; the PLC raises delete_distance_to_go at each cycle in
// `edges` and holds it `hold` cycles (long enough for the stop, unless a
// test clears it early).
std::vector<Sample> run_with_ddtg(const std::string& program, std::vector<int64_t> edges, int64_t hold,
                                  std::vector<Event>* events = nullptr, uint32_t activation = 0) {
  const MachineConfig m = test::xyz_machine();
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  std::vector<Sample> samples;
  run_program(channel, &checker, [&](int64_t k, const HliState& s, HliControl& c) {
    samples.push_back({k, channel.setpoints()[0].position, channel.setpoints()[1].position, s.path_velocity,
                       s.delete_distance_to_go_active_r, s.block_nr_r});
    bool command = false;
    for (int64_t edge : edges) command = command || (k >= edge && k < edge + hold);
    c.delete_distance_to_go = {command, true};
    c.delete_distance_to_go_activation = {activation, activation != 0};
  });
  for (const auto& v : checker.finish().violations)
    FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value << " > " << v.limit << " at " << v.time_s);
  const HliState& end = channel.hli();
  samples.push_back({end.cycle, channel.setpoints()[0].position, channel.setpoints()[1].position, end.path_velocity,
                     end.delete_distance_to_go_active_r, end.block_nr_r});
  if (events) *events = channel.take_events();
  return samples;
}

// Distance of (x, y) from the line through a and b.
double off_line(double x, double y, double ax, double ay, double bx, double by) {
  return std::abs((bx - ax) * (y - ay) - (by - ay) * (x - ax)) / std::hypot(bx - ax, by - ay);
}

const Sample* first_active(const std::vector<Sample>& samples) {
  for (const Sample& s : samples)
    if (s.active) return &s;
  return nullptr;
}

}  // namespace

TEST_CASE("DDTG-1 DDTG-4 delete distance to go: stop, then a linear short cut to the end of the next block",
          "[ddtg]") {
  // TF5200_delete_distance_to_go.txt, 2.1 (Fig. 2).
  const auto samples = run_with_ddtg("N05 G0 X0 Y0\nN10 G1 X80 F500\nN20 G1 Y60\nN30 G1 X60 Y80\nN40 M30\n",
                                     {3000}, 400);
  const Sample* cut = first_active(samples);
  REQUIRE(cut != nullptr);
  const double stop_x = cut->x;
  CHECK(stop_x > 20);
  CHECK(stop_x < 30);  // the rest of N10 (to X80) is dropped
  CHECK(cut->y == 0);
  double v_max_on_cut = 0;
  bool was_active = false, ended = false;
  for (const Sample& s : samples) {
    if (s.cycle < 3000) CHECK_FALSE(s.active);
    if (s.active) {
      was_active = true;
      CHECK_FALSE(ended);  // one short cut, then never again
      CHECK(s.block_nr == 20);  // DDTG-4: block_nr_r follows the interpolator
      CHECK(off_line(s.x, s.y, stop_x, 0, 80, 60) < 1e-9);
      v_max_on_cut = std::max(v_max_on_cut, s.v);
    } else if (was_active) {
      ended = true;
    }
  }
  CHECK(v_max_on_cut == Approx(500.0 / 60).epsilon(1e-9));  // DDTG-2: G01 at the next block's feed
  // After the short cut: N30 from (80, 60) to (60, 80).
  CHECK(samples.back().x == Approx(60).margin(1e-9));
  CHECK(samples.back().y == Approx(80).margin(1e-9));
  CHECK_FALSE(samples.back().active);
}

TEST_CASE("DDTG-2 the short cut runs in G00 after a G00 block, and linear out of an arc", "[ddtg]") {
  SECTION("G00") {
    const auto samples = run_with_ddtg("N10 G0 X200\nN20 G1 Y60 F500\nN30 X0\nM30\n", {150}, 300);
    const Sample* cut = first_active(samples);
    REQUIRE(cut != nullptr);
    double v = 0;
    for (const Sample& s : samples)
      if (s.active) {
        v = std::max(v, s.v);
        CHECK(off_line(s.x, s.y, cut->x, 0, 200, 60) < 1e-9);
      }
    CHECK(v > 100);  // far above F500 (8.3 mm/s): rapid
  }
  SECTION("interrupted inside G03") {
    // A line, a tangent quarter circle (centre 50, 20), a line.
    const auto samples =
        run_with_ddtg("N10 G01 X50 F3000\nN20 G03 X70 Y20 I0 J20\nN30 G01 Y60\nN40 X0\nM30\n", {1250}, 300);
    const Sample* cut = first_active(samples);
    REQUIRE(cut != nullptr);
    CHECK(cut->x > 50);  // stopped on the arc
    CHECK(cut->x < 70);
    for (const Sample& s : samples)
      if (s.active) {
        CHECK(off_line(s.x, s.y, cut->x, cut->y, 70, 60) < 1e-9);  // a line, not the arc
        CHECK(s.block_nr == 30);
      }
    CHECK(samples.back().x == Approx(0).margin(1e-9));
    CHECK(samples.back().y == Approx(60).margin(1e-9));
  }
}

TEST_CASE("DDTG-3 cleared before the short cut starts, the original contour goes on; a new edge on the short "
          "cut goes to the end of the block after it",
          "[ddtg]") {
  const char* program = "N10 G1 X80 F3000\nN20 Y60\nN30 X60 Y80\nN40 X0\nM30\n";
  SECTION("cleared while stopping") {
    const auto samples = run_with_ddtg(program, {500}, 20);  // stopping from 50 mm/s takes ~100 cycles
    CHECK(first_active(samples) == nullptr);
    // N10 ran to its end: the path stops at the corner (between two cycles).
    double closest = 1e9;
    for (const Sample& s : samples) closest = std::min(closest, std::hypot(s.x - 80, s.y));
    CHECK(closest < 1e-5);
    CHECK(samples.back().x == Approx(0).margin(1e-9));
    CHECK(samples.back().y == Approx(80).margin(1e-9));
  }
  SECTION("a second edge on the short cut") {
    const auto samples = run_with_ddtg(program, {500, 1300}, 150);
    const Sample* cut = first_active(samples);
    REQUIRE(cut != nullptr);
    bool second = false;
    double second_x = 0, second_y = 0;
    for (const Sample& s : samples) {
      if (!s.active) continue;
      if (s.block_nr == 30 && !second) {  // DDTG-4: still active on the shortened short cut
        second = true;
        second_x = s.x;
        second_y = s.y;
      }
      if (second) CHECK(off_line(s.x, s.y, second_x, second_y, 60, 80) < 1e-9);
    }
    CHECK(second);
    CHECK(second_x < 80);  // it left the first short cut before (80, 60)
    CHECK(samples.back().x == Approx(0).margin(1e-9));
    CHECK(samples.back().y == Approx(80).margin(1e-9));
  }
}

TEST_CASE("DDTG-6 delete distance to go in the last motion block: ends at the stop position, warning 50810",
          "[ddtg]") {
  std::vector<Event> events;
  const auto samples = run_with_ddtg("N10 G1 X80 F3000\nN20 M30\n", {500}, 200, &events);
  CHECK(first_active(samples) == nullptr);
  CHECK(samples.back().x > 20);
  CHECK(samples.back().x < 40);
  CHECK(samples.back().v == 0);
  bool warned = false;
  for (const Event& e : events) warned = warned || (e.id == 50810 && e.severity == Severity::warning);
  CHECK(warned);
}

TEST_CASE("DDTG-5 with an activation mask the short cut goes to the first valid #DEL DIST2GO marker", "[ddtg]") {
  // The markers of TF5200_delete_distance_to_go.txt 2.2 on a short contour.
  const std::string program =
      "N010 G1 X100 F3000\nN020 Y10\nN030 X110\n"
      "N041 #DEL DIST2GO\nN050 Y20\nN051 #DEL DIST2GO [END='16#01']\nN060 X150\n"
      "N061 #DEL DIST2GO [END=2]\nN070 Y60\nN071 #DEL DIST2GO [END='16#0105']\nN080 X200\n"
      "N081 #DEL DIST2GO [END=8]\nN090 Y100\nM30\n";
  struct Case {
    uint32_t activation;
    double x, y;  // where the short cut goes
    int64_t block_nr;
  };
  for (const Case& c : {Case{2, 150, 20, 60}, Case{4, 150, 60, 70}, Case{0x100, 150, 60, 70}, Case{8, 200, 60, 80},
                        Case{1, 110, 10, 30}, Case{0, 100, 10, 20}}) {
    INFO("activation " << c.activation);
    const auto samples = run_with_ddtg(program, {500}, 300, nullptr, c.activation);
    const Sample* cut = first_active(samples);
    REQUIRE(cut != nullptr);
    CHECK(cut->block_nr == c.block_nr);
    const Sample* last = cut;
    for (const Sample& s : samples)
      if (s.active) {
        CHECK(off_line(s.x, s.y, cut->x, cut->y, c.x, c.y) < 1e-9);
        last = &s;
      }
    CHECK(std::hypot(last->x - c.x, last->y - c.y) < 1.0);  // arrived (the next block starts there)
    CHECK(samples.back().x == Approx(200).margin(1e-9));
    CHECK(samples.back().y == Approx(100).margin(1e-9));
  }
  std::vector<Event> events;  // no marker valid for 0x10: DDTG-6
  const auto samples = run_with_ddtg(program, {500}, 300, &events, 0x10);
  CHECK(first_active(samples) == nullptr);
  CHECK(samples.back().x < 100);
  bool warned = false;
  for (const Event& e : events) warned = warned || e.id == 50810;
  CHECK(warned);
}

TEST_CASE("DDTG-9 with G91 the blocks after the short cut keep their programmed end points", "[ddtg]") {
  // TF5200_delete_distance_to_go.txt 2.6: no contour offset.
  const auto samples =
      run_with_ddtg("N00 G90 G0 X0 Y0\nN10 G1 G91 X100 F3000\nN20 G91 Y100\nN30 G91 X-10 Y10 M30\n", {600}, 300);
  const Sample* cut = first_active(samples);
  REQUIRE(cut != nullptr);
  CHECK(cut->x < 50);
  for (const Sample& s : samples)
    if (s.active) CHECK(off_line(s.x, s.y, cut->x, 0, 100, 100) < 1e-9);  // to N20's programmed end
  CHECK(samples.back().x == Approx(90).margin(1e-9));
  CHECK(samples.back().y == Approx(110).margin(1e-9));
}

namespace {

struct SyncSample {
  int64_t cycle;
  double x, y, v;
  bool active, m_request;
  int32_t m_nr;
};

// Runs `program`, acknowledging each M function `ack_after` cycles after
// it is output; optionally with one delete distance to go at `ddtg_at`.
std::vector<SyncSample> run_with_m_functions(const std::string& program, int ack_after, int64_t ddtg_at = -1) {
  const MachineConfig m = test::xyz_machine();
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  std::vector<SyncSample> samples;
  int waited = 0;
  run_program(channel, &checker, [&](int64_t k, const HliState& s, HliControl& c) {
    samples.push_back({k, channel.setpoints()[0].position, channel.setpoints()[1].position, s.path_velocity,
                       s.delete_distance_to_go_active_r, s.m_function_request_r, s.m_function_nr_r});
    c.m_function_ack.enable_w = true;
    if (c.m_function_ack.command_w) c.m_function_ack.command_w = false;
    else if (s.m_function_request_r && ++waited >= ack_after) c.m_function_ack.command_w = true, waited = 0;
    c.delete_distance_to_go = {ddtg_at >= 0 && k >= ddtg_at && !s.delete_distance_to_go_active_r && k < ddtg_at + 400,
                               true};
  });
  for (const auto& v : checker.finish().violations)
    FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value << " > " << v.limit << " at " << v.time_s);
  samples.push_back({channel.hli().cycle, channel.setpoints()[0].position, channel.setpoints()[1].position, 0,
                     false, false, 0});
  return samples;
}

}  // namespace

TEST_CASE("KRN-1 M functions (MVS_SVS) and #TIME: the path stands still until acknowledged, then dwells",
          "[ddtg]") {
  const auto samples = run_with_m_functions("N10 G1 X50 F3000\nN20 M48\nN30 #TIME 0.5\nN40 X100 M7\nM30\n", 100);
  int64_t m48_from = -1, m48_to = -1, m7_from = -1, moving_again = -1;
  for (const SyncSample& s : samples) {
    if (s.m_request && s.m_nr == 48) {
      if (m48_from < 0) m48_from = s.cycle;
      m48_to = s.cycle;
      CHECK(s.x == Approx(50).margin(1e-9));  // at rest on N10's end, before N40's motion
      CHECK(s.v == 0);
    }
    if (s.m_request && s.m_nr == 7) {
      if (m7_from < 0) m7_from = s.cycle;
      CHECK(s.x == Approx(50).margin(1e-9));
    }
    if (m7_from >= 0 && moving_again < 0 && s.x > 50 + 1e-9) moving_again = s.cycle;
  }
  REQUIRE(m48_from >= 0);
  CHECK(m48_to - m48_from + 1 == 100);  // output until the PLC acknowledged it
  REQUIRE(m7_from >= 0);
  CHECK(m7_from - m48_to >= 500);       // the dwell of 0.5 s between them
  CHECK(m7_from - m48_to <= 502);
  CHECK(moving_again > m7_from + 99);   // N40 moves only after M7 was acknowledged
  CHECK(samples.back().x == Approx(100).margin(1e-9));
}

TEST_CASE("DDTG-7 commands in the deleted contour run at the interruption point, before the short cut",
          "[ddtg]") {
  // TF5200_delete_distance_to_go.txt 4.5 (a shorter dwell), DDTG in N010.
  const auto samples = run_with_m_functions(
      "N005 X0 Y0 Z0 F3000\nN010 X100\nN015 M48\nN016 P1=1\nN017 #TIME 1\nN020 Y100 M7\nN030 X90 Y110\nN040 M30\n",
      20, 500);
  int64_t m48 = -1, m7 = -1, cut = -1;
  double stop_x = -1;
  for (const SyncSample& s : samples) {
    if (s.m_request && s.m_nr == 48 && m48 < 0) {
      m48 = s.cycle;
      stop_x = s.x;
      CHECK(s.x < 60);  // at the interruption point in N010, not at its end
      CHECK(s.y == 0);
      CHECK(s.active);  // the short cut is the active block; it moves once these are done
    }
    if (s.m_request && s.m_nr == 7 && m7 < 0) {
      m7 = s.cycle;  // case A: the M function of the target's line, also at the interruption point
      CHECK(s.x == stop_x);
      CHECK(s.y == 0);
    }
    if (s.active && s.y > 1e-9 && cut < 0) cut = s.cycle;
  }
  REQUIRE(m48 >= 0);
  REQUIRE(m7 > m48);
  CHECK(m7 - m48 >= 20 + 1000);  // acknowledged after 20 cycles, then #TIME 1
  REQUIRE(cut > m7);             // the short cut moves after all of it
  CHECK(samples.back().x == Approx(90).margin(1e-9));
  CHECK(samples.back().y == Approx(110).margin(1e-9));
}

TEST_CASE("DDTG-7 case C: an M function preset into the deleted contour goes out at the interruption point",
          "[ddtg]") {
  // TF5200_delete_distance_to_go.txt 2.4, case C: M7 of N220 goes out 20 mm
  // before N220, inside N210 (at Y50); N210 is the short cut's target.
  const std::string program =
      "N100 V.G.M_FCT[7].PRE_OUTP_PATH = 20\nN190 G1 X0 Y0 F3000\nN200 X100\nN210 Y70\nN220 M7\nN230 X0\nM30\n";
  const auto plain = run_with_m_functions(program, 20);
  bool preset = false;
  for (const SyncSample& s : plain)
    if (s.m_request && s.m_nr == 7) preset = preset || (s.x == Approx(100).margin(1e-9) && s.y == Approx(50).margin(1e-9));
  CHECK(preset);  // without delete distance to go: at Y50 in N210
  const auto samples = run_with_m_functions(program, 20, 500);
  int64_t m7 = -1, cut = -1;
  for (const SyncSample& s : samples) {
    if (s.m_request && s.m_nr == 7 && m7 < 0) {
      m7 = s.cycle;
      CHECK(s.x < 60);  // at the interruption point in N200
      CHECK(s.y == 0);
      CHECK(s.active);
    }
    if (s.active && s.y > 1e-9 && cut < 0) cut = s.cycle;
  }
  REQUIRE(m7 >= 0);
  REQUIRE(cut > m7);  // the short cut, to N210's end point (not to the split point), moves after it
  const SyncSample* before_n230 = nullptr;
  for (const SyncSample& s : samples)
    if (s.active) before_n230 = &s;
  REQUIRE(before_n230 != nullptr);
  CHECK(before_n230->y > 69);
  CHECK(samples.back().x == Approx(0).margin(1e-9));
  CHECK(samples.back().y == Approx(70).margin(1e-9));
}

TEST_CASE("DDTG-5 DDTG-6 short-cut targets: next motion block, or before the first valid marker", "[ddtg]") {
  const DecodedProgram p = decode_program(
      "N10 G1 X10 F1000\nN20 Y10\nN21 #DEL DIST2GO\nN22 M8\nN30 X20\nN31 #DEL DIST2GO [END=6]\nN40 Y20\nM30\n",
      test::xyz_machine(), {0, 0, 0});
  REQUIRE_FALSE(p.error);
  auto nr = [&](const ShortCutTarget& t) { return t.target ? p.blocks[*t.target].block_nr : -1; };
  CHECK(nr(short_cut_target(p.blocks, 0, 0)) == 20);   // DDTG-1: the next motion block
  CHECK(nr(short_cut_target(p.blocks, 0, 1)) == 20);   // N21 (END=1): the last motion block before it
  CHECK(nr(short_cut_target(p.blocks, 0, 4)) == 30);   // N31 (END=6 & 4)
  CHECK(nr(short_cut_target(p.blocks, 1, 1)) == 20);   // interrupted in N20, marker right after: N20 itself
  CHECK(nr(short_cut_target(p.blocks, 0, 8)) == -1);   // no valid marker: DDTG-6
  CHECK(nr(short_cut_target(p.blocks, 6, 0)) == -1);   // in the last motion block: DDTG-6
}

TEST_CASE("DDTG-11 delete distance to go needs P-STUP-00033 > 0", "[ddtg]") {
  MachineConfig m = test::xyz_machine();
  REQUIRE(m.fb_storage_size > 0);  // the shipped machine has it
  m.fb_storage_size = 0;
  Channel channel(m, "N10 G1 X80 F3000\nN20 Y60\nM30\n");
  bool warned = false, active = false;
  run_program(channel, nullptr, [&](int64_t k, const HliState& s, HliControl& c) {
    c.delete_distance_to_go = {k >= 500 && k < 700, true};
    active = active || s.delete_distance_to_go_active_r || s.delete_distance_to_go.state_r;
    for (const Event& e : channel.take_events())
      warned = warned || (e.parameter == "P-STUP-00033" && e.severity == Severity::warning);
  });
  CHECK(warned);
  CHECK_FALSE(active);
  CHECK(channel.setpoints()[0].position == Approx(80).margin(1e-9));  // the contour ran as programmed
  CHECK(channel.setpoints()[1].position == Approx(60).margin(1e-9));
}

TEST_CASE("DDTG-10 a backward request on a short cut holds it with warning 50729 until withdrawn", "[ddtg]") {
  // TF5200_delete_distance_to_go.txt 2.7: the short cut is not stored for
  // backward motion; the request holds it with the warning the text names.
  const MachineConfig m = test::xyz_machine();
  Channel channel(m, "N10 G1 X80 F3000\nN20 Y60\nN30 X0\nM30\n");
  logger::LimitChecker checker(m);
  int64_t cut = -1, held_from = -1;
  double held_x = 0, held_y = 0;
  bool w50729 = false, moved_while_held = false;
  run_program(channel, &checker, [&](int64_t k, const HliState& s, HliControl& c) {
    c.delete_distance_to_go = {k >= 500 && cut < 0, true};
    if (s.delete_distance_to_go_active_r && cut < 0) cut = k;
    const bool backward = cut >= 0 && k >= cut + 300 && k < cut + 1300;
    c.backward_motion = {backward, true};
    for (const Event& e : channel.take_events()) w50729 = w50729 || (e.id == 50729 && e.severity == Severity::warning);
    if (cut >= 0 && k >= cut + 300 && s.path_velocity == 0 && held_from < 0) {
      held_from = k;
      held_x = channel.setpoints()[0].position;
      held_y = channel.setpoints()[1].position;
    }
    if (held_from >= 0 && k < cut + 1301)
      moved_while_held = moved_while_held || channel.setpoints()[0].position != held_x ||
                         channel.setpoints()[1].position != held_y;
    if (held_from >= 0 && k < cut + 1301) CHECK(s.delete_distance_to_go_active_r);  // still on the short cut
    CHECK_FALSE(s.backward_motion.state_r);
  });
  CHECK(w50729);
  REQUIRE(held_from > 0);
  CHECK_FALSE(moved_while_held);
  CHECK(channel.setpoints()[0].position == Approx(0).margin(1e-9));  // resumed after withdrawal, to the end
  CHECK(channel.setpoints()[1].position == Approx(60).margin(1e-9));
  for (const auto& v : checker.finish().violations) FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value);
}

TEST_CASE("DDTG-8 short-cut targets: #CS must not be skipped, #CHANNEL INIT ends the search", "[ddtg]") {
  const DecodedProgram p = decode_program(
      "N10 G1 X10 F1000\nN20 Y10\nN21 #DEL DIST2GO\nN22 #CHANNEL INIT [CMDPOS]\nN30 X20\nN31 #CS ON [1,2,0]\n"
      "N40 Y20\nN41 #DEL DIST2GO [END=2]\nN50 #CS OFF\nN60 X0\nM30\n",
      test::xyz_machine(), {0, 0, 0});
  REQUIRE_FALSE(p.error);
  auto nr = [&](std::optional<size_t> i) { return i ? p.blocks[*i].block_nr : -1; };
  const ShortCutTarget single = short_cut_target(p.blocks, 0, 0);
  CHECK(nr(single.target) == 20);  // the next motion block, before any restriction
  CHECK_FALSE(single.not_skippable);
  const ShortCutTarget init = short_cut_target(p.blocks, 0, 2);  // searching for END=2 meets N22
  CHECK(nr(init.channel_initialisation) == 22);
  CHECK(nr(init.target) == 20);  // the last motion block before N22
  const ShortCutTarget right_before = short_cut_target(p.blocks, 1, 2);  // interrupted in N20
  CHECK(nr(right_before.target) == 20);
  const ShortCutTarget cs = short_cut_target(p.blocks, 4, 2);  // interrupted in N30: N31 #CS lies before N41
  CHECK(nr(cs.not_skippable) == 31);
  CHECK_FALSE(cs.target);
  CHECK(nr(short_cut_target(p.blocks, 4, 0).not_skippable) == 31);  // also before the next motion block
  CHECK(nr(short_cut_target(p.blocks, 6, 2).target) == 40);          // after it: N41 is reached first
}

TEST_CASE("DDTG-8 skipping #CS is error 51016: the path stays at the stop position, the program is aborted",
          "[ddtg]") {
  std::vector<Event> events;
  const auto samples = run_with_ddtg(
      "N10 G1 X80 F3000\nN15 #CS ON [0,0,0,0,0,90]\nN20 X10 Y60\nN25 #CS OFF\nN30 X0\nM30\n", {500}, 300, &events);
  CHECK(first_active(samples) == nullptr);
  const Sample& end = samples.back();
  CHECK(end.x > 20);
  CHECK(end.x < 60);  // stopped in N10
  CHECK(end.y == 0);
  CHECK(end.v == 0);
  const Event* refused = nullptr;
  for (const Event& e : events)
    if (e.id == 51016) refused = &e;
  REQUIRE(refused != nullptr);
  CHECK(refused->severity == Severity::error);
  CHECK(refused->nc_line == 2);  // the #CS line
  CHECK(refused->block_nr == 15);
}

TEST_CASE("DDTG-8 #CHANNEL INIT, G74 homing and G100 measuring end the search for the end marker: short cut to "
          "before them, warning 51036",
          "[ddtg]") {
  // TF5200_delete_distance_to_go.txt 2.5: "channel initialisation is
  // required with: #CHANNEL INIT ... Homing G74, Measuring functions
  // G100"; the program goes on from there.
  for (const std::string command : {"#CHANNEL INIT [CMDPOS]", "G74 X1", "G100 X40 Y30"}) {
    CAPTURE(command);
    std::vector<Event> events;
    const auto samples = run_with_ddtg(
        "N10 G1 X80 F3000\nN20 Y60\nN25 " + command + "\nN30 X0\nN31 #DEL DIST2GO\nN40 Y0\nM30\n", {500}, 300,
        &events, 1);
    const Sample* cut = first_active(samples);
    REQUIRE(cut != nullptr);
    CHECK(cut->block_nr == 20);
    for (const Sample& s : samples)
      if (s.active) CHECK(off_line(s.x, s.y, cut->x, cut->y, 80, 60) < 1e-9);  // to N20's end, not beyond N25
    bool went_on = false;
    for (const Sample& s : samples) went_on = went_on || (s.block_nr >= 25 && !s.active && s.x < 40);
    CHECK(went_on);  // N25 and N30 run as programmed after the short cut
    CHECK(samples.back().x == Approx(0).margin(1e-9));
    CHECK(samples.back().y == Approx(0).margin(1e-9));
    const Event* warned = nullptr;
    for (const Event& e : events)
      if (e.id == 51036) warned = &e;
    REQUIRE(warned != nullptr);
    CHECK(warned->severity == Severity::warning);
    CHECK(warned->block_nr == 25);
    const DecodedProgram p = decode_program("N10 G1 X80 F3000\nN25 " + command + "\nM30\n", test::xyz_machine(), {0, 0, 0});
    REQUIRE_FALSE(p.error);
    CHECK(p.blocks[1].short_cut_restriction == ShortCutRestriction::channel_initialisation);
    CHECK(p.blocks[1].stops_path());  // the path stands still before it
  }
}
