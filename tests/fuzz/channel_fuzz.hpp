#pragma once
// Channel-level fuzz (KRN-3, DDTG-1, KRN-5, DPS-1): a seeded random NC
// program (program_generator.hpp) runs on hil::cnc::Channel cycle by cycle,
// through its public API only, while a seeded random PLC plays the HLI:
// feed hold, override 0 .. 120 % (0.1 % steps, enable_w on and off, now and
// then ramped every few cycles), delete distance to go edges with and
// without activation masks (held a few cycles, until the short cut runs, or
// long), the backward_motion level, late M acknowledgements (up to 2 s,
// now and then without enable_w or unasked). After a random phase the PLC
// turns calm (no feed hold, override >= 30 %, forward, prompt
// acknowledgements) so that the program ends. Every cycle is checked:
//
//  - Channel::check_invariants(): the interpolator's block cursors keep
//    their meaning (issue 35);
//  - no exception leaves Channel::step (a crash or a hang is caught by
//    run_channel_fuzz_isolated); setpoints and HLI values finite;
//  - each axis' commanded velocity, acceleration and jerk, as finite
//    differences of the commanded positions per cycle, within v_max, a_max,
//    j_max: logger::LimitChecker (RIG-4's offline check) fed every cycle's
//    setpoints and HLI state (in cycles with lift_active an axis may use
//    the lift's overload range, LIFT-2: a up to P-AXIS-00442's limit, j up
//    to j_max * max(1, P-AXIS-00442 / 1000)). Its only slack is round-off: relative 1e-6 of the limit plus
//    2^n ulp / T^n for the n-th difference. No allowance for discretisation
//    is needed: the n-th difference of a sampled motion is a weighted mean
//    of its n-th derivative, so it never exceeds the true maximum;
//  - dist_prog_start (DPS-1, KRN-5, DPS-2): never decreases while the path
//    moves forward, never increases while it moves backward (backward
//    travel is counted off), changes by at most the main axes' path velocity
//    limit times T in a cycle, and - in programs without #DISTANCE PROG
//    START OFF/CLEAR - by at least the chord the main axes moved (the path
//    is never shorter than its chord). Exempt: the cycle in which
//    block_count_r passes a CLEAR line and the next (a short cut starts
//    after the cycle's interpolation; DDTG-7 runs the skipped lines then),
//    and, with CLEAR in the program, values within one cycle's travel of 0
//    (the path can pass a CLEAR and turn back within one cycle,
//    block_count_r showing neither). "Moving backward" is
//    backward_motion.state_r in this and the previous cycle;
//  - every event raised by the program (not the PLC's override or program
//    start warnings) names an NC line of the program; no error event (the
//    programs are valid, no drive error is injected); m_function_nr_r is
//    one of the program's M functions; block_count_r a line of it;
//  - the run ends (finished(), PROGRAM_END) within a bound: the random
//    phase, then 1.5 x (every block rest to rest at 30 % override, one
//    short cut across the program's extent at its slowest feed and 30 %,
//    the dwells, 8 ms per M function, 2 s) + 1000 cycles;
//  - DPS-3 (resets and block searches by the PLC): the cycle a reset acts
//    (reset.state_r: dist_prog_start 0) and the cycle a program starts (a
//    search presets the continuation's distance), and the cycles after
//    them, are exempt from the dist_prog_start steps; no chord while
//    repositioning (the approach covers no distance), nor after backward
//    motion following a search (the path may run back onto the approach);
//    the error event of a failed search (state 3 in that cycle) is allowed,
//    no other; a type 4 search continues at the distance asked (or, moved
//    to the block's start, at a larger one) and presets dist_prog_start to
//    it; each reset adds a whole calm run to the cycle bound; after a reset
//    the end point is the decoder's from where the axes stood at the last
//    start (Z of lift programs left out) and the final dist_prog_start is
//    not compared;
//  - at the end the axes stand on the program's end point within 1e-9 mm
//    (unless a short cut ended motion early, 50810, DDTG-6); after a run
//    without delete distance to go requests and (with OFF/CLEAR in the
//    program) without backward motion, dist_prog_start is the program's
//    main-axis path length counted as DPS-2 says (the generator's own
//    geometry, 1e-6 mm + 1e-9 relative); three more cycles move nothing.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "channel.hpp"
#include "program_generator.hpp"

namespace hil::fuzz {

struct FuzzOptions {
  // None: by seed, all kinds in turn (seed % 5).
  std::optional<ProgramKind> kind;
  int min_items = 4;
  int max_items = 24;
  bool random_plc = true;  // false: program start and prompt M acknowledgements only
  // Random insert stop commands (ISC-1 .. ISC-9) from the PLC, on a random
  // stream of their own: false runs every seed exactly as before them.
  bool insert_stops = true;
  // Resets with block searches (DPS-3) from the PLC, on a random stream of
  // their own: false runs every seed exactly as before them.
  bool block_search = true;
  // Called after every step with its events (the bench's --trace, golden traces).
  std::function<void(int64_t cycle, const cnc::Channel& channel, const HliControl& control,
                     const std::vector<Event>& events)>
      observer;
  // Instead of the generated program, this text (a shrunk one, the bench's
  // --minimize), with the seed's PLC; the end point and the final
  // dist_prog_start are not checked (the generator's expectations are gone).
  std::optional<std::string> program_text;
  std::optional<int64_t> chaos_cycles;  // instead of the seed's
  // Other machines: each axis' v, a and j drawn from the seed, on a stream
  // of its own, around the fuzz machine's (machine_of); false runs every
  // seed on the machine it always had.
  bool vary_machine = false;
};

struct Failure {
  std::string invariant;  // "limit", "drive", "exception", "finite", "dist_prog_start", "end position", "event", "end", "invariant"
  int64_t cycle = -1;
  std::string axis;
  std::string quantity;
  double value = 0;
  double limit = 0;
  int64_t nc_line = 0;  // the block in the interpolator then (block_count_r), 0 = none
  std::string detail;
};

struct PlcCounts {
  int64_t feedhold_edges = 0, override_changes = 0, ddtg_edges = 0, backward_toggles = 0, m_acks = 0;
  int64_t insert_commands = 0, insert_stops = 0;  // ISC: commands written with the semaphore, stops continued
  int64_t resets = 0, searches = 0, search_errors = 0;  // DPS-3: resets that acted, searching starts, state 3
};

struct FuzzRun {
  uint64_t seed = 0;
  ProgramKind kind = ProgramKind::mixed;
  GeneratedProgram program;
  int32_t override_max_percent = 100;
  bool varied_machine = false;  // FuzzOptions::vary_machine
  int64_t chaos_cycles = 0;  // the random PLC phase; calm after it
  int64_t cycle_bound = 0;
  int64_t restart_cycles = 0;  // added to the bound for each reset that acted (DPS-3): a whole calm run
  int64_t last_motion_line = 0;
  int64_t cycles = 0;        // stepped
  bool finished = false;
  bool expectations = true;  // the generator's end point and dist_prog_start apply
  // What the run went through (from the HLI).
  bool short_cut = false, backward = false, m_output = false;
  int64_t events = 0;
  int64_t search_error_events = 0;  // DPS-3: error events of failed block searches (allowed)
  // DPS-3: type 4 searches at what the PLC read at the stop that found a
  // continuation; of them, those whose approach moved the axes more than
  // 1 um (the starting movement counts, docs/BLOCK_SEARCH.md), the longest.
  int64_t at_stop_searches = 0, at_stop_moved = 0;
  double at_stop_approach_max_mm = 0;
  // Starts and searches after a reset whose decoding from where the axes
  // stood failed (a first arc or G91 motion valid only from 0): expected.
  int64_t restart_decode_errors = 0;
  std::vector<std::string> event_log;  // the first events: "cycle k: <event>"
  PlcCounts plc;
  std::vector<Failure> failures;
  bool passed() const { return failures.empty(); }
};

// The run of `seed` planned (program, PLC phase, cycle bound), not run.
FuzzRun prepare_channel_fuzz(uint64_t seed, const FuzzOptions& options = {});
// The run of `seed`: prepared and run in this process.
FuzzRun run_channel_fuzz(uint64_t seed, const FuzzOptions& options = {});
// The same in a child process (fork), so that a crash or a hang of the
// channel becomes a failure of this run ("crash": the signal; a hang is
// ended by SIGPROF after timeout_s of CPU time) instead of ending the caller.
FuzzRun run_channel_fuzz_isolated(uint64_t seed, const FuzzOptions& options = {}, unsigned timeout_s = 120);

// One line: cycle, axis, quantity, value, limit, NC line and its text.
std::string describe(const FuzzRun& run, const Failure& failure);

}  // namespace hil::fuzz
