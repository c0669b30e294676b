// KRN-3, DDTG-1, KRN-5, DPS-1: the channel fuzz (tests/fuzz/channel_fuzz.hpp)
// with a fixed seed set; bench/channel_fuzz runs it long.
#include <catch2/catch.hpp>

#include <chrono>
#include <iostream>

#include "channel_fuzz.hpp"
#include "decoder.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::fuzz;

TEST_CASE("channel fuzz: the generator writes programs the decoder takes, the same for a seed", "[fuzz]") {
  const MachineConfig m = xyz_fuzz_machine();
  std::string all;
  for (uint64_t seed = 1; seed <= 100; ++seed) {
    const ProgramKind kind = all_program_kinds[seed % std::size(all_program_kinds)];
    const GeneratedProgram p = generate_program(seed, {kind, 4, 24}, m);
    INFO("seed " << seed << "\n" << p.text);
    CHECK(p.text == generate_program(seed, {kind, 4, 24}, m).text);
    const cnc::DecodedProgram d = cnc::decode_program(p.text, m, {0, 0, 0});
    REQUIRE_FALSE(d.error);
    CHECK(p.lines.back().find("M30") != std::string::npos);
    all += p.text;
  }
  for (const char* feature : {"G00 ", "G01 ", "G02 ", "G03 ", "G91", "G90", " F", " M1", "#TIME ", "#DEL DIST2GO",
                              "[END=", "#DISTANCE PROG START ON", "#DISTANCE PROG START OFF",
                              "#DISTANCE PROG START CLEAR", "#SLOPE"})
    CHECK(all.find(feature) != std::string::npos);
}

namespace {

struct SeedRange {
  int64_t runs = 0, cycles = 0, failed = 0, short_cuts = 0, backward = 0, m_output = 0, resets = 0, searches = 0;
};

// Runs seeds first .. first + runs - 1, reports every failure (at most 40)
// and prints what the random PLC did.
SeedRange run_seeds(int64_t first, int64_t runs, const FuzzOptions& options, const char* name) {
  SeedRange r;
  r.runs = runs;
  int64_t shown = 0, random_plc = 0;
  PlcCounts plc;
  const auto t0 = std::chrono::steady_clock::now();
  for (int64_t seed = first; seed < first + runs; ++seed) {
    const FuzzRun run = run_channel_fuzz_isolated(static_cast<uint64_t>(seed), options);
    r.cycles += run.cycles;
    r.short_cuts += run.short_cut;
    r.backward += run.backward;
    r.m_output += run.m_output;
    random_plc += run.chaos_cycles > 0;
    plc.feedhold_edges += run.plc.feedhold_edges;
    plc.override_changes += run.plc.override_changes;
    plc.ddtg_edges += run.plc.ddtg_edges;
    plc.backward_toggles += run.plc.backward_toggles;
    plc.m_acks += run.plc.m_acks;
    plc.insert_commands += run.plc.insert_commands;
    plc.insert_stops += run.plc.insert_stops;
    plc.resets += run.plc.resets;
    plc.searches += run.plc.searches;
    plc.search_errors += run.plc.search_errors;
    r.resets += run.plc.resets;
    r.searches += run.plc.searches;
    if (run.passed()) continue;
    ++r.failed;
    for (const Failure& f : run.failures)
      if (++shown <= 40)
        FAIL_CHECK(describe(run, f) << "\n  reproduce: build/bin/channel_fuzz --seed " << seed << " --runs 1"
                                    << (options.kind ? std::string(" --program-kind ") + to_string(*options.kind) : "")
                                    << (options.vary_machine ? " --vary-machine" : "") << " --print-program");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "channel fuzz (" << name << "): " << runs << " runs (seeds " << first << " .. " << first + runs - 1
            << "), " << r.cycles << " cycles in " << seconds << " s; " << random_plc << " with the random PLC ("
            << plc.feedhold_edges << " feed hold edges, " << plc.override_changes << " override changes, "
            << plc.ddtg_edges << " delete distance to go edges, " << plc.backward_toggles
            << " backward motion toggles, " << plc.m_acks << " M acknowledgements, " << plc.insert_commands
            << " insert stop commands, " << plc.insert_stops << " stops continued, " << plc.resets << " resets, "
            << plc.searches << " block searches, " << plc.search_errors << " of them failed), " << r.short_cuts
            << " with a short cut, " << r.backward << " with backward motion, " << r.m_output
            << " with M functions; " << r.failed << " failed\n";
  return r;
}

}  // namespace

TEST_CASE("KRN-3 DDTG-1 KRN-5 DPS-1 ISC-3 DPS-3 channel fuzz: random programs and PLC edges keep every axis' limits and "
          "the channel's invariants, cycle by cycle",
          "[fuzz]") {
  // Seeds 1 .. 2500, the program kinds in turn (mixed, lines, arcs, steps,
  // commands), each with its random PLC (feed hold, override 0 .. 120 %,
  // delete distance to go with and without activation masks, backward
  // motion, late M acknowledgements, insert stop commands, resets with
  // block searches), checked as tests/fuzz/channel_fuzz.hpp says.
  const SeedRange r = run_seeds(1, 2500, FuzzOptions{}, "all kinds");
  CHECK(r.failed == 0);
  CHECK(r.searches > r.runs / 20);  // DPS-3
  // The fuzz reaches what it is for.
  CHECK(r.short_cuts > r.runs / 10);
  CHECK(r.backward > r.runs / 10);
  CHECK(r.m_output > r.runs / 10);
  CHECK(r.cycles > 10'000'000);
}

TEST_CASE("KRN-6 KRN-3 KRN-5 DPS-1 channel fuzz, contour kind: polynomial contouring under the random PLC keeps "
          "every axis' limits",
          "[fuzz][contour]") {
  // #CONTOUR MODE, G261/G260/G61, G60/G360/G359 over CAM polylines, near-
  // collinear joints and reversals; backward motion and turns inside the
  // curves, insert stops splitting them (docs/CONTOURING.md).
  FuzzOptions options;
  options.kind = ProgramKind::contour;
  const SeedRange r = run_seeds(1, 400, options, "contour");
  CHECK(r.failed == 0);
  CHECK(r.backward > r.runs / 10);
  CHECK(r.short_cuts > r.runs / 10);
}

TEST_CASE("KRN-9 KRN-3 KRN-5 DPS-1 ISC-3 DDTG-1 channel fuzz, hsc kind: HSC splines under the random PLC keep "
          "every axis' limits",
          "[fuzz][hsc]") {
  // #HSC ON [BSPLINE ..] with its parameters, #HSC OFF, over CAM polylines
  // rounded to 3 or 4 decimals, G00, arcs, M functions, G60 and G261 among
  // them; feed hold, override, short cuts, insert stops, backward motion
  // (docs/HSC.md).
  FuzzOptions options;
  options.kind = ProgramKind::hsc;
  const SeedRange r = run_seeds(1, 300, options, "hsc");
  CHECK(r.failed == 0);
  CHECK(r.backward > r.runs / 10);
  CHECK(r.short_cuts > r.runs / 10);
}

TEST_CASE("LIFT-1 LIFT-2 LIFT-3 LIFT-5 LIFT-8 channel fuzz, lift kind: both lift methods under the random PLC keep "
          "every axis' limits (the lift axis' jerk within j_max, its acceleration in the overload range where the "
          "text allows it, its drive below P-AXIS-00442) and land on POS",
          "[fuzz][lift]") {
  // Lift ranges, single-block lifts, G91, DOWN, POS beyond POS_LIMIT,
  // #FLUSH, ranges left open to M30, around XY motion, M functions and
  // dwells; feed hold, override, short cuts, insert stops (docs/LIFT.md);
  // three Z drives, a stiff one among them (docs/FUZZ.md).
  FuzzOptions options;
  options.kind = ProgramKind::lift;
  const SeedRange r = run_seeds(1, 1000, options, "lift");
  CHECK(r.failed == 0);
  CHECK(r.short_cuts > r.runs / 20);
  CHECK(r.m_output > r.runs / 10);
}

TEST_CASE("KRN-3 KRN-6 KRN-9 LIFT-2 channel fuzz on other machines: each axis' v, a and j drawn from the seed keep "
          "every limit",
          "[fuzz][machines]") {
  // FuzzOptions::vary_machine: v 0.25..2x, a 0.25..4x, j 0.2..5x the fuzz
  // machine's, each axis on its own (channel_fuzz --vary-machine; its first
  // fresh seeds found the lift's drive reserve short, docs/FUZZ.md).
  FuzzOptions options;
  options.vary_machine = true;
  CHECK(run_seeds(1, 300, options, "all kinds, varied machines").failed == 0);
  for (const auto& [kind, runs] : {std::pair{ProgramKind::contour, 100}, {ProgramKind::hsc, 100}, {ProgramKind::lift, 300}}) {
    options.kind = kind;
    CHECK(run_seeds(1, runs, options, to_string(kind)).failed == 0);
  }
}

TEST_CASE("channel fuzz: a run without an end is ended by its CPU time limit, a failure that says so", "[fuzz]") {
  // 500 mm at 6 mm/min: 5,000 s of path, millions of cycles; 1 s of CPU
  // time is the limit. CPU time, not wall time: a loaded machine must not
  // fail the long seeds (the 120 s default).
  FuzzOptions options;
  options.random_plc = false;
  options.insert_stops = false;
  options.block_search = false;
  options.program_text = "N10 G01 X500 F6\nM30\n";
  const auto t0 = std::chrono::steady_clock::now();
  const FuzzRun run = run_channel_fuzz_isolated(1, options, 1);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE(run.failures.size() == 1);
  CHECK(run.failures[0].invariant == "crash");
  CHECK(run.failures[0].detail.find("no end within 1 s of CPU time") != std::string::npos);
  CHECK(wall_s < 60);
}

TEST_CASE("KRN-8 KRN-3 KRN-5 DPS-3 channel fuzz, a program of its own: the corpus' real CAM output and a program "
          "with T, S and M functions under the random PLC keep every limit and end",
          "[fuzz][corpus]") {
  // channel_fuzz --program: the PLC acknowledges T, S and H functions the
  // cycle after their request, and the M functions a program may output
  // are its own (a corpus program's T6 M06 waited for its acknowledgement
  // until the cycle bound; its M06 was taken for one it does not have).
  FuzzOptions options;
  options.program_text = "G90 G71\nT6 M06\nD6\nS14000 M03\nM07\nG01 X10 Y5 F3000\nX20 Y0\nH20\nX0\nM05\nM30\n";
  CHECK(run_seeds(1, 40, options, "program with T, S, H and M").failed == 0);
  options.program_text =
      "#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n" + test::source_text("tests/programs/public/jscut_tball.nc");
  CHECK(run_seeds(1, 4, options, "jscut_tball with #HSC").failed == 0);
}
