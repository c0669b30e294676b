// Channel fuzz seeds that failed once (tests/fuzz, bench/channel_fuzz;
// docs/FUZZ.md names each failure by its letter), pinned: each runs as the
// fuzz ran it, with every PLC action, and must keep every invariant. The
// failures found by hand-written scenarios are in channel_known_bugs_test.
// (A failure that cannot be fixed at once is pinned hidden, tagged
// [.][known-bug].) Each run is a child process: they crashed once.
#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <string>

#include "channel_fuzz.hpp"

using namespace hil;

namespace {

// Runs the seeds of one program kind as the fuzz did (every PLC action;
// `vary_machine`: on the seed's machine, FuzzOptions::vary_machine).
void check_seeds(fuzz::ProgramKind kind, std::initializer_list<uint64_t> seeds, bool vary_machine = false) {
  fuzz::FuzzOptions options;
  options.kind = kind;
  options.vary_machine = vary_machine;
  for (uint64_t seed : seeds) {
    const fuzz::FuzzRun run = fuzz::run_channel_fuzz_isolated(seed, options);
    INFO("seed " << seed << ": " << (run.failures.empty() ? "" : fuzz::describe(run, run.failures[0])));
    CHECK(run.passed());
  }
}

}  // namespace

TEST_CASE("LIFT-2 LIFT-3 the lift fuzz seeds that broke the lift axis' jerk limit or never ended keep it and end",
          "[channel][lift][fuzz]") {
  // Issue 32 / 33 (docs/LIFT.md "What issue 32 found"): 9, 110, 214, 246,
  // 444: Advanced Lifting moved on twice in a program's first cycle (40,000
  // mm/s^3 for 30,000); 30, 124, 130: its motion began while the path's of Z
  // came to rest; 81: Lifting's jerk budget; 6000212: a curve across a range
  // without path motion (421,461 mm/s^3); 6000474: the lift and the path
  // waited for each other (no end in 58,565 cycles).
  check_seeds(fuzz::ProgramKind::lift, {9, 30, 81, 110, 124, 130, 214, 246, 444, 6000212, 6000474});
}

TEST_CASE("KRN-3 a plan that reaches a stretch's end velocity only beyond its end has not met it", "[channel][fuzz]") {
  // N, issue 33's fresh seeds: where even ramping a to 0 passes the
  // stretch's end, block_profile arrives beyond it; that plan reached v_end
  // 1.57 mm past the transition it had to keep and was taken as meeting it.
  // Steps 12016401: X's acceleration 24,512 mm/s^2 for 2,000; arcs 12010998:
  // 1.8e6 mm/s^3 on a G02; mixed 12013039: 386,191 mm/s^3.
  check_seeds(fuzz::ProgramKind::steps, {12016401});
  check_seeds(fuzz::ProgramKind::arcs, {12010998});
  check_seeds(fuzz::ProgramKind::mixed, {12013039});
}

TEST_CASE("ISC-3 ISC-6 KRN-3 insert stop commands every few cycles for minutes: a split no stop needs is joined again",
          "[channel][fuzz]") {
  // O, issue 33's fresh seeds: restart_here() pushed every part an insert
  // stop had ever split a block into again, so stops commanded every few
  // cycles added splits for good; the look-ahead grew to ~1,100 pieces and
  // the program never ended (arcs 12010265, lift 12012180: no end in 120 s).
  check_seeds(fuzz::ProgramKind::arcs, {12010265});
  check_seeds(fuzz::ProgramKind::lift, {12012180});
  // Contour 12006824 (dist_prog_start 2.7e-5 mm backwards while moving
  // forward) passes since N, O and P; not traced to one of them.
  check_seeds(fuzz::ProgramKind::contour, {12006824});
}

TEST_CASE("DPS-3 KRN-3 a search by distance to within round-off of a block's end: the approach ends on that end",
          "[channel][contour][fuzz]") {
  // P, issue 33: after a reset the search continued 0.4 pm before its
  // block's end; nothing was left of the block, and the approach leg ended
  // on the continuation point while the next block began on the end: a jump
  // of 4e-10 mm, 40,000.43 mm/s^3 for 40,000 (contour 7000444, 12001270,
  // 12005224; lift 12009117, 12012545: 1.00001 x j_max).
  check_seeds(fuzz::ProgramKind::contour, {7000444, 12001270, 12005224});
  check_seeds(fuzz::ProgramKind::lift, {12009117, 12012545});
}

TEST_CASE("DPS-1 KRN-6 a turn on the chord of a curve's tiny rest counts on along the curve",
          "[channel][contour][fuzz]") {
  // Q, issue 33: a turn on a curve left a rest under 10 nm, pushed as its
  // chord; a turn on that chord took it for a point off the block's motion
  // and ran a line from there to the block's end, which counts less than
  // the curve and the block it replaces. Contour 12004916 (feed hold, the
  // random PLC turning the path ~20 times on one curve) ended 6.4e-5 mm
  // short of the program's 166.1318678 mm; 6531 (insert stops) 4.9e-6 mm
  // beyond it.
  check_seeds(fuzz::ProgramKind::contour, {12004916, 6531});
}

TEST_CASE("LIFT-2 LIFT-3 LIFT-8 fresh lift seeds: a landing in time while the path brakes to a lower override, and "
          "Lifting's caps by the lift axis' true largest speed",
          "[channel][lift][fuzz]") {
  // Issue 33's fresh lift seeds 13,000,000 ..: 13005122 (Advanced
  // Lifting): the override fell from 101.4 % to 1.1 % in a full circle; the
  // path's time to the range's end was taken at the programmed velocity at
  // 1.1 % while the path still braked from 21 mm/s, Z landed a cycle after
  // the path had left the range (error "left the lift range before the lift
  // axis had landed"). 13010605 (Lifting): the caps were sized by a largest
  // lift speed of 38.5 mm/s where the profile peaks at 76 mm/s inside a
  // phase: 30,248 mm/s^3 for 30,000.
  check_seeds(fuzz::ProgramKind::lift, {13005122, 13010605});
}

TEST_CASE("LIFT-2 RIG-3 other machines: Advanced Lifting's acceleration leaves room for a velocity reversal as a ramp "
          "ends",
          "[channel][lift][fuzz]") {
  // Fresh lift seeds on other machines (channel_fuzz --vary-machine,
  // 40,200,000 ..): Z's velocity reversed 4 cycles before the lift's ramp to
  // -a ended; with its underdamped loop and Coulomb friction the drive's
  // actual acceleration went 7.2 % over the command, 834.4 mm/s^2 against
  // P-AXIS-00442's 832.5 (40200958; 40211326 alike, 943.8 for 940.9): the
  // monitor would have stopped the channel. The hardest commands the lift's
  // acceleration is planned for (axis/drive_response) now include that turn.
  check_seeds(fuzz::ProgramKind::lift, {40200958, 40211326}, true);
}

TEST_CASE("KRN-3 KRN-6 a block after a dwell that follows an arc: the arc keeps its jerk, the path stops for the dwell",
          "[channel][contour][fuzz]") {
  // T, issue 33's fresh contour seeds: N60 G02 .. / N70 #TIME 0.003 / N80
  // G01 ..: the look-ahead halved the arc's path jerk for the curvature
  // step into N80 when N80 came in, after the path had entered the arc at
  // the speed from which it could stop at full jerk; at half it could not,
  // the plan ran through the dwell at 15.5 mm/s (X 82,623 mm/s^3 for
  // 40,000). At a stop there is no curvature step to pass (13009555).
  check_seeds(fuzz::ProgramKind::contour, {13009555});
}

TEST_CASE("KRN-3 KRN-6 issue 36: near-tangent kinks three cycles apart, crossed with a = 0 at any override",
          "[channel][contour][fuzz]") {
  // Y, Z, AA, AB (docs/FUZZ.md), fresh seeds of the first cut of near-tangent joints:
  // kinks of 0.003 mm blocks in one sample (23000750, 23000886: Y jerk
  // 46,565 and 40,089 for 40,000); chains of kinks passed at cruise with
  // a != 0, then an override raise made them limiting while the path braked
  // (24002435: the corner after them run through at 8.6 mm/s, X 492,652
  // mm/s^3; lift 23001876); a kink that lets nothing pass halved the jerk
  // of a curve the path already braked on (23002858).
  check_seeds(fuzz::ProgramKind::contour, {23000750, 23000886, 24002435, 23002858});
  check_seeds(fuzz::ProgramKind::lift, {23001876});
  // AB: a kink of 1.6e-9 rad between collinear blocks, taken for round-off,
  // on a path at Z's jerk limit: 30,000.11 mm/s^3 (mixed 26001680).
  check_seeds(fuzz::ProgramKind::mixed, {26001680});
}

TEST_CASE("KRN-9 KRN-5 DPS-1 a restart standing where an HSC span begins finishes its block", "[channel][hsc][fuzz]") {
  // AC (docs/FUZZ.md): restarted after an insert stop on the start of an
  // HSC span, going backward, nothing was left to push and the block was
  // not finished; the turn there ran straight to the next block's end,
  // 1.5e-3 mm of dist_prog_start short (hsc 31002326, 30001651).
  check_seeds(fuzz::ProgramKind::hsc, {31002326, 30001651});
}

TEST_CASE("KRN-5 DPS-1 a turn on an arc whose end radius is off its start radius goes on along the arc",
          "[channel][fuzz]") {
  // W (docs/FUZZ.md): after a block search re-decoded an incremental block
  // from where the axes stood, a 321 degree G02 began 0.0015 mm off its end
  // radius; a point on it looked off the arc, the rest after a turn was a
  // straight line, and dist_prog_start changed 0.389 mm in one cycle
  // (limit 0.384): arcs 15000914.
  check_seeds(fuzz::ProgramKind::arcs, {15000914});
}

TEST_CASE("DPS-1 KRN-6 a lone corner after a tight arc keeps the arc's tangent length: the curve is no longer than "
          "what it replaces",
          "[channel][contour][fuzz]") {
  // Issue 36 item 4, before it landed: a lone corner's curve took the
  // turn's tangent length, 1 / cos(θ/2) of the chord, from the corner's
  // tangents; after a G03 of r 4.8 um the arc's tangent at the curve's
  // start was another, the curve bent out 28 % longer than the path it
  // replaced, and dist_prog_start grew 22 % slower than the axes moved
  // (contour 39000199, N940 G03 / N950 G01). Next to an arc the curve keeps
  // the chord's tangent length.
  check_seeds(fuzz::ProgramKind::contour, {39000199});
}

TEST_CASE("LIFT-2 LIFT-3 KRN-6 a full circle in the lift axis' plane before LIFT_START is not contoured into the range",
          "[channel][lift][fuzz]") {
  // X (docs/FUZZ.md): N220 G19 G03 X.. J.. K.. (Y and Z end where they
  // began: a helix of one turn) / N230 Z[LIFT_START DOWN ..] / N240 G00 ..
  // under G261: the block before the range was taken as not moving Z, the
  // curve into N240 still moved it, and the lift took Z from the programmed
  // height: 0.07 mm in a cycle, 70,142 mm/s^2 for 3,000 (lift 19001122).
  check_seeds(fuzz::ProgramKind::lift, {19001122});
}

TEST_CASE("DPS-1 KRN-6 dist_prog_start on contouring curves at arcs of 0.3 mm radius and less grows with the chord",
          "[channel][contour][fuzz]") {
  // M and U (docs/FUZZ.md): a curve counts the programmed distance of the
  // block parts it replaces (DPS-1: the blocks' lengths); at tight arcs it
  // was longer than them, so dist_prog_start grew up to 0.27 % less than the
  // chord the axes moved, where the fuzz allows contoured programs 0.1 %.
  // Contour 13006359 (G03 of r 0.075 mm, PATH_DEV 0.158), lift 8001172 (r
  // 5.6 um) and 15006312 (G02 of r 0.124 mm); contour 26000330 (G03
  // 0.27 % less) and lift 27002862 (a G03 of r 2.9 um); contour
  // 39300454 (a G02 of r 0.075 mm) and 40500275 (a G03 R0.284). Next to an
  // arc a curve now shrinks until it is no longer than the path it replaces
  // (ContourBuilder::corner_curve).
  check_seeds(fuzz::ProgramKind::contour, {13006359, 26000330, 39300454, 40500275});
  check_seeds(fuzz::ProgramKind::lift, {8001172, 15006312, 27002862});
}

TEST_CASE("DPS-2 DPS-3 a search continued before #DISTANCE PROG START CLEAR and a dwell, with no motion left: "
          "dist_prog_start starts at the continuation's distance",
          "[channel][fuzz]") {
  // V (docs/FUZZ.md): commands 15009636. A reset at the program's end,
  // then a type 4 search at what was read (block N160, 0 mm after N140
  // #DISTANCE PROG START CLEAR) moved back to N120's start with its warning
  // (11.59 mm there); the program goes on N120 #TIME 0.231 / N130 M18 /
  // N140 CLEAR / N160 M30 without motion. The interpolator reaches the
  // blocks without motion at once; the CLEAR acted then, before the dwell
  // and M18 it follows, and dist_prog_start showed 0 in the search's first
  // cycle instead of the continuation's 11.59 mm. It acts in program order now.
  check_seeds(fuzz::ProgramKind::commands, {15009636});
}

TEST_CASE("KRN-3 KRN-9 DPS-1 the piece the path runs on is planned with the piece after it: its jerk share is final",
          "[channel][hsc][fuzz]") {
  // AD (docs/FUZZ.md): the look-ahead fills over cycles (issue 36). After a
  // short cut the path ran on its only piece while the spline after it still
  // waited for its fit window; braking to the piece's end at -146 mm/s^2
  // with the whole jerk share, it got the halved share of the curvature step
  // into the spline, and a could not reach 0 before v did: the path ran
  // backward (hsc 40000192; 32 and 31002326 of the ctest ranges alike).
  check_seeds(fuzz::ProgramKind::hsc, {40000192, 32});
}

TEST_CASE("KRN-3 a turn moves what is left of the block or spline span the path stands in, however short: no jump "
          "to the block before",
          "[channel][hsc][fuzz]") {
  // AG (docs/FUZZ.md), fresh hsc seed 40510261: the path had moved 0.8e-9
  // mm into the block after a dwell when the PLC turned it back; a rest
  // below 1e-9 mm counted as none, the path went on from the programmed
  // end of the block before, and that jump put 0.8 mm/s^3 on X's jerk of
  // 40,000 as it started (the limit check allows 1e-6 of it). Only a rest
  // within the coordinates' round-off is none now. AH, fresh hsc seed
  // 40781308: alike on an HSC span, turned 0.58e-9 mm after its start; the
  // span's rest, below 1e-9 mm, was dropped and the path went back from the
  // programmed point: Y 40,000.53 mm/s^3.
  check_seeds(fuzz::ProgramKind::hsc, {40510261, 40781308});
}

TEST_CASE("DPS-1 KRN-9 a curve where a spline meets a block is no longer than the block's part it replaces, and "
          "never on an arc",
          "[channel][hsc][fuzz]") {
  // AI (docs/FUZZ.md), fresh hsc seed 41000100: a lead-in under contour
  // mode DIST turned back by 162 degrees over DIST; dist_prog_start grew by
  // 0.80 of the chord the axes moved. 41002823: a lead-out on a G02 full
  // circle, whose rest was the full circle again (one circle too far).
  check_seeds(fuzz::ProgramKind::hsc, {41000100, 41002823});
}

TEST_CASE("DPS-3 KRN-2 a program refused from where the axes stood after a reset errs when the look-ahead's decoder "
          "reaches the line, cycles after the start: the fuzz's oracle expects it until the next start",
          "[channel][contour][fuzz]") {
  // AF (docs/FUZZ.md), fresh contour seed 40301643: after each of three
  // resets the program, decoded from where the axes stood, has N390's arc
  // off its circle (error 21758), as the oracle's own decoding says; the
  // look-ahead fills 4 blocks a cycle, so the channel's error came ~10
  // cycles after the start, when the oracle no longer expected it. An
  // oracle fault, not the channel's.
  check_seeds(fuzz::ProgramKind::contour, {40301643});
}

TEST_CASE("KRN-5 DPS-1 a turn at a full circle's start on a tiny rest of it runs the whole circle",
          "[channel][fuzz]") {
  // AK (docs/FUZZ.md): backward along a G03 full circle (its start is its
  // end), the path stood on a 2.4e-14 mm rest of it at its start when the
  // PLC turned it forward. Which end of the circle it stood at was told by
  // where it stood in that rest, not in the block: taken for the circle's
  // end, the turn skipped the circle (dist_prog_start 319.06 mm at the end
  // for a program of 373.42).
  check_seeds(fuzz::ProgramKind::arcs, {42301617}, true);
}

TEST_CASE("LIFT-2 RIG-3 a lift rising fast over a crawling path keeps a_max: its path parameter is not lost "
          "in the program's covered distance",
          "[channel][lift][fuzz]") {
  // AL (docs/FUZZ.md): Advanced Lifting over 1.6 um blocks, the path at
  // 3.9 um/s and Z at a_max along its profile. The path parameter was the
  // program's covered distance so far plus the front's part, less the
  // range's start: 5e-14 mm of round-off, which dz/dq (some 8,000) made
  // 1.2e-6 of a_max in Z's sampled acceleration.
  check_seeds(fuzz::ProgramKind::lift, {43300505, 43303849}, true);
}

namespace {

// A corpus program (tests/programs/NAME.nc) as cam_programs' `hsc+g261`
// way runs it: G261 and #HSC ON [BSPLINE MERGE=1] within 0.01 mm, after its
// first G90 line.
std::string with_hsc_and_g261(const std::string& name) {
  std::ifstream in(std::string(HIL_SOURCE_DIR) + "/tests/programs/" + name + ".nc");
  std::string text, line;
  bool done = false;
  while (std::getline(in, line)) {
    text += line + "\n";
    const size_t g90 = line.find("G90");
    if (!done && g90 != std::string::npos && line.find(';') > g90) {
      text += "#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n";
      done = true;
    }
  }
  return text;
}

// Runs `program` with each seed's PLC, as `channel_fuzz --program` does.
void check_program_seeds(const std::string& program, std::initializer_list<uint64_t> seeds) {
  fuzz::FuzzOptions options;
  options.program_text = program;
  for (uint64_t seed : seeds) {
    const fuzz::FuzzRun run = fuzz::run_channel_fuzz_isolated(seed, options);
    for (const fuzz::Failure& f : run.failures) FAIL_CHECK(fuzz::describe(run, f));
    CHECK(run.passed());
  }
}

}  // namespace

TEST_CASE("KRN-3 KRN-5 DPS-1 a braking never runs the path backward when a jerk share comes to the piece it brakes in",
          "[channel][hsc][fuzz]") {
  // AJ (docs/FUZZ.md), fresh seeds on corpus programs under G261 and HSC:
  // the path set off or braked in a piece and a feed hold, a turn or a lower
  // override came; then the piece pushed behind it made a curvature step,
  // halving the jerk the braking began with. The path ran 2e-5 .. 1e-4 mm
  // past its stop and back, dist_prog_start falling while forward. The last
  // piece is now planned at the step's share until what follows is known.
  check_program_seeds(with_hsc_and_g261("surfacing_3d"), {41200025, 41200055, 41200056});
  check_program_seeds(with_hsc_and_g261("public/jscut_jsdc"), {41200063, 41810009});
}
