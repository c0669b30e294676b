// The log fuzz (RIG-4, RIG-9; tests/fuzz/log_fuzz.hpp): mutants of two
// real logs through every reader, each in a child process with bounded
// memory and CPU time. Prints each failing mutant with its seed (the
// mutant's file is kept in the work folder), then the figures. Exit status
// 1 if any mutant failed.
//
//   build/bin/log_fuzz --seed 1 --runs 400
//   build/bin/log_fuzz --seed 4711 --runs 1 --here    (reproduce one in this process, e.g. under gdb)
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "command_line.hpp"
#include "fuzz_rng.hpp"
#include "log_fuzz.hpp"

using namespace hil::fuzz;

int main(int argc, char** argv) {
  CLI::App app{"log fuzz: crafted LCM logs through every reader of the rig (RIG-4, RIG-9)"};
  uint64_t seed = 1;
  int runs = 100;
  bool here = false;
  LogFuzzOptions options;
  options.work_dir = (std::filesystem::temp_directory_path() / "hil_log_fuzz").string();
  app.add_option("--seed", seed, "the first mutant's seed; the others follow it");
  app.add_option("--runs", runs, "mutants")->check(CLI::PositiveNumber);
  app.add_option("--work", options.work_dir, "folder for the base logs, failing mutants and the readers' output")
      ->capture_default_str();
  app.add_option("--cpu-limit-s", options.cpu_limit_s, "CPU time per mutant")->capture_default_str();
  app.add_option("--memory-limit-mb", options.memory_limit_mb, "address space per mutant beyond the fuzz's own")
      ->capture_default_str();
  bool no_rerun = false;
  app.add_flag("--no-rerun", no_rerun, "leave hil rerun out");
  app.add_flag("--here", here, "read the mutants in this process (no limits: a crash ends the fuzz)");
  bool write_only = false;
  app.add_flag("--write-only", write_only,
               "write the mutants into the work folder (mutant_<seed>.lcmlog), read none: to try other builds on them");
  bool verbose = false;
  app.add_flag("--verbose,-v", verbose, "a line per mutant: seed, base, mutation, verdict, time");
  app.footer("Documentation: docs/FUZZ.md in the source tree");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  options.rerun = !no_rerun;

  const auto start = std::chrono::steady_clock::now();
  const std::vector<BaseLog> bases = make_base_logs((std::filesystem::path(options.work_dir) / "base").string());
  const double base_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("log fuzz: base logs");
  for (const BaseLog& b : bases)
    std::printf(" %s (%s, %zu records, %lld bytes)", b.name.c_str(), b.passes ? "PASS" : "FAIL", b.records.records.size(),
                static_cast<long long>(b.bytes));
  std::printf(", made in %.1f s\n", base_s);

  if (write_only) {
    for (int i = 0; i < runs; ++i) {
      const uint64_t s = seed + static_cast<uint64_t>(i);
      std::string base;
      const Mutant m = mutant_of(bases, s, &base);
      const std::string path = options.work_dir + "/mutant_" + std::to_string(s) + ".lcmlog";
      std::ofstream(path, std::ios::binary)
          .write(reinterpret_cast<const char*>(m.bytes.data()), static_cast<std::streamsize>(m.bytes.size()));
      std::printf("%s %s %s %s: %s%s\n", path.c_str(), base.c_str(), name_of(m.kind), m.must_fail ? "must-fail" : "may-pass",
                  m.what.c_str(), m.changed ? "" : " (unchanged)");
    }
    return 0;
  }

  struct KindFigures {
    int mutants = 0, unchanged = 0, passed = 0, failing = 0;
  };
  std::map<std::string, KindFigures> by_kind;
  int failing = 0;
  MutantResult slowest, largest;
  const auto fuzz_start = std::chrono::steady_clock::now();
  for (int i = 0; i < runs; ++i) {
    const uint64_t s = seed + static_cast<uint64_t>(i);
    const MutantResult r = here ? run_mutant_here(bases, s, options) : run_mutant(bases, s, options);
    KindFigures& k = by_kind[name_of(r.kind)];
    ++k.mutants;
    k.unchanged += r.changed ? 0 : 1;
    k.passed += r.verdict == "PASS" ? 1 : 0;
    if (r.wall_s > slowest.wall_s) slowest = r;
    if (r.peak_rss_kb > largest.peak_rss_kb) largest = r;
    if (verbose)
      std::printf("seed %llu %s %s: %s -> %s, %.3f s, %lld kB\n", static_cast<unsigned long long>(s), r.base.c_str(),
                  name_of(r.kind), r.what.c_str(), r.verdict.c_str(), r.wall_s, static_cast<long long>(r.peak_rss_kb));
    if (r.failures.empty()) continue;
    ++failing;
    ++k.failing;
    std::printf("FAILED seed %llu, %s, %s: %s (verdict %s)\n", static_cast<unsigned long long>(s), r.base.c_str(),
                name_of(r.kind), r.what.c_str(), r.verdict.c_str());
    for (const std::string& f : r.failures) std::printf("  %s\n", f.c_str());
    std::printf("  the mutant: %s/mutant_%llu.lcmlog\n", options.work_dir.c_str(), static_cast<unsigned long long>(s));
  }
  const double fuzz_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - fuzz_start).count();
  std::printf("%d mutants (seeds %llu .. %llu) in %.1f s: %.1f mutants/s, %d failing\n", runs,
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed + runs - 1), fuzz_s,
              runs / fuzz_s, failing);
  std::printf("slowest: %.3f s (seed %llu, %s); most memory: %lld kB peak resident (seed %llu, %s)\n", slowest.wall_s,
              static_cast<unsigned long long>(slowest.seed), name_of(slowest.kind),
              static_cast<long long>(largest.peak_rss_kb), static_cast<unsigned long long>(largest.seed),
              name_of(largest.kind));
  for (const auto& [kind, k] : by_kind)
    std::printf("  %-16s %4d mutants, %3d unchanged, %3d judged PASS, %d failing\n", kind.c_str(), k.mutants,
                k.unchanged, k.passed, k.failing);
  return failing > 0 ? 1 : 0;
}
