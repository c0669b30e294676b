// KRN-1 (decoder subset) and KRN-2 (errors carry line and block number).
#include <catch2/catch.hpp>

#include "decoder_checks.hpp"

using namespace hil;
using namespace hil::cnc;
using namespace hil::test;

TEST_CASE("KRN-1 decoder: N numbers, G00/G01, modal feed, absolute and incremental", "[decoder]") {
  const DecodedProgram p = decode(
      "%prog\n"
      "N10 G00 X10 Y20 Z5 ; rapid\n"
      "N20 G01 X20 F600 (feed 10 mm/s)\n"
      "N30 G91 Y-5\n"
      "N40 G90 Z0\n"
      "N50 M30\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 5);
  CHECK(p.blocks[0].block_nr == 10);
  CHECK(p.blocks[0].nc_line == 2);
  CHECK(p.blocks[0].motion.type == MotionType::rapid);
  CHECK(p.blocks[0].motion.end == std::vector<double>{10, 20, 5});
  CHECK(p.blocks[1].motion.type == MotionType::linear);
  CHECK(p.blocks[1].motion.feed == Approx(10.0));
  CHECK(p.blocks[1].motion.start == std::vector<double>{10, 20, 5});
  CHECK(p.blocks[2].motion.end == std::vector<double>{20, 15, 5});
  CHECK(p.blocks[2].motion.feed == Approx(10.0));  // modal
  CHECK(p.blocks[3].motion.end == std::vector<double>{20, 15, 0});
  CHECK(p.blocks[4].program_end);
  CHECK_FALSE(p.blocks[4].has_motion);
}

TEST_CASE("KRN-1 decoder: G02/G03 with I/J centre incremental to the start point", "[decoder]") {
  const DecodedProgram p = decode("G01 X10 F1000\nG03 X20 Y10 I0 J10\nG02 X10 Y20 I-10 J0\nG03 I-5\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 4);
  CHECK(p.blocks[1].motion.type == MotionType::arc_ccw);
  CHECK(p.blocks[1].motion.center[0] == Approx(10));
  CHECK(p.blocks[1].motion.center[1] == Approx(10));
  CHECK(p.blocks[2].motion.type == MotionType::arc_cw);
  CHECK(p.blocks[2].motion.center[0] == Approx(10));
  CHECK(p.blocks[2].motion.center[1] == Approx(10));
  // Only I given: a full circle back to the start point.
  CHECK(p.blocks[3].motion.end == p.blocks[3].motion.start);
  CHECK(p.blocks[3].motion.center[0] == Approx(5));
}

TEST_CASE("KRN-1 decoder: program ends at M30 or M02; text after it is not decoded", "[decoder]") {
  for (const char* end : {"M30", "M02", "M2"}) {
    INFO(end);
    const DecodedProgram p = decode(std::string("G01 X1 F100\n") + end + "\nthis is not NC code\n");
    REQUIRE_FALSE(p.error);
    REQUIRE(p.blocks.size() == 2);
    CHECK(p.blocks[1].program_end);
    // A CNC command (TF5200 "Default M functions"): not output to the PLC.
    CHECK(p.blocks[1].m_functions.empty());
  }
}

TEST_CASE("KRN-2 decoder: an error names its line and block; the blocks before it are kept", "[decoder]") {
  struct Case {
    const char* line;
    const char* message_part;
  };
  const Case cases[] = {
      {"N30 G41 X5", "G41 tool radius compensation (left) is not supported by this rig"},
      {"N30 P1 = 2 * P9", "P9 has no value yet"},
      {"N30 P1 = 2 / [1 - 1]", "division by zero"},
      {"N30 X=5", "'=' is only allowed in P<n> = <expression>"},
      {"N30 #TIME 0", "#TIME needs a dwell time > 0"},
      {"N30 Q5", "Q is not an axis"},
      {"N30 X", "needs a number"},
      {"N30 X1.2.3", "malformed number"},
      {"N30 X1 X2", "programmed twice"},
      {"N30 G01 G02 X1", "two motion G codes"},
      {"N30 G02 X30 Y0 I5 J0", "maximum difference between radii exceeded"},
      {"N30 #FLUSH X", "#FLUSH takes nothing but WAIT"},
      {"N30 $FOR P1=0,1,1", "$FOR without $ENDFOR"},
      {"N30 $IF P1 == 1", "'$IF' is not supported yet"},
      {"N30 $ENDFOR", "$ENDFOR without $FOR"},
      {"N30 X1 (open comment", "comment '(' is not closed"},
      {"N30 G01 X5 I3", "only allowed with G02/G03"},
      {"N30 F0", "feed 'F0' is out of range 0.001 .. 10000000 mm/min"},
  };
  for (const Case& c : cases) {
    INFO(c.line);
    const DecodedProgram p = decode(std::string("N10 G01 X1 F100\nN20 Y1\n") + c.line + "\nN40 X50\nM30\n");
    REQUIRE(p.error);
    CHECK(p.error->severity == Severity::error);
    CHECK(p.error->nc_line == 3);
    CHECK(p.error->block_nr == 30);
    CHECK_THAT(p.error->message, Catch::Contains(c.message_part));
    CHECK(p.blocks.size() == 2);  // exactly what was decoded correctly
  }
}

TEST_CASE("KRN-2 decoder: G01 without any feed is an error", "[decoder]") {
  const DecodedProgram p = decode("G01 X10\n");
  REQUIRE(p.error);
  CHECK(p.error->nc_line == 1);
  CHECK_THAT(p.error->message, Catch::Contains("no feed F"));
}

TEST_CASE("KRN-1 DPS-2 decoder: #DISTANCE PROG START ON/OFF/CLEAR, G92 position preset, #SLOPE", "[decoder]") {
  const DecodedProgram p = decode(
      "N10 #DISTANCE PROG START OFF\n"
      "N20 G01 X0 Y0 F1000\n"  // no axis moves: no motion block
      "N30 G92 X33 Y55\n"
      "N40 X0 Y0\n"
      "#distance prog start  on\n"
      "N50 #SLOPE [TYPE=SIN2]\n"
      "N60 G91 X100\n"
      "N70 #DISTANCE PROG START CLEAR\n");
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 5);
  CHECK(p.blocks[0].block_nr == 10);
  CHECK(p.blocks[0].distance_prog_start == DistanceProgStart::off);
  CHECK_FALSE(p.blocks[0].has_motion);
  CHECK(p.blocks[1].block_nr == 40);  // G92 X33 Y55: X0 Y0 of the program is X33 Y55 (additive, KRN-8)
  CHECK(p.blocks[1].motion.end == std::vector<double>{33, 55, 0});
  CHECK(p.blocks[1].slope == SlopeType::trapez);
  CHECK(p.blocks[2].distance_prog_start == DistanceProgStart::on);
  CHECK(p.blocks[3].motion.end == std::vector<double>{133, 55, 0});
  CHECK(p.blocks[3].slope == SlopeType::sin2);
  CHECK(p.blocks[4].distance_prog_start == DistanceProgStart::clear);

  for (const char* bad : {"N10 #DISTANCE PROG START\n", "N10 #SLOPE[TYPE=CUBIC]\n", "N10 G01 X1 F100 #FLUSH\n",
                          "N10 #FLUSH WAITING\n", "N10 G92 G01 X1\n"}) {
    const DecodedProgram e = decode(bad);
    REQUIRE(e.error);
    CHECK(e.error->nc_line == 1);
    CHECK(e.error->block_nr == 10);
  }
}

TEST_CASE("KRN-1 DDTG-5 decoder: #DEL DIST2GO end markers, default END=1, IEC literals '16#0105'", "[decoder]") {
  // The marker lines of TF5200_delete_distance_to_go.txt 2.2.
  const DecodedProgram p = decode(
      "N040 X130 F1000\n"
      "N041 #DEL DIST2GO ;Default ACTIVATION = '16#01'\n"
      "N051 #DEL DIST2GO [END='16#01'] ; short cut target\n"
      "N061 #DEL DIST2GO [END=2]\n"
      "N071 #DEL DIST2GO [END='16#0105']\n"
      "N081 #del dist2go [ END = 8 ]\n"
      "N091 #DEL DIST2GO []\n"
      "N101 #DEL DIST2GO [END='2#1010']\n");
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 8);
  CHECK_FALSE(p.blocks[0].ddtg_end_marker);
  const uint32_t expected[] = {1, 1, 2, 0x105, 8, 1, 10};
  for (int i = 0; i < 7; ++i) {
    INFO("marker " << i);
    REQUIRE(p.blocks[i + 1].ddtg_end_marker);
    CHECK(*p.blocks[i + 1].ddtg_end_marker == expected[i]);
    CHECK_FALSE(p.blocks[i + 1].has_motion);
  }
  CHECK(p.blocks[4].block_nr == 71);
  for (const char* bad : {"N10 #DEL DIST2GO [END='16#1FFFFFFFF']\n", "N10 #DEL DIST2GO [END=X]\n",
                          "N10 #DEL DIST2GO [ACT=1]\n", "N10 #DEL DIST2GO [END='3#12']\n",
                          "N10 #DEL DIST2GO [END=-1]\n"}) {
    INFO(bad);
    const DecodedProgram e = decode(bad);
    REQUIRE(e.error);
    CHECK(e.error->block_nr == 10);
  }
}

TEST_CASE("KRN-1 DDTG-7 decoder: M functions, P parameters with arithmetic, #TIME dwell", "[decoder]") {
  // TF5200_delete_distance_to_go.txt 4.5, and arithmetic on P parameters.
  const DecodedProgram p = decode(
      "N005 X0 Y0 Z0 F1000\n"
      "N010 X100 ;interrupt and delete distance to go\n"
      "N015 M48\n"
      "N016 P1=1\n"
      "N017 #TIME 10\n"
      "N020 Y100 M7 M8\n"
      "N025 P2 = [P1 + 2] * -1.5 / 3 (round brackets: a comment)\n"
      "N026 #TIME -P2\n"
      "N030 X90 Y110\n"
      "N040 M30\n");
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 7);  // the P assignments are decoder work: no blocks
  CHECK(p.blocks[1].block_nr == 15);
  CHECK(p.blocks[1].m_functions == std::vector<MFunction>{{48, 0}});
  CHECK_FALSE(p.blocks[1].has_motion);
  CHECK(p.blocks[2].block_nr == 17);
  CHECK(p.blocks[2].dwell_s == 10);
  CHECK(p.blocks[3].has_motion);
  CHECK(p.blocks[3].m_functions == std::vector<MFunction>{{7, 0}, {8, 0}});
  CHECK(p.blocks[4].dwell_s == Approx(1.5));  // -P2 = -((1 + 2) * -1.5 / 3)
  CHECK(p.blocks[6].program_end);
}

TEST_CASE("KRN-1 decoder: $FOR/$ENDFOR loops repeat their lines; block_count_r counts every line read",
          "[decoder]") {
  const DecodedProgram p = decode(
      "N010 G01 X0 Y0 F1000\n"
      "N020 $FOR P1 = 1, 3, 1\n"
      "N030 G91 X10\n"
      "N040 $FOR P2 = 2, 1, 1 (never: 2 > 1)\n"
      "N050 Y99\n"
      "N060 $ENDFOR\n"
      "N070 $ENDFOR\n"
      "N080 G90 X0 Y5\n"
      "N090 M30\n");
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 5);  // N030 three times (P1 = 1, 2, 3), N080, M30
  for (int i = 0; i < 3; ++i) {
    CHECK(p.blocks[i].block_nr == 30);
    CHECK(p.blocks[i].nc_line == 3);
    CHECK(p.blocks[i].motion.end[0] == 10.0 * (i + 1));
  }
  // Lines read: 1 2 3 4 7 | 3 4 7 | 3 4 7 8 9 (5, 6 never): N030 is the 3rd, 6th, 9th
  CHECK(p.blocks[0].block_count == 3);
  CHECK(p.blocks[1].block_count == 6);
  CHECK(p.blocks[2].block_count == 9);
  CHECK(p.blocks[3].nc_line == 8);
  CHECK(p.blocks[3].block_count == 12);
  CHECK(p.blocks[4].program_end);
}

TEST_CASE("KRN-1 decoder: G161/G162 circle centre absolute/relative, G165 centre correction", "[decoder]") {
  const DecodedProgram p = decode(
      "N10 G01 X100 Y60 F1000\n"
      "N20 G02 X150 Y10 J-50\n"         // G162 (initial): centre relative to the start
      "N30 G161 G03 X100 Y60 I100 J10\n"  // G161: the same centre, absolute
      "N40 G162 G165 G02 X150 Y10 I1 J-50\n"  // 1 mm off: G165 moves the centre onto the bisector
      "N50 G164 G03 X100 Y60 I-49 J0\n");     // G164: 1 mm off is an error again
  REQUIRE(p.error);
  CHECK(p.error->block_nr == 50);
  CHECK_THAT(p.error->message, Catch::Contains("maximum difference between radii exceeded"));
  REQUIRE(p.blocks.size() == 4);
  for (int i = 1; i <= 3; ++i) {
    INFO("block " << p.blocks[i].block_nr);
    CHECK(p.blocks[i].motion.center[0] == Approx(100 + (i == 3 ? 0.5 : 0)).margin(1e-9));
    CHECK(p.blocks[i].motion.center[1] == Approx(10 + (i == 3 ? 0.5 : 0)).margin(1e-9));
  }
}

TEST_CASE("KRN-1 DDTG-8 decoder: #CS ON [v1,v2,v3,φ1,φ2,φ3] offsets and rotates the program, #CS OFF", "[decoder]") {
  const DecodedProgram p = decode(
      "N10 G01 X10 Y0 F1000\n"
      "N20 #CS ON [100,50,5,0,0,90]\n"  // rotated 90° about Z
      "N30 X10 Y0 Z0\n"               // program (10, 0, 0) -> machine (100, 60, 5)
      "N40 G91 Y10\n"                 // +Y in the CS is -X on the machine
      "N50 G90 G03 X0 Y20 I-10 J0\n"  // quarter circle around program (0, 10)
      "N60 #CS OFF\n"
      "N70 G01 X0 Y0 Z0\n"
      "N75 X5\n"                      // unprogrammed axes keep their program coordinates
      "N80 #CS ON [,,-2]\n"           // translation only, gaps are 0
      "N90 Z0\n"
      "N95 #CS OFF\n"
      "N100 #channel init [ cmdpos ]\n");
  if (p.error) FAIL(p.error->message);
  REQUIRE(p.blocks.size() == 12);
  CHECK(p.blocks[1].short_cut_restriction == ShortCutRestriction::not_skippable);
  const Motion& n30 = p.blocks[2].motion;
  CHECK(n30.end[0] == Approx(100).margin(1e-9));
  CHECK(n30.end[1] == Approx(60).margin(1e-9));
  CHECK(n30.end[2] == Approx(5).margin(1e-9));
  const Motion& n40 = p.blocks[3].motion;
  CHECK(n40.end[0] == Approx(90).margin(1e-9));
  CHECK(n40.end[1] == Approx(60).margin(1e-9));
  const Motion& n50 = p.blocks[4].motion;
  CHECK(n50.center[0] == Approx(90).margin(1e-9));
  CHECK(n50.center[1] == Approx(50).margin(1e-9));
  CHECK(n50.end[0] == Approx(80).margin(1e-9));
  CHECK(n50.end[1] == Approx(50).margin(1e-9));
  CHECK(p.blocks[5].short_cut_restriction == ShortCutRestriction::not_skippable);
  CHECK(p.blocks[6].motion.end == std::vector<double>{0, 0, 0});  // back in workpiece coordinates
  CHECK(p.blocks[7].motion.end == std::vector<double>{5, 0, 0});
  CHECK(p.blocks[9].motion.end[2] == Approx(-2).margin(1e-12));
  CHECK(p.blocks[11].short_cut_restriction == ShortCutRestriction::channel_initialisation);
  CHECK(p.blocks[11].stops_path());
}

TEST_CASE("KRN-2 decoder: #CS and #CHANNEL INIT forms that are not supported are errors with their line",
          "[decoder]") {
  struct Case {
    const char* program;
    const char* message;
  };
  for (const Case& c : {Case{"#CS OFF\n", "without an active #CS"},
                        Case{"#CS ON [1,2]\n#CS ON [3]\n", "nesting is not supported"},
                        Case{"#CS ON\n", "needs [v1,v2,v3"},
                        Case{"#CS ON [1,2,3,4,5,6,7]\n", "at most 6 components"},
                        Case{"#CS ON [0,0,0,30]\nG02 X1 Y1 I1 F100\n", "rotated out of that plane"},
                        Case{"#CS ON [1]\nG92 X0\n", "G92 while a #CS is active"},
                        Case{"#CHANNEL INIT [ACTPOS]\n", "#CHANNEL INIT takes [CMDPOS]"}}) {
    INFO(c.program);
    const DecodedProgram p = decode(c.program);
    REQUIRE(p.error);
    CHECK_THAT(p.error->message, Catch::Contains(c.message));
  }
}

TEST_CASE("KRN-1 DDTG-7 decoder: M function pre-output path from P-CHAN-00070 and V.G.M_FCT[i].PRE_OUTP_PATH",
          "[decoder]") {
  MachineConfig m = test::xyz_machine();
  m.m_pre_output_mm[7] = 2.5;  // m_pre_outp[7] = 25000 (0.1 um)
  const DecodedProgram p = decode_program(
      "N10 G1 X10 F1000 M7 M8\n"
      "N20 V.G.M_FCT[8].PRE_OUTP_PATH = P1 + 4\n"  // P1 is not set: an error, caught below
      "N30 X20\n",
      m, {0, 0, 0});
  REQUIRE(p.blocks.size() == 1);
  CHECK(p.blocks[0].m_functions == std::vector<MFunction>{{7, 2.5}, {8, 0}});
  REQUIRE(p.error);
  CHECK(p.error->block_nr == 20);
  const DecodedProgram q = decode_program(
      "N10 P1 = 1\nN20 v.g.m_fct[ 8 ].pre_outp_path = P1 + 4\nN30 G1 X10 F1000 M8\nN40 V.G.M_FCT[7].PRE_OUTP_PATH = 0\n"
      "N50 X20 M7\n",
      m, {0, 0, 0});
  REQUIRE_FALSE(q.error);
  REQUIRE(q.blocks.size() == 2);
  CHECK(q.blocks[0].m_functions == std::vector<MFunction>{{8, 5}});
  CHECK(q.blocks[1].m_functions == std::vector<MFunction>{{7, 0}});
}

TEST_CASE("KRN-1 decoder: each '#' command is found through the command table, any case and spacing",
          "[decoder]") {
  const DecodedProgram p = decode(
      "N10 #DISTANCE PROG START CLEAR\n"
      "N20 #slope  [ type = step ]\n"
      "N30 G01 X1 F100\n"
      "N40 #DEL   DIST2GO [END=4]\n"
      "N50 #Time2.5\n"  // a digit may follow the keyword directly
      "N60 #CS ON[0,0,1]\n"
      "N70 #CS OFF\n"
      "N80 #CHANNEL INIT[CMDPOS]\n");
  INFO((p.error ? p.error->message : std::string()));
  REQUIRE_FALSE(p.error);
  REQUIRE(p.blocks.size() == 7);  // #SLOPE is modal decoder state: no block of its own
  CHECK(p.blocks[0].distance_prog_start == DistanceProgStart::clear);
  CHECK(p.blocks[1].slope == SlopeType::step);
  CHECK(p.blocks[2].ddtg_end_marker == 4u);
  CHECK(p.blocks[3].dwell_s == 2.5);
  CHECK(p.blocks[4].short_cut_restriction == ShortCutRestriction::not_skippable);
  CHECK(p.blocks[5].short_cut_restriction == ShortCutRestriction::not_skippable);
  CHECK(p.blocks[6].short_cut_restriction == ShortCutRestriction::channel_initialisation);
  const int64_t block_nrs[] = {10, 30, 40, 50, 60, 70, 80};
  for (size_t i = 0; i < p.blocks.size(); ++i) CHECK(p.blocks[i].block_nr == block_nrs[i]);
}

TEST_CASE("KRN-1 KRN-2 decoder: a command is its whole keyword; others are refused with their line", "[decoder]") {
  check_refused_as_line_3("N30 #CSX ON [1]", "command '#CSX' is not supported yet");
  check_refused_as_line_3("N30 #SLOPEX[TYPE=STEP]", "command '#SLOPEX' is not supported yet");
  check_refused_as_line_3("N30 #TIMEX 5", "command '#TIMEX' is not supported yet");
  check_refused_as_line_3("N30 #DEL DIST2GOX", "command '#DEL' is not supported yet");
  check_refused_as_line_3("N30 #foo [1]", "command '#FOO' is not supported yet");
  check_refused_as_line_3("N30 #FLUSHWAIT", "command '#FLUSHWAIT' is not supported yet");
  check_refused_as_line_3("N30 #CONTOUR MODEX [DEV PATH_DEV=0.1]", "command '#CONTOUR' is not supported yet");
}

TEST_CASE("KRN-1 KRN-2 LIFT-1 decoder: axis commands <axis>[KEYWORD ...]; the lift forms need the lift function",
          "[decoder]") {
  // The forms of TF5200_lift_function.txt (tests/unit/lift_decoder_test.cpp): this machine has no lift function.
  const std::string not_enabled =
      ": the lift function is not enabled on this machine (FCT_LIFT_UP or FCT_LIFT_UP_TIME in P-STUP-00060 "
      "path_preparation_function, P-CHAN-00345 enable_time_based_lift)";
  check_refused_as_line_3("N30 Z[LIFT_START POS=40 POS_LIMIT=30]", "Z[LIFT_START]" + not_enabled);
  check_refused_as_line_3("N30 G01 X2 Y3 Z[LIFT_END]", "Z[LIFT_END]" + not_enabled);
  check_refused_as_line_3("N30 x2 z [ lift pos=30 pos_limit=300 ]", "Z[LIFT]" + not_enabled);
  check_refused_as_line_3("N30 Z[LIFTX POS=40]", "axis command 'Z[LIFTX]' is not supported yet");
  check_refused_as_line_3("N30 Z[LIFT_START DOWN G91 POS_LIMIT=3", "axis command 'Z[LIFT_START' has no closing ']'");
  check_refused_as_line_3("N30 Q[LIFT_END]", "'Q[LIFT_END]': Q is not an axis of this machine");
  // An expression in brackets is no command; expressions in axis words are not supported.
  check_refused_as_line_3("N30 X[10]", "address 'X' needs a number");
  check_refused_as_line_3("N30 X[P1 + 2]", "address 'X' needs a number");
}
