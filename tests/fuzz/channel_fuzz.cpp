#include "channel_fuzz.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

#include "decoder.hpp"
#include "drive_model.hpp"
#include "fuzz_plc.hpp"
#include "fuzz_rng.hpp"
#include "limit_check.hpp"
#include "path_segment.hpp"
#include "position_profile.hpp"

namespace hil::fuzz {
namespace {

// Seconds the program needs at 100 %, every block from rest to rest: more
// than the look-ahead needs.
double rest_to_rest_time(const std::vector<cnc::Block>& blocks, const MachineConfig& machine) {
  double t = 0;
  for (const cnc::Block& b : blocks) {
    if (!b.has_motion) continue;
    const cnc::PathSegment segment(b.motion, machine);
    cnc::Limits lim = segment.limits();
    lim.v = segment.programmed_velocity();
    lim.j *= 0.5;  // next to a curvature step a block gets half its path jerk
    t += cnc::rest_to_rest(segment.length(), lim, b.slope).duration();
  }
  return t;
}

bool finite(double x) { return std::isfinite(x); }

}  // namespace

std::string describe(const FuzzRun& run, const Failure& f) {
  std::ostringstream out;
  out.precision(10);
  out << "seed " << run.seed << " (" << to_string(run.kind) << "): " << f.invariant;
  if (f.cycle >= 0) out << ", cycle " << f.cycle;
  if (!f.axis.empty()) out << ", axis " << f.axis;
  if (!f.quantity.empty()) out << ", " << f.quantity << " " << f.value << " (limit " << f.limit << ")";
  if (f.nc_line > 0) {
    out << ", NC line " << f.nc_line;
    if (f.nc_line <= static_cast<int64_t>(run.program.lines.size()))
      out << " '" << run.program.lines[f.nc_line - 1] << "'";
  }
  if (!f.detail.empty()) out << ": " << f.detail;
  return out.str();
}

// With FuzzOptions::vary_machine, each axis' limits are drawn around the
// fuzz machine's: v 0.25..2x, a 0.25..4x, j 0.2..5x, log-uniform, each on
// its own (axes of unlike dynamics, slow and fast machines).
void draw_axis_limits(MachineConfig& m, uint64_t seed) {
  Rng rng(seed ^ 0x6d616368696e65);  // "machine"
  for (AxisConfig& axis : m.axes) {
    axis.v_max = axis.v_rapid = axis.v_max * rng.log_uniform(0.25, 2);
    axis.a_max *= rng.log_uniform(0.25, 4);
    axis.j_max *= rng.log_uniform(0.2, 5);
  }
  m.name += " (varied)";
}

// Lift programs run on a machine that lifts time-based (even seeds) or
// path-based, with one of three Z drives by seed / 2 (LIFT-2: Advanced
// Lifting plans for the drive): config/xyz_machine.yaml's; a stiff one
// (j_max 90,000, P-AXIS-00441 / 00442 1500 / 1600); a second-order velocity
// loop with little damping and Coulomb friction.
MachineConfig machine_of(const FuzzRun& run) {
  const bool lift = run.kind == ProgramKind::lift;
  LiftMethod method = LiftMethod::none;
  if (lift) method = run.seed % 2 == 0 ? LiftMethod::time_based : LiftMethod::path_based;
  MachineConfig m = xyz_fuzz_machine(run.override_max_percent, method);
  if (run.varied_machine) draw_axis_limits(m, run.seed);
  if (!lift) return m;
  AxisConfig& z = m.axes[2];
  switch (run.seed / 2 % 3) {
    case 1:
      z.j_max = 90000;
      z.kv = 40;
      z.velocity_lag_s = 0.002;
      z.dyn_monitoring_a_warn = 1500;
      z.dyn_monitoring_a_err = 1600;
      break;
    case 2:
      z.velocity_loop_order = 2;
      z.velocity_lag_s = 0.0015;
      z.velocity_damping = 0.5;
      z.kv = 30;
      z.friction_coulomb = 50;
      break;
    default:
      break;
  }
  return m;
}

FuzzRun prepare_channel_fuzz(uint64_t seed, const FuzzOptions& options) {
  FuzzRun run;
  run.seed = seed;
  Rng rng(seed);
  run.kind = options.kind ? *options.kind : all_program_kinds[seed % std::size(all_program_kinds)];
  run.override_max_percent = rng.chance(0.5) ? 100 : 120;
  run.varied_machine = options.vary_machine;
  const MachineConfig machine = machine_of(run);
  const double dt = machine.cycle_time_s();
  run.program = generate_program(mix_seed(seed ^ 0x5eed), {run.kind, options.min_items, options.max_items}, machine);
  run.expectations = !options.program_text;
  if (options.program_text) {
    GeneratedProgram& p = run.program;
    p.text = *options.program_text;
    p.lines.clear();
    p.clear_lines.clear();
    p.has_dps_off = false;
    p.contoured = false;
    p.hsc = false;
    for (size_t begin = 0; begin < p.text.size();) {
      const size_t end = std::min(p.text.find('\n', begin), p.text.size());
      p.lines.push_back(p.text.substr(begin, end - begin));
      begin = end + 1;
    }
    for (size_t i = 0; i < p.lines.size(); ++i) {
      if (p.lines[i].find("#DISTANCE PROG START CLEAR") != std::string::npos)
        p.clear_lines.push_back(static_cast<int64_t>(i) + 1);
      p.has_dps_off = p.has_dps_off || p.lines[i].find("#DISTANCE PROG START OFF") != std::string::npos;
      p.contoured = p.contoured || switches_contouring_on(p.lines[i]);
      p.hsc = p.hsc || switches_hsc_on(p.lines[i]);
    }
    // Its own M functions, not the generated program's (a corpus program's
    // M06, M03, M07 were taken for M functions the program does not have).
    p.m_functions.clear();
    for (const cnc::Block& b : cnc::decode_program(p.text, machine, std::vector<double>(machine.axes.size(), 0.0)).blocks)
      for (const cnc::MFunction& f : b.m_functions)
        if (f.address == 'M') p.m_functions.push_back(f.nr);
  }
  const GeneratedProgram& program = run.program;

  // The generator's own check: the decoder takes the program and ends where
  // the generator says.
  const cnc::DecodedProgram decoded =
      cnc::decode_program(program.text, machine, std::vector<double>(machine.axes.size(), 0.0));
  if (decoded.error) {
    run.failures.push_back(
        {"generator", -1, "", "", 0, 0, decoded.error->nc_line, "the decoder refuses: " + decoded.error->message});
    return run;
  }
  for (const cnc::Block& b : decoded.blocks)
    if (b.has_motion) run.last_motion_line = b.nc_line;
  for (auto b = decoded.blocks.rbegin(); run.expectations && b != decoded.blocks.rend(); ++b) {
    if (!b->has_motion) continue;
    std::vector<double> end = b->motion.end;
    if (program.lifts) end[2] = program.end_position[2];  // Z lands on POS after it (LIFT-1)
    if (end != program.end_position)
      run.failures.push_back({"generator", -1, "", "", 0, 0, b->nc_line, "end point differs from the decoder's"});
    break;
  }

  const double t100 = rest_to_rest_time(decoded.blocks, machine);
  const int64_t program_cycles = static_cast<int64_t>(std::ceil(t100 / dt));
  run.chaos_cycles = !options.random_plc || rng.chance(0.15) ? 0 : rng.integer(0, program_cycles * 3 / 2 + 500);
  if (options.chaos_cycles) run.chaos_cycles = *options.chaos_cycles;
  // Calm: at >= 30 % override every block rest to rest, dwells, M functions
  // acknowledged within 6 cycles, 2 s for stops and turns; 50 % margin.
  // A short cut still running then goes up to across the program's
  // extent at its slowest feed (DDTG-2: a G00 block's short cut takes the
  // interrupted block's feed).
  double slowest = std::numeric_limits<double>::infinity(), extent_sq = 0;
  std::vector<double> low(machine.axes.size(), 0.0), high(machine.axes.size(), 0.0);
  for (const cnc::Block& b : decoded.blocks) {
    if (!b.has_motion) continue;
    if (b.motion.feed > 0) slowest = std::min(slowest, b.motion.feed);
    const int first = b.motion.plane[0] >= 0 ? b.motion.plane[0] : 0, second = b.motion.plane[1] >= 0 ? b.motion.plane[1] : 1;
    const double r = std::hypot(b.motion.start[first] - b.motion.center[0], b.motion.start[second] - b.motion.center[1]);
    for (size_t i = 0; i < low.size(); ++i) {
      const double reach = b.motion.type == cnc::MotionType::arc_cw || b.motion.type == cnc::MotionType::arc_ccw ? r : 0;
      low[i] = std::min({low[i], b.motion.end[i] - reach, b.motion.start[i] - reach});
      high[i] = std::max({high[i], b.motion.end[i] + reach, b.motion.start[i] + reach});
    }
  }
  for (size_t i = 0; i < low.size(); ++i) extent_sq += (high[i] - low[i]) * (high[i] - low[i]);
  const double short_cut_s = std::isfinite(slowest) ? std::sqrt(extent_sq) / slowest * 1000.0 / calm_override_min : 0;
  const double calm_s = t100 * 1000.0 / calm_override_min + short_cut_s + program.dwell_s +
                        0.008 * static_cast<double>(program.m_functions.size()) + 2.0;
  run.restart_cycles = static_cast<int64_t>(std::ceil(1.5 * calm_s / dt)) + 1000 +
                       (options.insert_stops && options.random_plc ? 3000 : 0);  // a last stop, its continuation
  run.cycle_bound = run.chaos_cycles + run.restart_cycles;
  return run;
}

FuzzRun run_channel_fuzz(uint64_t seed, const FuzzOptions& options) {
  FuzzRun run = prepare_channel_fuzz(seed, options);
  if (!run.failures.empty()) return run;
  const MachineConfig machine = machine_of(run);
  const double dt = machine.cycle_time_s();
  const GeneratedProgram& program = run.program;
  const bool expectations = run.expectations;
  const int64_t lines = static_cast<int64_t>(program.lines.size());
  auto fail = [&](Failure f) { run.failures.push_back(std::move(f)); };

  cnc::Channel channel(machine, program.text);
  logger::LimitChecker checker(machine);
  FuzzPlc plc(mix_seed(seed ^ 0x91c), run.chaos_cycles, options.insert_stops && options.random_plc,
              options.block_search && options.random_plc, lines);
  HliControl control;
  control.program_start = {true, true};
  control.feedhold.enable_w = true;
  control.override = {override_full, false};
  control.m_function_ack.enable_w = true;

  const size_t axes = machine.axes.size();
  std::vector<int64_t> line_at;  // block_count_r per cycle: the NC line
  line_at.reserve(static_cast<size_t>(std::min<int64_t>(run.cycle_bound, 1 << 20)));
  std::vector<double> previous_position(axes, 0.0);
  std::vector<bool> previous_lifted(axes, false);
  // LIFT-2: with Advanced Lifting each axis' drive, as the rig simulates
  // it: while the axis lifts, its actual acceleration stays below
  // P-AXIS-00442's limit (the other machines need no drive here).
  std::vector<axis::DriveModel> drives;
  if (machine.lift_method == LiftMethod::time_based)
    for (const AxisConfig& a : machine.axes) drives.emplace_back(axis::drive_parameters(a, dt), 0.0);
  std::vector<bool> drive_failed(axes, false);
  double previous_dps = 0;
  bool previous_backward = false;
  int64_t previous_line = 0;
  double v_path_max_sq = 0;  // the main axes' velocity limits: the fastest the path may cover distance
  for (const AxisConfig& a : machine.axes) v_path_max_sq += a.v_max * a.v_max;
  const double dps_step_limit = std::sqrt(v_path_max_sq) * dt;
  const bool dps_counts_all = !program.has_dps_off && program.clear_lines.empty();
  bool ddtg_requested = false, motion_ended_early = false, clear_seen_before = false;
  bool lift_command_not_skipped = false;  // 51016 ended the run (DDTG-8)
  // DPS-3: resets and program starts (with a block search or not).
  int64_t resets = 0;
  ChannelState previous_state = ChannelState::ready;
  int32_t previous_search_state = block_search_state::none;
  bool previous_dps_jump = false;
  bool approach_behind = false;  // backward motion since a search: the path may run on its approach (no distance)
  std::vector<double> last_start_position(axes, 0.0);  // where the axes stood at the last program start
  double approach_mm = 0;  // the path the axes travelled while repositioning
  bool restart_refused = false;  // the last start's decoder refused the program from there: it ends in ERROR
  // What the decoder refuses of the program decoded at the last start or
  // search: the channel decodes it as the look-ahead fills (4 blocks a
  // cycle), so its error comes when the decoder reaches that line, not in
  // the start's cycle (fresh contour seed 40301643: N390's arc, line 39,
  // refused ~10 cycles after each of three restarts).
  std::optional<Event> refusal;
  const size_t max_failures = 20;

  // search_failed: the cycle a block search failed (state 3): its error event is expected.
  std::vector<Event> step_events;  // the last check_events' (for the observer)
  auto check_events = [&](int64_t k, bool search_failed = false, const Event* refused = nullptr) {
    step_events = channel.take_events();
    for (const Event& e : step_events) {
      ++run.events;
      if (e.id == 50810) {
        motion_ended_early = true;
      }
      if (e.id == 51016 && program.lifts) {  // DDTG-8: a short cut would skip a lift command
        lift_command_not_skipped = motion_ended_early = true;
        continue;
      }
      const bool from_plc = e.nc_line == 0 && (e.message.rfind("override ", 0) == 0 ||
                                               e.message.rfind("program start ignored", 0) == 0 ||
                                               e.message.rfind("reset ignored", 0) == 0);  // before any block
      if (!from_plc && run.event_log.size() < 64)
        run.event_log.push_back("cycle " + std::to_string(k) + ": " + describe(e));
      if (refused && e.severity == Severity::error && e.nc_line == refused->nc_line && e.message == refused->message)
        continue;
      if (e.severity == Severity::error && search_failed) {
        ++run.search_error_events;  // DPS-3: the search's error (no such block, beyond the end, G74 ..)
        continue;
      }
      if (e.severity == Severity::error)
        fail({"event", k, e.axis, "", e.value, e.limit, e.nc_line, "error event: " + describe(e)});
      else if (!from_plc && (e.nc_line < 1 || e.nc_line > lines))
        fail({"event", k, e.axis, "", static_cast<double>(e.nc_line), static_cast<double>(lines), e.nc_line,
              "event without an NC line of the program: " + describe(e)});
    }
  };

  int64_t k = 0;
  for (; k < run.cycle_bound && run.failures.size() < max_failures; ++k) {
    try {
      channel.step(k, control);
    } catch (const std::exception& e) {
      fail({"exception", k, "", "", 0, 0, previous_line, std::string("Channel::step threw: ") + e.what()});
      break;
    } catch (...) {
      fail({"exception", k, "", "", 0, 0, previous_line, "Channel::step threw a non-standard exception"});
      break;
    }
    const HliState& s = channel.hli();
    const std::vector<cnc::AxisSetpoint>& sp = channel.setpoints();
    const int64_t line = s.block_count_r;
    line_at.push_back(line);
    const int32_t search_state = s.block_search.state_r.state;
    // DPS-3: a reset sets dist_prog_start to 0, a start with a search to the
    // continuation's distance: that cycle and the next are exempt.
    const bool started = previous_state == ChannelState::ready && s.channel_state != ChannelState::ready;
    // A program start (after a reset) or a search decodes the program from
    // where the axes stand: a program whose first arc or G91 motion is
    // valid only from where it began is refused from elsewhere, as the
    // decoder says (the blocks before the error still run).
    const bool search_failed =
        search_state == block_search_state::error && previous_search_state != block_search_state::error;
    const bool decodes = resets > 0 && (started || search_failed);
    std::optional<Event> refused;
    if (decodes) {
      refused = cnc::decode_program(program.text, machine, previous_position).error;
      if (refused) ++run.restart_decode_errors;
      restart_refused = restart_refused || (refused && started);
      refusal = refused;
    }
    check_events(k, search_failed, refusal ? &*refusal : nullptr);
    if (options.observer) options.observer(k, channel, control, step_events);
    if (const std::string broken = channel.check_invariants(); !broken.empty())
      fail({"invariant", k, "", "", 0, 0, line, "the interpolator's block cursors: " + broken});
    if (started) last_start_position = previous_position;
    if (s.reset.state_r) {
      ++resets;
      restart_refused = false;
      run.cycle_bound += run.restart_cycles;
      motion_ended_early = false;  // the program runs again
      approach_behind = false;
    }
    const bool dps_jump = s.reset.state_r || started;
    const bool searched = started && (search_state == block_search_state::repositioning ||
                                      search_state == block_search_state::continued);
    if (searched) {  // the continuation the search reports against the request
      const BlockSearchCommand& asked = plc.last_search().command;
      const BlockSearchState& found = s.block_search.state_r;
      const double cont_mm = found.continuation_distance / hli_units_per_mm, asked_mm = asked.distance / hli_units_per_mm;
      if (asked.type == 4 && !found.continuation_moved && std::abs(cont_mm - asked_mm) > 1e-9 + 1e-12 * asked_mm)
        fail({"block search", k, "", "continuation_distance (mm)", cont_mm, asked_mm, line,
              "a type 4 search continues at another distance than asked"});
      // Moved to the block's start only if the distance lay before it (a round-off below is its start, no move).
      if (asked.type == 4 && found.continuation_moved && !(cont_mm > asked_mm - 1e-9 - 1e-12 * asked_mm))
        fail({"block search", k, "", "continuation_distance (mm)", cont_mm, asked_mm, line,
              "moved to the block's start, but the distance did not lie before it"});
      if (std::abs(s.dist_prog_start - found.continuation_distance) > 1e-3)
        fail({"block search", k, "", "dist_prog_start at the search's start (mm)", s.dist_prog_start / hli_units_per_mm,
              cont_mm, line, "not preset to the continuation's distance"});
      approach_mm = 0;
    }
    // The approach covers no distance (DPS OFF): no chord in the cycles on it.
    const bool repositioning = search_state == block_search_state::repositioning ||
                               previous_search_state == block_search_state::repositioning;
    if (search_state == block_search_state::repositioning || search_state == block_search_state::continued)
      approach_behind = approach_behind || s.backward_motion.state_r;

    double chord_sq = 0;
    checker.add_hli_state(s);  // lift_active: the lift's overload range (LIFT-2)
    for (size_t i = 0; i < axes; ++i) {
      checker.add_setpoint(static_cast<int>(i), k, sp[i].position);
      if (!drives.empty()) {
        const double actual = drives[i].step(sp[i].position, sp[i].velocity).acceleration;
        const double a_err = machine.axes[i].accel_error_limit();
        if (s.lift_active[i] && !drive_failed[i] && !(std::abs(actual) <= a_err)) {
          drive_failed[i] = true;
          fail({"drive", k, machine.axes[i].name, "actual acceleration (P-AXIS-00442) while Advanced Lifting lifts",
                actual, a_err, line, "the drive's monitor would stop the channel"});
        }
      }
      if (!finite(sp[i].position) || !finite(sp[i].velocity) || !finite(sp[i].acceleration))
        fail({"finite", k, machine.axes[i].name, "setpoint", sp[i].position, 0, line,
              "position/velocity/acceleration not finite"});
      // A lift axis moved by the lift is not on the path (LIFT-1): no share of dist_prog_start.
      const bool lifted = s.lift_active[i] || s.lift_suppressed[i] || previous_lifted[i];
      previous_lifted[i] = s.lift_active[i] || s.lift_suppressed[i];
      const double d = sp[i].position - previous_position[i];
      if (!lifted) chord_sq += d * d;
      previous_position[i] = sp[i].position;
    }
    const double dps = s.dist_prog_start / hli_units_per_mm;
    if (!finite(dps) || !finite(s.path_velocity))
      fail({"finite", k, "", "dist_prog_start / path_velocity", dps, 0, line, "not finite"});
    if (line < 0 || line > lines)
      fail({"event", k, "", "block_count_r", static_cast<double>(line), static_cast<double>(lines), 0,
            "block_count_r is no line of the program"});
    if (s.m_function_request_r && s.m_function_nr_r != FuzzPlc::insert_m_function &&
        std::find(program.m_functions.begin(), program.m_functions.end(), s.m_function_nr_r) == program.m_functions.end())
      fail({"event", k, "", "m_function_nr_r", static_cast<double>(s.m_function_nr_r), 0, line,
            "an M function the program does not have"});

    // DPS-1 / KRN-5 / DPS-2.
    const bool backward = s.backward_motion.state_r;
    // A CLEAR runs when the interpolator passes its line; the HLI may show
    // the cleared value a cycle later (a short cut starts after the cycle's
    // interpolation, DDTG-7 runs the skipped lines then).
    bool cleared = clear_seen_before || dps_jump || previous_dps_jump;
    clear_seen_before = false;
    for (int64_t c : program.clear_lines)
      if (c > std::min(previous_line, line) && c <= std::max(previous_line, line)) cleared = clear_seen_before = true;
    // The path may pass a CLEAR and turn back (backward motion) within one
    // cycle, block_count_r showing neither: a value cleared in this cycle
    // lies within one cycle's travel of 0.
    if (!program.clear_lines.empty() && std::abs(dps) <= dps_step_limit * (1 + 1e-6)) cleared = true;
    const double change = dps - previous_dps, chord = std::sqrt(chord_sq);
    if (search_state == block_search_state::repositioning) approach_mm += chord;
    if ((searched || previous_search_state == block_search_state::repositioning) &&
        search_state == block_search_state::continued && plc.last_search().at_stop) {
      ++run.at_stop_searches;
      run.at_stop_moved += approach_mm > 1e-3;
      run.at_stop_approach_max_mm = std::max(run.at_stop_approach_max_mm, approach_mm);
    }
    const double tol = 1e-9 + 1e-12 * std::abs(dps);
    if (!cleared) {
      if (!backward && !previous_backward && change < -tol)
        fail({"dist_prog_start", k, "", "dist_prog_start change (mm) moving forward", change, 0, line,
              "decreased while the path moved forward"});
      if (backward && previous_backward && change > tol)
        fail({"dist_prog_start", k, "", "dist_prog_start change (mm) moving backward", change, 0, line,
              "increased while the path moved backward"});
      if (std::abs(change) > dps_step_limit * (1 + 1e-6) + tol)
        fail({"dist_prog_start", k, "", "dist_prog_start change (mm) in one cycle", change, dps_step_limit, line,
              "more than the path can cover in one cycle"});
      // A contouring curve a little longer than the blocks' parts it
      // replaces: 1e-4 of it in 1000 contoured programs (docs/CONTOURING.md);
      // an HSC spline longer than the chords it smooths (GeneratedProgram::hsc).
      const double slower = program.hsc ? 2e-2 : program.contoured ? 1e-3 : 1e-6;
      if (dps_counts_all && !repositioning && !approach_behind && backward == previous_backward &&
          std::abs(change) < chord * (1 - slower) - tol)
        fail({"dist_prog_start", k, "", "dist_prog_start change (mm) in one cycle", change, chord, line,
              "less than the chord the main axes moved (DPS-1)"});
    }
    previous_dps = dps;
    previous_backward = backward;
    previous_state = s.channel_state;
    previous_search_state = search_state;
    previous_dps_jump = dps_jump;
    previous_line = line;
    ddtg_requested = ddtg_requested || s.delete_distance_to_go.request_r || s.delete_distance_to_go.state_r;
    run.short_cut = run.short_cut || s.delete_distance_to_go_active_r;
    run.backward = run.backward || backward;
    run.m_output = run.m_output || s.m_function_request_r;

    if (channel.finished()) {
      run.finished = true;
      ++k;
      break;
    }
    plc.answer(k, s, control);
  }
  run.cycles = k;
  run.plc = plc.counts();
  const HliState& end = channel.hli();
  if (!run.finished && run.failures.empty()) {
    std::ostringstream state;
    state << "not finished after " << k << " cycles (bound " << run.cycle_bound << ", random PLC until "
          << run.chaos_cycles << "): channel " << to_string(end.channel_state) << ", stop conditions 0x" << std::hex
          << end.stop_conditions_r << std::dec << ", m_function_request_r " << end.m_function_request_r
          << ", backward " << end.backward_motion.state_r << ", short cut " << end.delete_distance_to_go_active_r
          << ", v " << end.path_velocity;
    fail({"end", k, "", "", 0, 0, end.block_count_r, state.str()});
  }
  if (run.finished) {
    if (end.channel_state != ChannelState::program_end &&
        !((lift_command_not_skipped || restart_refused) && end.channel_state == ChannelState::error))
      fail({"end", k, "", "", 0, 0, end.block_count_r, std::string("ended in ") + to_string(end.channel_state)});
    const std::vector<double> at_end = previous_position;
    // After a reset the program ran again from where the axes stood (a
    // search decodes it from there too): it ends where the decoder ends it
    // from there (G91 before a position is programmed absolutely shifts it).
    std::vector<double> end_point = program.end_position;
    if (resets > 0) {
      const cnc::DecodedProgram again = cnc::decode_program(program.text, machine, last_start_position);
      for (auto b = again.blocks.rbegin(); b != again.blocks.rend(); ++b)
        if (b->has_motion) {
          end_point = b->motion.end;
          break;
        }
    }
    if (expectations && !motion_ended_early && !restart_refused)
      for (size_t i = 0; i < axes; ++i) {
        if (resets > 0 && program.lifts && i == 2) continue;  // Z lands on POS after a lift (LIFT-1)
        if (std::abs(at_end[i] - end_point[i]) > 1e-9)
          fail({"end position", k, machine.axes[i].name, "position (mm)", at_end[i], end_point[i],
                end.block_count_r,
                resets > 0 ? "the path did not end on the program's end point decoded from its last start"
                           : "the path did not end on the program's end point"});
      }
    // After a reset the count started again where the program restarted.
    const bool dps_comparable = !ddtg_requested && (!run.backward || dps_counts_all) && resets == 0;
    const double dps = end.dist_prog_start / hli_units_per_mm;
    if (expectations && dps_comparable &&
        std::abs(dps - program.dist_prog_start_end_mm) > 1e-6 + 1e-9 * program.path_length_mm)
      fail({"dist_prog_start", k, "", "dist_prog_start at the end (mm)", dps, program.dist_prog_start_end_mm,
            end.block_count_r, "not the program's path length (DPS-1, DPS-2)"});
    // The channel commands no more motion.
    for (int extra = 0; extra < 3; ++extra, ++k) {
      plc.answer(k - 1, channel.hli(), control);
      channel.step(k, control);
      check_events(k, false, refusal ? &*refusal : nullptr);
      for (size_t i = 0; i < axes; ++i)
        if (channel.setpoints()[i].position != at_end[i] || !channel.finished())
          fail({"end", k, machine.axes[i].name, "position (mm)", channel.setpoints()[i].position, at_end[i], 0,
                "moved after finished()"});
    }
  }
  for (const logger::Violation& v : checker.finish().violations) {
    const int64_t cycle = std::llround(v.worst_time_s / dt);
    const int64_t first = std::llround(v.time_s / dt);
    std::ostringstream detail;
    detail << v.cycles << " cycle(s) from " << first;
    fail({"limit", cycle, v.axis, v.quantity, v.value, v.limit,
          cycle >= 0 && cycle < static_cast<int64_t>(line_at.size()) ? line_at[cycle] : 0, detail.str()});
  }
  return run;
}

}  // namespace hil::fuzz
