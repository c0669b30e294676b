#pragma once
// Seeded random NC programs for the channel fuzz (tests/unit/channel_fuzz_test.cpp,
// bench/channel_fuzz.cpp): G00/G01 lines, G02/G03 arcs in the XY plane
// (centre by I/J relative to the start, end on the circle; full circles,
// helices, tangent chains), G91 sections and back to G90, F changes, M
// functions alone and with motion, #TIME dwells, #DEL DIST2GO [END=..]
// markers, #DISTANCE PROG START ON/OFF/CLEAR, #SLOPE TRAPEZ/SIN2; tiny
// (1 um) and long blocks, short collinear steps and reversals; M30 at the
// end. Every line is one block with its own N number (N10, N20, ..), so the
// HLI's block_count_r is the NC line (no $FOR loops are generated).
//
// Only programs the decoder accepts are generated: every number written is
// read back as the decoder reads it (strtod) and the position is tracked as
// the decoder computes it, so the expected end point is exact.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "machine_config.hpp"

namespace hil::fuzz {

enum class ProgramKind {
  mixed,     // everything below, mixed
  lines,     // G00/G01 lines: long, short, tiny, corners, G91 sections, F changes
  arcs,      // G02/G03: random, tangent chains (curvature steps), full circles, helices, tiny
  steps,     // short collinear steps with reversals, tiny blocks (the look-ahead's braking)
  commands,  // lines with many M functions, dwells, #DEL DIST2GO markers, #DISTANCE PROG START
  // KRN-6: #CONTOUR MODE (DEV, DIST, ON/OFF), G261/G260/G61, G60/G360/G359
  // over polylines of tiny chords, near-collinear joints and reversals, with
  // the other items now and then. Chosen by name only (--program-kind
  // contour): the by-seed rotation keeps its five kinds, so that the seeds
  // of known failures still make the same programs.
  contour,
  // LIFT-1 .. LIFT-5: lift ranges (Z[LIFT_START ..] .. Z[LIFT_END], the
  // single-block Z[LIFT ..], G91, DOWN with Advanced Lifting, POS beyond
  // POS_LIMIT, #FLUSH inside, a range left open to M30) around XY lines,
  // arcs, M functions, dwells and markers; the machine lifts time-based
  // on even seeds, path-based on odd ones. Chosen by name only.
  lift,
  // KRN-9: #HSC ON [BSPLINE ..] (PATH_DEV, MERGE, MAX_ANGLE, AUTO_OFF_*,
  // MAX_PATH_LENGTH), #HSC OFF, over CAM polylines rounded to 3 or 4
  // decimals, near-collinear joints, corners and reversals, with the other
  // items (G00, arcs, M functions, dwells, G60) ending splines. By name only.
  hsc,
};
constexpr ProgramKind all_program_kinds[] = {ProgramKind::mixed, ProgramKind::lines, ProgramKind::arcs,
                                             ProgramKind::steps, ProgramKind::commands};
constexpr ProgramKind named_program_kinds[] = {ProgramKind::mixed,    ProgramKind::lines,   ProgramKind::arcs,
                                               ProgramKind::steps,    ProgramKind::commands, ProgramKind::contour,
                                               ProgramKind::lift,     ProgramKind::hsc};
const char* to_string(ProgramKind kind);
std::optional<ProgramKind> parse_program_kind(const std::string& name);

struct ProgramOptions {
  ProgramKind kind = ProgramKind::mixed;
  int min_items = 4;   // generator items (one to a dozen lines each)
  int max_items = 24;
};

struct GeneratedProgram {
  std::string text;
  std::vector<std::string> lines;  // lines[i] is NC line i + 1
  // Where the program leaves the axes (machine axis order), as the decoder
  // computes it: the path ends exactly here unless a short cut ended the
  // motion early (DDTG-6).
  std::vector<double> end_position;
  // dist_prog_start at the end if the program runs once, forward, without a
  // short cut: the main-axis path lengths (lines: chord, arcs: R * sweep
  // with the helix' Z), counted while ON, reset by CLEAR (DPS-1, DPS-2).
  // Computed here from the intended geometry, not by the kernel's code.
  double dist_prog_start_end_mm = 0;
  std::vector<int64_t> clear_lines;  // lines of #DISTANCE PROG START CLEAR
  bool has_dps_off = false;          // some #DISTANCE PROG START OFF
  // Polynomial contouring somewhere (KRN-6): on a contouring curve
  // dist_prog_start counts the programmed distance the curve replaces, so
  // where the curve is longer it grows slower than the path moves.
  bool contoured = false;
  // An HSC spline somewhere (KRN-9): over a polyline that bends, the spline
  // is longer than its chords (an arc over chords turning by θ each:
  // θ / (2 sin(θ/2)), 1.1 % for the generator's sharpest, 29°).
  bool hsc = false;
  // Lift ranges (LIFT-1): the last motion block's end is not the program's
  // end on the lift axis, which lands on POS after it; a short cut past a
  // lift command is refused (DDTG-8: 51016) and ends the run in ERROR.
  bool lifts = false;
  std::vector<int> m_functions;      // every M function output (not M30), in order
  int motion_blocks = 0;
  double dwell_s = 0;                // sum of #TIME
  double path_length_mm = 0;         // sum of block lengths
};

// G261, G61, #CONTOUR MODE ON (KRN-6) or #HSC ON (KRN-9) on the line.
bool switches_contouring_on(const std::string& line);
bool switches_hsc_on(const std::string& line);

GeneratedProgram generate_program(uint64_t seed, const ProgramOptions& options, const MachineConfig& machine);

// The 3-axis machine of config/xyz_machine.yaml, built in code (the bench
// runs from anywhere): X, Y 250 mm/s, 2000 mm/s^2, 40000 mm/s^3; Z 150,
// 1500, 30000; cycle 1 ms; fb_storage_size 1,000,000 (DDTG and backward
// motion available).
MachineConfig xyz_fuzz_machine(int32_t override_max_percent = 100, LiftMethod lift = LiftMethod::none);

}  // namespace hil::fuzz
