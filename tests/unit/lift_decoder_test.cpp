// LIFT-1, LIFT-5, LIFT-6, DDTG-8: the lift function in the decoder
// (TF5200_lift_function.txt 2.1.3, 2.2.3, 2.3, 2.4, 3), with the text's
// example programs.
#include <catch2/catch.hpp>

#include "decoder.hpp"
#include "short_cut_target.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

constexpr int z_axis = 2;

DecodedProgram decode(const std::string& text, const MachineConfig& machine = test::xyz_lift_machine()) {
  return decode_program(text, machine, {0, 0, 0});
}

DecodedProgram decoded(const std::string& text, const MachineConfig& machine = test::xyz_lift_machine()) {
  DecodedProgram p = decode(text, machine);
  INFO(text);
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  return p;
}

const Block& block_nr(const DecodedProgram& p, int64_t nr) {
  for (const Block& b : p.blocks)
    if (b.block_nr == nr) return b;
  FAIL("no block N" << nr);
  return p.blocks.front();
}

void check_lift_start(const Block& b, double pos, double pos_limit, bool down = false) {
  INFO("N" << b.block_nr);
  REQUIRE(b.lift_start);
  CHECK(b.lift_start->axis == z_axis);
  CHECK(b.lift_start->down == down);
  CHECK(b.lift_start->pos == Approx(pos));
  CHECK(b.lift_start->pos_limit == Approx(pos_limit));
  CHECK(b.short_cut_restriction == ShortCutRestriction::not_skippable);  // DDTG-8
}

// Z at the start and the end of a motion block.
void check_z(const Block& b, double z) {
  INFO("N" << b.block_nr);
  REQUIRE(b.has_motion);
  CHECK(b.motion.start[z_axis] == Approx(z));
  CHECK(b.motion.end[z_axis] == Approx(z));
}

// Refused at `line` (its N number `nr`) with `part` in the message, TF5200
// error `id`, the `kept` blocks before it decoded (KRN-2).
void check_refused(const std::string& program, int64_t line, int64_t nr, const std::string& part, size_t kept,
                   int32_t id = 0, const MachineConfig& machine = test::xyz_lift_machine()) {
  INFO(program);
  const DecodedProgram p = decode(program, machine);
  REQUIRE(p.error);
  CHECK(p.error->severity == Severity::error);
  CHECK(p.error->nc_line == line);
  CHECK(p.error->block_nr == nr);
  CHECK(p.error->id == id);
  CHECK_THAT(p.error->message, Catch::Contains(part));
  CHECK(p.blocks.size() == kept);
}

}  // namespace

TEST_CASE("LIFT-1 cross-block lifting N10..N90: the range's motions keep Z, after LIFT_END Z stands at POS",
          "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "N10 G01 X10 Y20 Z30 F1000 ;Cut with laser\n"
      "N20 M5                    ;Laser off\n"
      "N30 Z[LIFT_START POS=12 POS_LIMIT=100] ;Lift Z axis\n"
      "N31 G01 X20 Y20\n"
      "N40 G02 X30 Y30 I0 J10\n"
      "N50 G03 X40 Y40 I10 J0\n"
      "N60 G01 X50 Y40\n"
      "N70 Z[LIFT_END]           ;Absolutely lower Z axis to target 12 mm\n"
      "N80 M4                    ;Laser on\n"
      "N90 X20 Y20\n");
  REQUIRE(p.blocks.size() == 10);
  const Block& start = block_nr(p, 30);
  check_lift_start(start, 12, 100);
  CHECK_FALSE(start.has_motion);
  CHECK_FALSE(start.lift_end);
  for (int64_t nr : {31, 40, 50, 60}) {
    check_z(block_nr(p, nr), 30);
    CHECK_FALSE(block_nr(p, nr).lift_start);
    CHECK_FALSE(block_nr(p, nr).lift_end);
    CHECK(block_nr(p, nr).short_cut_restriction == ShortCutRestriction::none);
  }
  const Block& end = block_nr(p, 70);
  CHECK(end.lift_end);
  CHECK_FALSE(end.lift_start);
  CHECK_FALSE(end.has_motion);
  CHECK(end.short_cut_restriction == ShortCutRestriction::not_skippable);
  CHECK_FALSE(block_nr(p, 80).lift_end);
  const Block& after = block_nr(p, 90);
  CHECK(after.motion.start == std::vector<double>{50, 40, 12});
  CHECK(after.motion.end == std::vector<double>{20, 20, 12});
}

TEST_CASE("LIFT-1 alternative programming: LIFT_START and LIFT_END on the range's first and last motion lines",
          "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "N110 X10 Y20 Z30 F1000\n"
      "N140 G01 X20 Y30 Z[LIFT_START POS=12 POS_LIMIT=100]\n"
      "N150 G01 X30 Y40 Z[LIFT_END]\n"
      "N170 X100\n");
  REQUIRE(p.blocks.size() == 4);
  check_lift_start(p.blocks[1], 12, 100);
  CHECK_FALSE(p.blocks[1].lift_end);
  CHECK(p.blocks[1].motion.start == std::vector<double>{10, 20, 30});
  CHECK(p.blocks[1].motion.end == std::vector<double>{20, 30, 30});
  CHECK(p.blocks[2].lift_end);
  CHECK_FALSE(p.blocks[2].lift_start);
  CHECK(p.blocks[2].short_cut_restriction == ShortCutRestriction::not_skippable);
  check_z(p.blocks[2], 30);
  CHECK(p.blocks[3].motion.start == std::vector<double>{30, 40, 12});
  CHECK(p.blocks[3].motion.end == std::vector<double>{100, 40, 12});
}

TEST_CASE("LIFT-1 single-row lifting Fig. 11 N200..N280: Z[LIFT ..] begins and ends the range in its block",
          "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "; single-row programming\n"
      "N200 G01 Z40 F2000\n"
      "N240 X10 Y5 Z[LIFT POS=30 POS_LIMIT=300]\n"
      "N250 X20 Y10 Z[LIFT POS=20 POS_LIMIT=300]\n"
      "N260 X30 Y15 Z[LIFT POS=25 POS_LIMIT=300]\n"
      "N270 X40 Y20 Z[LIFT POS=30 POS_LIMIT=300]\n"
      "N280 X50 Y25 z [ lift pos = 30 pos_limit = 300 ]\n"
      "N290 X0\n");
  REQUIRE(p.blocks.size() == 7);
  const double pos[] = {30, 20, 25, 30, 30};
  double z = 40;
  for (size_t k = 0; k < 5; ++k) {
    const Block& b = p.blocks[k + 1];
    check_lift_start(b, pos[k], 300);
    CHECK(b.lift_end);
    check_z(b, z);  // where the previous row's lift landed
    z = pos[k];
  }
  check_z(p.blocks[6], 30);
  // Without a motion it is an error; a motion line whose axes do not move has none.
  check_refused("N10 G01 X1 F100\nN20 Z[LIFT POS=30 POS_LIMIT=300]\n", 2, 20, "Z[LIFT] needs a motion in its block", 1);
  check_refused("N10 G01 X1 F100\nN20 X1 Z[LIFT POS_LIMIT=300]\n", 2, 20, "Z[LIFT] needs a motion", 1);
}

TEST_CASE("LIFT-1 LIFT-5 POS greater than POS_LIMIT (special case 1): the decoder keeps both as programmed",
          "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "N10 G01 Z10 F1000\n"
      "N20 Z[LIFT_START POS=40 POS_LIMIT=30]\n"
      "N30 X10\n"
      "N40 X20\n"
      "N50 X35\n"
      "N60 Z[LIFT_END]\n"
      "N70 Y5\n");
  check_lift_start(block_nr(p, 20), 40, 30);
  for (int64_t nr : {30, 40, 50}) check_z(block_nr(p, nr), 10);
  CHECK(block_nr(p, 60).lift_end);
  check_z(block_nr(p, 70), 40);
}

TEST_CASE("LIFT-1 POS defaults to where Z stands; G91 is relative for this command only; DOWN", "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "N10 G01 Z10 F1000\n"
      "N20 Z[LIFT_START POS_LIMIT=30]\n"
      "N30 X10\n"
      "N40 Z[LIFT_END]\n"
      "N50 Z[LIFT_START DOWN G91 POS=5 POS_LIMIT=-3]\n"
      "N60 X20\n"
      "N70 Z[LIFT_END]\n"
      "N80 Y5\n"
      "N90 G91 X1\n"  // modal G91 does not make the lift's values relative: G90 is their default
      "N100 Z[LIFT_START POS=12 POS_LIMIT=20]\n"
      "N110 X1\n"
      "N120 Z[LIFT_END]\n"
      "N130 G90 Z[LIFT_START G90 POS_LIMIT=3]\n");
  check_lift_start(block_nr(p, 20), 10, 30);
  check_z(block_nr(p, 30), 10);
  check_lift_start(block_nr(p, 50), 15, 7, true);
  check_z(block_nr(p, 60), 10);
  check_z(block_nr(p, 80), 15);
  CHECK(block_nr(p, 80).motion.end[1] == Approx(5));  // G90 still modal
  check_lift_start(block_nr(p, 100), 12, 20);
  check_z(block_nr(p, 110), 15);
  CHECK(block_nr(p, 110).motion.end[0] == Approx(22));
  check_lift_start(block_nr(p, 130), 12, 3);
  // P parameters in the values; an expression with blanks goes in square brackets.
  const DecodedProgram q = decoded("P1 = 7\nN10 Z[LIFT_START POS=[P1 * 2] POS_LIMIT=P1+1]\nN20 G01 X1 F100\n");
  check_lift_start(q.blocks[0], 14, 8);
  check_refused("P1 = 7\nN10 Z[LIFT_START POS_LIMIT=P1 + 1]\n", 2, 10, "unknown keyword '+'", 0);
}

TEST_CASE("LIFT-1 POS and POS_LIMIT go through G92 and an active #CS like Z words", "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "N10 G01 Z10 F1000\n"
      "N20 G92 Z10\n"  // Z0 of the program is Z10 of the machine (an additive offset, KRN-8)
      "N30 Z[LIFT_START POS=5 POS_LIMIT=20]\n"
      "N40 X10\n"
      "N50 Z[LIFT_END]\n"
      "N60 Z[LIFT_START G91 POS=-2 POS_LIMIT=4]\n"
      "N70 X20\n"
      "N80 Z[LIFT_END]\n");
  check_lift_start(block_nr(p, 30), 15, 30);
  check_z(block_nr(p, 40), 10);
  check_lift_start(block_nr(p, 60), 13, 19);
  const DecodedProgram q = decoded(
      "N10 #CS ON [0,0,2,0,0,30]\n"  // rotated about Z only: permitted
      "N20 Z[LIFT_START POS=5 POS_LIMIT=20]\n"
      "N30 G01 X10 F1000\n"
      "N40 Z[LIFT_END]\n"
      "N50 G01 X0\n");
  check_lift_start(block_nr(q, 20), 7, 22);
  check_z(block_nr(q, 30), 0);
  check_z(block_nr(q, 50), 7);
}

TEST_CASE("LIFT-5 #FLUSH inside a range acts as LIFT_END at POS_LIMIT and LIFT_START: the text's equivalent program",
          "[decoder][lift]") {
  const std::string flush =
      "N20 G01 X40 Z2 F1000\n"
      "N30 Z[LIFT_START POS=12 POS_LIMIT=40]\n"
      "N40 X50\n"
      "N50 X40\n"
      "N60 #FLUSH\n"
      "N70 X30\n"
      "N80 X20\n"
      "N90 Z[LIFT_END]\n"
      "N100 Y10\n";
  const std::string equivalent =
      "N20 G01 X40 Z2 F1000\n"
      "N30 Z[LIFT_START POS=40 POS_LIMIT=40]\n"
      "N40 X50\n"
      "N50 X40\n"
      "N60 Z[LIFT_END]\n"
      "N60 Z[LIFT_START POS=12 POS_LIMIT=40]\n"
      "N70 X30\n"
      "N80 X20\n"
      "N90 Z[LIFT_END]\n"
      "N100 Y10\n";
  for (const char* wait : {"", " WAIT"}) {
    std::string text = flush;
    text.replace(text.find("#FLUSH") + 6, 0, wait);
    const DecodedProgram f = decoded(text);
    const DecodedProgram e = decoded(equivalent);
    REQUIRE(f.blocks.size() == 9);
    REQUIRE(e.blocks.size() == 10);  // the #FLUSH block is the equivalent's two N60 blocks in one
    check_lift_start(f.blocks[1], 40, 40);
    const Block& flushed = f.blocks[4];
    CHECK(flushed.block_nr == 60);
    CHECK(flushed.lift_end);
    check_lift_start(flushed, 12, 40);
    CHECK(e.blocks[4].lift_end);
    CHECK(e.blocks[5].lift_start->pos == flushed.lift_start->pos);
    CHECK(e.blocks[5].lift_start->pos_limit == flushed.lift_start->pos_limit);
    for (size_t i = 0, j = 0; i < f.blocks.size(); ++i, ++j) {
      if (i == 4) ++j;
      INFO("N" << f.blocks[i].block_nr);
      CHECK(f.blocks[i].block_nr == e.blocks[j].block_nr);
      CHECK(f.blocks[i].has_motion == e.blocks[j].has_motion);
      CHECK(f.blocks[i].motion.start == e.blocks[j].motion.start);
      CHECK(f.blocks[i].motion.end == e.blocks[j].motion.end);
      if (i != 4) CHECK(f.blocks[i].lift_end == e.blocks[j].lift_end);
      CHECK(f.blocks[i].lift_start.has_value() == e.blocks[j].lift_start.has_value());
      if (f.blocks[i].lift_start && i != 4) {
        CHECK(f.blocks[i].lift_start->pos == e.blocks[j].lift_start->pos);
        CHECK(f.blocks[i].lift_start->pos_limit == e.blocks[j].lift_start->pos_limit);
      }
    }
    check_z(block_nr(f, 40), 2);
    check_z(block_nr(f, 70), 40);  // the second part stands at POS_LIMIT
    check_z(block_nr(f, 100), 12);
  }
  // Outside a range #FLUSH does nothing in this rig: no block. #FLUSH WAIT
  // keeps one, marked for block search only (DPS-3).
  const DecodedProgram outside = decoded("N10 G01 X1 F100\nN20 #FLUSH\nN30 #flush  wait\nN40 X2\n");
  REQUIRE(outside.blocks.size() == 3);
  CHECK(outside.blocks[1].not_searchable == "#FLUSH WAIT");
  CHECK_FALSE(outside.blocks[1].lift_end);
  check_refused("N10 G01 X1 F100\nN20 #FLUSH NOW\n", 2, 20, "#FLUSH takes nothing but WAIT", 1);
}

TEST_CASE("LIFT-5 DOWN is kept through #FLUSH; two #FLUSH in one range", "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "N10 G01 Z50 F1000\nN20 Z[LIFT_START DOWN POS=45 POS_LIMIT=20]\nN30 X10\nN40 #FLUSH\nN50 X20\n"
      "N60 #FLUSH WAIT\nN70 X30\nN80 Z[LIFT_END]\nN90 X0\n");
  check_lift_start(block_nr(p, 20), 20, 20, true);
  check_lift_start(block_nr(p, 40), 20, 20, true);
  check_lift_start(block_nr(p, 60), 45, 20, true);
  check_z(block_nr(p, 30), 50);
  check_z(block_nr(p, 50), 20);
  check_z(block_nr(p, 70), 20);
  check_z(block_nr(p, 90), 45);
}

TEST_CASE("LIFT-5 syntax error within the lift range: the blocks before it are kept, Z parks at POS_LIMIT",
          "[decoder][lift]") {
  const DecodedProgram p = decode(
      "N10 G01 Z10 F1000\n"
      "N20 Z[LIFT_START POS_LIMIT=30]\n"
      "N30 X10\n"
      "N40 X20\n"
      "N50 X35\n"
      "N100 syntax error\n"
      "N560 X50\n"
      "N600 Z[LIFT_END]\n");
  REQUIRE(p.error);
  CHECK(p.error->nc_line == 6);
  CHECK(p.error->block_nr == 100);
  REQUIRE(p.blocks.size() == 5);
  check_lift_start(p.blocks[1], 30, 30);  // lands at POS_LIMIT where the decoded blocks end
  for (size_t i = 2; i < 5; ++i) CHECK_FALSE(p.blocks[i].lift_end);
  // After a #FLUSH the open part parks; the part before it already ends at POS_LIMIT.
  const DecodedProgram q = decode("N10 G01 Z10 F1000\nN20 Z[LIFT_START POS=5 POS_LIMIT=30]\nN30 X10\nN40 #FLUSH\n"
                                  "N50 X20\nN60 G41\n");
  REQUIRE(q.error);
  CHECK(q.error->block_nr == 60);
  check_lift_start(block_nr(q, 20), 30, 30);
  check_lift_start(block_nr(q, 40), 30, 30);
  // An error on the LIFT_START line itself opens no range.
  const DecodedProgram r = decode("N10 G01 Z10 F1000\nN20 X5 Z[LIFT_START POS=5 POS_LIMIT=30] G41\n");
  REQUIRE(r.error);
  REQUIRE(r.blocks.size() == 1);
  CHECK_FALSE(r.blocks[0].lift_start);
  // A closed range is not touched by a later error.
  const DecodedProgram s = decode("N10 Z[LIFT_START POS=5 POS_LIMIT=30]\nN20 G01 X5 F100\nN30 Z[LIFT_END]\nN40 G41\n");
  REQUIRE(s.error);
  check_lift_start(s.blocks[0], 5, 30);
}

TEST_CASE("LIFT-5 program end inside a range: M30 acts as LIFT_END; end of text ends it with the last block",
          "[decoder][lift]") {
  const DecodedProgram p = decoded("N10 Z[LIFT_START POS=5 POS_LIMIT=30]\nN20 G01 X5 F100\nN30 M30\n");
  REQUIRE(p.blocks.size() == 3);
  CHECK(p.blocks[2].program_end);
  CHECK(p.blocks[2].lift_end);
  CHECK(p.blocks[2].short_cut_restriction == ShortCutRestriction::not_skippable);
  check_lift_start(p.blocks[0], 5, 30);
  const DecodedProgram q = decoded("N10 G01 X5 F100 Z[LIFT_START POS=5 POS_LIMIT=30] M30\n");
  CHECK(q.blocks[0].lift_end);
  const DecodedProgram r = decoded("N10 Z[LIFT_START POS=5 POS_LIMIT=30]\nN20 G01 X5 F100\n");
  CHECK_FALSE(r.blocks.back().lift_end);
  check_lift_start(r.blocks[0], 5, 30);
  // M30 outside a range: no lift_end.
  CHECK_FALSE(decoded("N10 G01 X5 F100\nM30\n").blocks.back().lift_end);
}

TEST_CASE("LIFT-1 V.G.LIFT_ACTIVE is 1 inside an open lift range, else 0", "[decoder][lift]") {
  const DecodedProgram p = decoded(
      "P1 = V.G.LIFT_ACTIVE\n"
      "N10 #TIME P1 + 1\n"
      "N20 Z[LIFT_START POS_LIMIT=30]\n"
      "P2 = V.G.LIFT_ACTIVE\n"
      "N30 #TIME P2 + 1\n"
      "P3 = 2 * v.g.lift_active + [V.G.LIFT_ACTIVE * 3]\n"
      "N40 #TIME P3\n"
      "N50 #TIME V.G.LIFT_ACTIVE * 4\n"
      "N60 Z[LIFT_END]\n"
      "P4 = V.G.LIFT_ACTIVE\n"
      "N70 #TIME P4 + 1\n"
      "N80 G01 X1 F100 Z[LIFT POS_LIMIT=3]\n"
      "N90 #TIME V.G.LIFT_ACTIVE + 1\n");
  CHECK(block_nr(p, 10).dwell_s == 1);
  CHECK(block_nr(p, 30).dwell_s == 2);
  CHECK(block_nr(p, 40).dwell_s == 5);
  CHECK(block_nr(p, 50).dwell_s == 4);
  CHECK(block_nr(p, 70).dwell_s == 1);
  CHECK(block_nr(p, 90).dwell_s == 1);  // Z[LIFT ..] ended with its block
  check_refused("N10 G01 X1 F100\nP1 = V.G.LIFT_ACTIVEX\n", 2, 0, "unknown variable 'V.G.LIFT_ACTIVEX'", 1);
}

TEST_CASE("LIFT-1 LIFT-3 the lift function must be enabled; DOWN only with Advanced Lifting", "[decoder][lift]") {
  const std::string not_enabled =
      "the lift function is not enabled on this machine (FCT_LIFT_UP or FCT_LIFT_UP_TIME in P-STUP-00060 "
      "path_preparation_function, P-CHAN-00345 enable_time_based_lift)";
  for (const char* line : {"N20 Z[LIFT_START POS_LIMIT=30]", "N20 X5 Z[LIFT POS_LIMIT=30]", "N20 Z[LIFT_END]"})
    check_refused(std::string("N10 G01 X1 F100\n") + line + "\n", 2, 20, not_enabled, 1, 0, test::xyz_machine());
  // Lifting (path-based): the range works, DOWN is refused.
  const DecodedProgram p = decoded("N10 Z[LIFT_START POS=3 POS_LIMIT=30]\nN20 G01 X5 F100\nN30 Z[LIFT_END]\n",
                                   test::xyz_lifting_machine());
  check_lift_start(p.blocks[0], 3, 30);
  check_refused("N10 G01 X1 F100\nN20 Z[LIFT_START DOWN POS_LIMIT=-30]\n", 2, 20,
                "Z[LIFT_START]: DOWN is only available with Advanced Lifting", 1, 0, test::xyz_lifting_machine());
}

TEST_CASE("LIFT-1 LIFT-6 malformed lift commands and ranges are refused with their line", "[decoder][lift]") {
  const std::string before = "N10 G01 X1 F100\n";
  struct Case {
    std::string lines;  // after N10; the last one is refused
    int64_t line;
    int64_t nr;
    std::string part;
    size_t kept;
  };
  const Case cases[] = {
      {"N20 Z[LIFT_START POS=12]\n", 2, 20, "Z[LIFT_START] needs POS_LIMIT=..", 1},
      {"N20 Z[LIFT_START POS_LIMIT=30 FOO]\n", 2, 20, "Z[LIFT_START]: unknown keyword 'FOO'", 1},
      {"N20 Z[LIFT_START POS_LIMIT=30 POS_LIMIT=40]\n", 2, 20, "POS_LIMIT given twice", 1},
      {"N20 Z[LIFT_START POS=1 POS=2 POS_LIMIT=40]\n", 2, 20, "POS given twice", 1},
      {"N20 Z[LIFT_START DOWN DOWN POS_LIMIT=40]\n", 2, 20, "DOWN given twice", 1},
      {"N20 Z[LIFT_START G90 G91 POS_LIMIT=40]\n", 2, 20, "one of G90 / G91", 1},
      {"N20 Z[LIFT_START DOWN=1 POS_LIMIT=40]\n", 2, 20, "DOWN takes no value", 1},
      {"N20 Z[LIFT_START POS=abc POS_LIMIT=40]\n", 2, 20, "POS=ABC is not a number", 1},
      {"N20 Z[LIFT_START POS_LIMIT=]\n", 2, 20, "POS_LIMIT needs =<value>", 1},
      {"N20 Z[LIFT_START POS_LIMIT]\n", 2, 20, "POS_LIMIT needs =<value>", 1},
      {"N20 Z[LIFT_START POS_LIMIT=1e7]\n", 2, 20, "out of range", 1},
      {"N20 Z[LIFT_START POS_LIMIT=P9]\n", 2, 20, "P9 has no value yet", 1},
      {"N20 Z[POS_LIMIT=30 LIFT_START]\n", 2, 20, "Z[LIFT_START]: LIFT_START must be the first keyword", 1},
      {"N20 Z[DOWN LIFT POS_LIMIT=30]\n", 2, 20, "Z[LIFT]: LIFT must be the first keyword", 1},
      {"N20 Z[POS_LIMIT=30]\n", 2, 20, "axis command 'Z[POS_LIMIT]' is not supported yet", 1},
      {"N20 Z[LIFT_START POS_LIMIT=30 LIFT_START]\n", 2, 20, "LIFT_START must be the first keyword", 1},
      {"N20 Z[LIFT_END POS=3]\n", 2, 20, "Z[LIFT_END] takes no parameters", 1},
      {"N20 Z[LIFT_END]\n", 2, 20, "Z[LIFT_END] without an open lift range", 1},
      {"N20 Z[LIFT_START POS_LIMIT=30]\nN30 X[LIFT_END]\n", 3, 30,
       "X[LIFT_END]: the open range is the lift range of Z (LIFT_START in line 2)", 2},
      {"N20 Z[LIFT_START POS_LIMIT=30]\nN30 X5\nN40 Z[LIFT_START POS_LIMIT=30]\n", 4, 40,
       "Z[LIFT_START] inside the lift range of Z (LIFT_START in line 2)", 3},
      {"N20 Z[LIFT_START POS_LIMIT=30]\nN30 X5 Z[LIFT POS_LIMIT=30]\n", 3, 30, "Z[LIFT] inside the lift range", 2},
      {"N20 X5 Z[LIFT_START POS_LIMIT=30] Z[LIFT_END]\n", 2, 20, "Z[LIFT_END]: one lift command per block", 1},
      {"N20 G92 X0 Z[LIFT_START POS_LIMIT=30]\n", 2, 20, "a lift command cannot be combined with G92", 1},
  };
  for (const Case& c : cases) check_refused(before + c.lines, c.line, c.nr, c.part, c.kept);
  // A modulo axis is no lift axis.
  MachineConfig xyzc = test::xyzc_machine();
  xyzc.lift_method = LiftMethod::time_based;
  const DecodedProgram c = decode_program("N10 C[LIFT_START POS_LIMIT=30]\n", xyzc, {0, 0, 0, 0});
  REQUIRE(c.error);
  CHECK(c.error->block_nr == 10);
  CHECK_THAT(c.error->message, Catch::Contains("C[LIFT_START]: a modulo axis cannot be a lift axis"));
}

TEST_CASE("LIFT-6 the lift axis programmed inside its range is an error naming the axis", "[decoder][lift]") {
  const std::string range = "N10 G01 X1 F100\nN20 Z[LIFT_START POS_LIMIT=30]\nN30 X5\n";
  const std::string part = "axis Z is programmed inside the lift range of Z (LIFT_START in line 2)";
  check_refused(range + "N40 X6 Z3\n", 4, 40, part, 3);
  check_refused(range + "N40 Z3\n", 4, 40, part, 3);
  check_refused(range + "N40 G91 Z0\n", 4, 40, part, 3);
  check_refused(range + "N40 G92 Z0\n", 4, 40, part, 3);
  check_refused(range + "N40 X6 Z3 Z[LIFT_END]\n", 4, 40, part, 3);
  check_refused("N10 G01 X1 F100\nN20 X2 Z5 Z[LIFT_START POS_LIMIT=30]\n", 2, 20,
                "axis Z is programmed inside its lift range", 1);
  check_refused("N10 G01 X1 F100\nN20 X2 Z5 Z[LIFT POS_LIMIT=30]\n", 2, 20, "axis Z is programmed inside its lift range",
                1);
  // Other axes, and Z after the range, are free.
  const DecodedProgram p = decoded(range + "N40 Y6\nN50 Z[LIFT_END]\nN60 Z3\n");
  CHECK(block_nr(p, 60).motion.end[z_axis] == 3);
}

TEST_CASE("LIFT-6 #CS ON/OFF inside a lift range is error 120606; #ROTATION and #TRAFO are refused by name",
          "[decoder][lift]") {
  const std::string range = "N10 G01 X1 F100\nN20 Z[LIFT_START POS_LIMIT=30]\nN30 X5\n";
  check_refused(range + "N40 #CS ON [0,0,0,0,0,10]\n", 4, 40, "#CS ON inside the lift range of Z (LIFT_START in line 2)",
                3, 120606);
  check_refused("N10 #CS ON [0,0,0,0,0,10]\nN20 Z[LIFT_START POS_LIMIT=30]\nN30 G01 X5 F100\nN40 #CS OFF\n", 4, 40,
                "#CS OFF inside the lift range of Z", 3, 120606);
  check_refused(range + "N40 #ROTATION ON\n", 4, 40, "#ROTATION inside the lift range of Z", 3, 120606);
  check_refused(range + "N40 #TRAFO OFF\n", 4, 40, "#TRAFO inside the lift range of Z", 3, 120606);
  check_refused("N10 G01 X1 F100\nN20 #ROTATION ON [ANGLE=30]\n", 2, 20, "'#ROTATION' is not supported by this rig", 1);
  check_refused("N10 G01 X1 F100\nN20 #TRAFO ON\n", 2, 20, "'#TRAFO' is not supported by this rig", 1);
  check_refused("N10 G01 X1 F100\nN20 #TRAFO ON\n", 2, 20, "'#TRAFO' is not supported by this rig", 1, 0,
                test::xyz_machine());
  // After the range #CS is free again.
  decoded(range + "N40 Z[LIFT_END]\nN50 #CS ON [0,0,0,0,0,10]\nN60 #CS OFF\n");
}

TEST_CASE("LIFT-6 LIFT_START with a #CS that rotates the lift axis is error 21071; about Z it is permitted",
          "[decoder][lift]") {
  for (const char* cs : {"[0,0,0,10,0,0]", "[0,0,0,0,-5,0]", "[0,0,0,1,1,30]"}) {
    check_refused(std::string("N10 G01 X1 F100\nN20 #CS ON ") + cs + "\nN30 Z[LIFT_START POS_LIMIT=30]\n", 3, 30,
                  "Z[LIFT_START]: the active #CS rotates the lift axis Z", 2, 21071);
    check_refused(std::string("N10 G01 X1 F100\nN20 #CS ON ") + cs + "\nN30 X5 Z[LIFT POS_LIMIT=30]\n", 3, 30,
                  "Z[LIFT]: the active #CS rotates the lift axis Z", 2, 21071);
  }
  for (const char* cs : {"[0,0,0,0,0,90]", "[5,5,5,360,0,0]", "[0,0,0,0,0,0]"})
    decoded(std::string("N10 #CS ON ") + cs + "\nN20 Z[LIFT_START POS_LIMIT=30]\nN30 G01 X1 F100\nN40 Z[LIFT_END]\n");
  // A rotation about Z rotates X: X as the lift axis is refused.
  check_refused("N10 #CS ON [0,0,0,0,0,30]\nN20 X[LIFT_START POS_LIMIT=30]\n", 2, 20,
                "the active #CS rotates the lift axis X", 1, 21071);
}

TEST_CASE("LIFT-6 #SLOPE[TYPE=HSC] with Advanced Lifting is error 120711", "[decoder][lift]") {
  check_refused("N10 G01 X1 F100\nN20 #SLOPE [TYPE=HSC]\n", 2, 20, "#SLOPE type HSC is not supported with Advanced Lifting",
                1, 120711);
  // Without Advanced Lifting the rig refuses HSC as before, without the ID.
  for (const MachineConfig& m : {test::xyz_machine(), test::xyz_lifting_machine()})
    check_refused("N10 G01 X1 F100\nN20 #SLOPE [TYPE=HSC]\n", 2, 20, "#SLOPE type 'HSC' is not one of STEP, TRAPEZ, SIN2",
                  1, 0, m);
  // STEP, TRAPEZ, SIN2 are permitted with Advanced Lifting.
  decoded("N10 #SLOPE [TYPE=STEP]\nN20 #SLOPE [TYPE=SIN2]\nN30 #SLOPE [TYPE=TRAPEZ]\nN40 Z[LIFT_START POS_LIMIT=3]\n");
}

TEST_CASE("DDTG-8 lift commands must not be skipped: every block with lift_start or lift_end is not_skippable",
          "[decoder][lift][ddtg]") {
  const DecodedProgram p = decoded(
      "N10 G01 X10 F1000\n"
      "N20 Z[LIFT_START POS_LIMIT=30]\n"
      "N30 X20\n"
      "N40 #FLUSH\n"
      "N50 X30\n"
      "N60 Z[LIFT_END]\n"
      "N70 X40 Z[LIFT POS_LIMIT=5]\n"
      "N80 X50 Z[LIFT_START POS_LIMIT=5]\n"
      "N90 X60\n"
      "N100 M30\n");
  for (const Block& b : p.blocks) {
    INFO("N" << b.block_nr);
    const bool lift = b.lift_start || b.lift_end;
    CHECK(lift == (b.block_nr == 20 || b.block_nr == 40 || b.block_nr == 60 || b.block_nr == 70 ||
                   b.block_nr == 80 || b.block_nr == 100));
    CHECK((b.short_cut_restriction == ShortCutRestriction::not_skippable) == lift);
  }
  // A short cut from N10 to the end marker would skip N20: the DDTG unit refuses it (error 51016).
  const DecodedProgram q = decoded("N10 G01 X10 F1000\nN20 Z[LIFT_START POS_LIMIT=30]\nN30 X20\n"
                                   "N40 #DEL DIST2GO\nN50 Z[LIFT_END]\nN60 X0\n");
  const ShortCutTarget t = short_cut_target(q.blocks, 0, 1);
  REQUIRE(t.not_skippable);
  CHECK(q.blocks[*t.not_skippable].block_nr == 20);
}
