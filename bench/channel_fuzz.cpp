// The channel fuzz, long runs (KRN-3, DDTG-1, KRN-5, DPS-1): seeded random
// programs on hil::cnc::Channel with a random PLC, every cycle checked
// against the invariants of tests/fuzz/channel_fuzz.hpp. Prints runs,
// cycles, and each failing run's seed with a line per failure (cycle, axis,
// quantity, value, limit, NC line). Exit status 1 if any run failed.
//
//   build/bin/channel_fuzz --runs 10000 --seed 1
//   build/bin/channel_fuzz --seed 4711 --runs 1 --print-program   (reproduce one)
//   build/bin/channel_fuzz --seed 4711 --runs 1 --trace > trace.tsv
//   build/bin/channel_fuzz --seed 1 --runs 8 --program-kind arcs --golden tests/golden/fuzz   (docs/GOLDEN.md)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "command_line.hpp"
#include "channel_fuzz.hpp"
#include "fuzz_golden_trace.hpp"

using namespace hil;
using namespace hil::fuzz;

namespace {

bool same_kind(const Failure& a, const Failure& b) { return a.invariant == b.invariant && a.quantity == b.quantity; }

FuzzRun run_one(uint64_t seed, const FuzzOptions& options, bool isolated) {
  return isolated ? run_channel_fuzz_isolated(seed, options) : run_channel_fuzz(seed, options);
}

// Deletes lines (not the first, not M30) of a failing run's program while a
// failure of the same kind (invariant and quantity) remains: without the
// random PLC if it fails so, else with the seed's PLC (its random phase
// kept as long as in the original run).
void minimize(const FuzzRun& failed, FuzzOptions options, bool isolated) {
  const Failure target = failed.failures.front();
  std::vector<std::string> lines = failed.program.lines;
  auto text_of = [](const std::vector<std::string>& l) {
    std::string t;
    for (const std::string& line : l) t += line + "\n";
    return t;
  };
  auto fails = [&](const std::vector<std::string>& l, const FuzzOptions& o, Failure* found = nullptr) {
    FuzzOptions with = o;
    with.program_text = text_of(l);
    const FuzzRun r = run_one(failed.seed, with, isolated);
    for (const Failure& f : r.failures)
      if (same_kind(f, target)) {
        if (found) *found = f;
        return true;
      }
    return false;
  };
  FuzzOptions quiet = options;
  quiet.random_plc = false;
  quiet.chaos_cycles = 0;
  FuzzOptions with_plc = options;
  with_plc.chaos_cycles = failed.chaos_cycles;
  const bool without_plc = fails(lines, quiet);
  const FuzzOptions& o = without_plc ? quiet : with_plc;
  if (!without_plc && !fails(lines, o)) {
    std::printf("  minimize: does not fail again from the program text\n");
    return;
  }
  for (size_t chunk = std::max<size_t>(1, (lines.size() - 2) / 2); chunk >= 1; chunk /= 2) {
    for (size_t i = 1; i + 1 < lines.size();) {
      std::vector<std::string> shorter = lines;
      const size_t end = std::min(i + chunk, shorter.size() - 1);
      shorter.erase(shorter.begin() + static_cast<long>(i), shorter.begin() + static_cast<long>(end));
      if (fails(shorter, o)) lines = shorter;
      else i += chunk;
    }
    if (chunk == 1) break;
  }
  Failure found;
  fails(lines, o, &found);
  FuzzRun shown = failed;
  shown.program.lines = lines;
  std::printf("  minimized to %zu lines (%s):\n", lines.size(),
              without_plc ? "without the random PLC, --quiet-plc"
                          : ("with the seed's PLC, --chaos-cycles " + std::to_string(failed.chaos_cycles)).c_str());
  for (const std::string& line : lines) std::printf("    %s\n", line.c_str());
  std::printf("    -> %s\n", describe(shown, found).c_str());
}

// Writes the run's golden trace, or compares it with the one written;
// false if it differs or is missing.
bool golden_step(const logger::GoldenTrace& trace, const std::string& dir, const FuzzRun& run, bool write) {
  const std::string path = fuzz_golden_path(dir, run.kind, run.seed);
  try {
    if (write) {
      std::filesystem::create_directories(std::filesystem::path(path).parent_path());
      trace.write(path);
      return true;
    }
    if (!std::filesystem::exists(path)) {
      std::printf("GOLDEN seed %llu (%s): no %s (write it with --write-golden)\n",
                  static_cast<unsigned long long>(run.seed), to_string(run.kind), path.c_str());
      return false;
    }
    const logger::TraceComparison c = logger::compare_golden_traces(logger::GoldenTrace::read(path), trace);
    if (c.same()) return true;
    std::printf("GOLDEN seed %llu (%s): %lld difference(s) beyond 1e-9 mm against %s\n",
                static_cast<unsigned long long>(run.seed), to_string(run.kind), static_cast<long long>(c.count),
                path.c_str());
    for (const std::string& d : c.differences) std::printf("  %s\n", d.c_str());
  } catch (const std::exception& e) {
    std::printf("GOLDEN seed %llu (%s): %s\n", static_cast<unsigned long long>(run.seed), to_string(run.kind), e.what());
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"channel fuzz: random NC programs and PLC edges against the channel's invariants"};
  int64_t runs = 1000;
  uint64_t seed = 1;
  std::string kind_name = "all";
  FuzzOptions options;
  bool print_program = false, trace = false, quiet_plc = false, no_fork = false, shrink = false;
  int max_failures_shown = 5;
  app.add_option("--runs", runs, "number of runs (seeds seed .. seed + runs - 1)")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "first seed");
  app.add_option("--program-kind", kind_name, "all (by seed), mixed, lines, arcs, steps, commands, contour, lift, hsc");
  app.add_option("--min-items", options.min_items, "fewest generator items per program")->check(CLI::PositiveNumber);
  app.add_option("--max-items", options.max_items, "most generator items per program")->check(CLI::PositiveNumber);
  app.add_flag("--quiet-plc", quiet_plc, "no random PLC edges: program start and prompt M acknowledgements only");
  bool no_insert_stops = false;
  app.add_flag("--no-insert-stops", no_insert_stops, "no random insert stop commands (ISC): every seed runs as before them");
  bool no_block_search = false;
  app.add_flag("--no-block-search", no_block_search,
               "no resets and block searches (DPS-3) from the PLC: every seed runs as before them");
  app.add_flag("--print-program", print_program, "print the NC program of every failing run (and of a single run)");
  app.add_flag("--trace", trace, "print every cycle (TSV) of the runs");
  app.add_option("--show", max_failures_shown, "failures shown per failing run");
  bool show_events = false;
  app.add_flag("--events", show_events, "print the first events of each failing run");
  app.add_flag("--no-fork", no_fork, "run in this process (for a debugger); a crash ends the bench");
  std::string program_file;
  app.add_option("--program", program_file, "run this NC program file instead of the generated one (with the seed's PLC)")
      ->check(CLI::ExistingFile);
  int64_t chaos = -1;
  app.add_option("--chaos-cycles", chaos, "random PLC phase in cycles instead of the seed's (with --program: as minimized)");
  app.add_flag("--minimize", shrink, "shrink each failing run's program by deleting lines while it fails alike");
  app.add_flag("--vary-machine", options.vary_machine,
               "each axis' v, a and j drawn from the seed (v 0.25..2x, a 0.25..4x, j 0.2..5x the fuzz machine's): "
               "other machines");
  std::string golden_dir;
  bool write_golden = false;
  app.add_option("--golden", golden_dir,
                 "compare each run's outputs with its golden trace DIR/<kind>/seed_<seed>.trace.xz within 1e-9 mm "
                 "(in this process; docs/GOLDEN.md)");
  app.add_flag("--write-golden", write_golden, "write the golden traces instead (with --golden)")->needs("--golden");
  app.footer("Documentation: docs/FUZZ.md in the source tree");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  if (options.vary_machine && !golden_dir.empty()) {
    std::fprintf(stderr, "--vary-machine: the golden traces are of the fuzz machine; not with --golden\n");
    return 2;
  }
  if (kind_name != "all") {
    const auto kind = parse_program_kind(kind_name);
    if (!kind) {
      std::fprintf(stderr, "unknown --program-kind '%s'\n", kind_name.c_str());
      return 2;
    }
    options.kind = *kind;
  }
  options.max_items = std::max(options.max_items, options.min_items);
  if (!program_file.empty()) {
    std::ifstream in(program_file);
    std::ostringstream text;
    text << in.rdbuf();
    options.program_text = text.str();
  }
  options.random_plc = !quiet_plc;
  options.insert_stops = !no_insert_stops;
  options.block_search = !no_block_search;
  if (chaos >= 0) options.chaos_cycles = chaos;
  if (trace) {
    std::printf("cycle\tx\ty\tz\tv_path\tblock_nr\tblock_count\tdps_mm\tstate\tbackward\tshort_cut\tm_request\t"
                "feedhold\toverride\tddtg\tbackward_cmd\tm_ack\n");
    options.observer = [](int64_t k, const cnc::Channel& ch, const HliControl& c, const std::vector<Event>&) {
      const HliState& s = ch.hli();
      const auto& p = ch.setpoints();
      std::printf("%lld\t%.9f\t%.9f\t%.9f\t%.6f\t%lld\t%lld\t%.7f\t%s\t%d\t%d\t%d\t%d\t%d\t%d\t%d\t%d\n",
                  static_cast<long long>(k), p[0].position, p.size() > 1 ? p[1].position : 0.0,
                  p.size() > 2 ? p[2].position : 0.0, s.path_velocity, static_cast<long long>(s.block_nr_r),
                  static_cast<long long>(s.block_count_r), s.dist_prog_start / hli_units_per_mm,
                  to_string(s.channel_state), s.backward_motion.state_r, s.delete_distance_to_go_active_r,
                  s.m_function_request_r, c.feedhold.command_w && c.feedhold.enable_w,
                  c.override.enable_w ? c.override.command_w : override_full,
                  c.delete_distance_to_go.command_w && c.delete_distance_to_go.enable_w,
                  c.backward_motion.command_w && c.backward_motion.enable_w, c.m_function_ack.command_w);
    };
  }

  FuzzGoldenRecorder golden;
  if (!golden_dir.empty()) {
    if (trace) {
      std::fprintf(stderr, "--golden and --trace both observe the runs: one at a time\n");
      return 2;
    }
    golden.attach(options);
    no_fork = true;  // the trace is recorded in this process
  }
  int64_t golden_different = 0;

  const auto t0 = std::chrono::steady_clock::now();
  int64_t cycles = 0, failed_runs = 0, failures = 0;
  int64_t with_short_cut = 0, with_backward = 0, with_m = 0, with_random_plc = 0, insert_commands = 0, insert_stops = 0;
  int64_t resets = 0, searches = 0, search_errors = 0, with_reset = 0, at_stop = 0, at_stop_moved = 0;
  double approach_max = 0;
  int64_t decode_refused = 0;
  std::map<std::string, int64_t> by_invariant, failed_by_kind, runs_by_kind;
  for (int64_t i = 0; i < runs; ++i) {
    const uint64_t s = seed + static_cast<uint64_t>(i);
    const FuzzRun run = run_one(s, options, !no_fork);
    cycles += run.cycles;
    ++runs_by_kind[to_string(run.kind)];
    with_short_cut += run.short_cut;
    with_backward += run.backward;
    with_m += run.m_output;
    insert_commands += run.plc.insert_commands;
    insert_stops += run.plc.insert_stops;
    resets += run.plc.resets;
    searches += run.plc.searches;
    search_errors += run.plc.search_errors;
    with_reset += run.plc.resets > 0;
    at_stop += run.at_stop_searches;
    decode_refused += run.restart_decode_errors;
    at_stop_moved += run.at_stop_moved;
    approach_max = std::max(approach_max, run.at_stop_approach_max_mm);
    with_random_plc += run.chaos_cycles > 0;
    if (runs == 1 && print_program && !trace) std::printf("%s", run.program.text.c_str());
    if (!golden_dir.empty()) golden_different += !golden_step(golden.take(run), golden_dir, run, write_golden);
    if (run.passed()) continue;
    ++failed_runs;
    failures += static_cast<int64_t>(run.failures.size());
    ++failed_by_kind[to_string(run.kind)];
    std::printf("FAIL seed %llu (%s, %lld cycles, random PLC until cycle %lld, override max %d %%): %zu failure(s)\n",
                static_cast<unsigned long long>(s), to_string(run.kind), static_cast<long long>(run.cycles),
                static_cast<long long>(run.chaos_cycles), run.override_max_percent, run.failures.size());
    for (size_t f = 0; f < run.failures.size(); ++f) {
      const Failure& failure = run.failures[f];
      ++by_invariant[failure.invariant + (failure.quantity.empty() ? "" : ": " + failure.quantity)];
      if (static_cast<int>(f) < max_failures_shown) std::printf("  %s\n", describe(run, failure).c_str());
    }
    if (show_events)
      for (const std::string& e : run.event_log) std::printf("  event %s\n", e.c_str());
    std::printf("  reproduce: channel_fuzz --seed %llu --runs 1 --program-kind %s%s%s --print-program\n",
                static_cast<unsigned long long>(s), to_string(run.kind), quiet_plc ? " --quiet-plc" : "",
                options.vary_machine ? " --vary-machine" : "");
    if (print_program && runs > 1) std::printf("%s", run.program.text.c_str());
    if (shrink) minimize(run, options, !no_fork);
    std::fflush(stdout);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("\nchannel fuzz: %lld runs (seeds %llu .. %llu), %lld cycles (%.1f s simulated) in %.1f s "
              "(%.0f cycles/s)\n",
              static_cast<long long>(runs), static_cast<unsigned long long>(seed),
              static_cast<unsigned long long>(seed + runs - 1), static_cast<long long>(cycles), cycles * 1e-3,
              seconds, cycles / seconds);
  std::printf("runs with random PLC %lld, with a short cut %lld, with backward motion %lld, with M functions %lld\n",
              static_cast<long long>(with_random_plc), static_cast<long long>(with_short_cut),
              static_cast<long long>(with_backward), static_cast<long long>(with_m));
  std::printf("insert stop commands %lld, insert / M00 / M01 stops continued %lld%s\n",
              static_cast<long long>(insert_commands), static_cast<long long>(insert_stops),
              options.insert_stops ? "" : " (--no-insert-stops)");
  std::printf("resets %lld (in %lld runs), block searches %lld, of them failed (state 3) %lld%s\n",
              static_cast<long long>(resets), static_cast<long long>(with_reset), static_cast<long long>(searches),
              static_cast<long long>(search_errors), options.block_search ? "" : " (--no-block-search)");
  std::printf("restarts and searches after a reset refused by the decoder from where the axes stood %lld\n",
              static_cast<long long>(decode_refused));
  std::printf("type 4 searches at what was read at the stop that continued %lld, their approach moved > 1 um %lld "
              "(the starting movement counts), longest %.6f mm\n",
              static_cast<long long>(at_stop), static_cast<long long>(at_stop_moved), approach_max);
  std::printf("failed runs: %lld, failures: %lld\n", static_cast<long long>(failed_runs),
              static_cast<long long>(failures));
  for (const auto& [kind, n] : runs_by_kind)
    std::printf("  kind %-9s %6lld runs, %6lld failed\n", kind.c_str(), static_cast<long long>(n),
                static_cast<long long>(failed_by_kind[kind]));
  for (const auto& [what, n] : by_invariant)
    std::printf("  %6lld x %s\n", static_cast<long long>(n), what.c_str());
  if (!golden_dir.empty() && !write_golden)
    std::printf("golden traces (%s): %lld of %lld runs differ\n", golden_dir.c_str(),
                static_cast<long long>(golden_different), static_cast<long long>(runs));
  return failed_runs > 0 || golden_different > 0 ? 1 : 0;
}
