// Benchmarks of the motion planner (issues 3 and 17, KRN-3): time per 1-D
// profile per case family (bench/profile_cases.hpp), and decode + plan
// throughput of a generated G01 program streamed from a file, with the peak
// memory of each size in a process of its own. Prints figures; asserts
// nothing.
// Run: build/bin/planner_bench [--profiles-only | --blocks N [--dir D]]
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "command_line.hpp"
#include "line_source.hpp"
#include "program_stream.hpp"
#include "machine_config.hpp"
#include "path_segment.hpp"
#include "look_ahead.hpp"
#include "position_profile.hpp"
#include "call_timer.hpp"
#include "profile_cases.hpp"

using namespace hil;
using namespace hil::cnc;
using clock_type = std::chrono::steady_clock;

namespace {

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

void print_times(const char* what, int cases, const bench::CallTimes& t) {
  std::printf("  %-29s %7d cases: mean %5.0f ns, p50 %5.0f ns, p99 %5.0f ns, max %7.0f ns (%d of %d batches"
              " preempted; checksum %.6g)\n",
              what, cases, t.mean_ns, t.p50_ns, t.p99_ns, t.max_ns, t.preempted_batches,
              t.batches + t.preempted_batches, t.checksum);
}

// TRAPEZ per case family, then every slope type from random states.
void profile_times(const bench::CallTimer& timer) {
  std::printf("position_profile, per call (mean of batches of 1000; p50/p99/max each call timed, %.3f ns/tick):\n",
              timer.ns_per_tick());
  for (bench::CaseFamily family : {bench::CaseFamily::random_from_rest, bench::CaseFamily::a_max_boundary,
                                   bench::CaseFamily::v_max_boundary, bench::CaseFamily::random_state}) {
    const int count = family == bench::CaseFamily::random_state ? 1000000 : 200000;
    const std::vector<bench::ProfileCase> cases = bench::profile_cases(family, count);
    const bench::CallTimes t = timer.time(count, [&](int i) {
      return position_profile(cases[i].start, cases[i].target, cases[i].lim, SlopeType::trapez).duration();
    });
    print_times((std::string("TRAPEZ ") + bench::to_string(family)).c_str(), count, t);
  }
  const std::vector<bench::ProfileCase> cases = bench::profile_cases(bench::CaseFamily::random_state, 200000);
  for (SlopeType slope : {SlopeType::step, SlopeType::sin2}) {
    const bench::CallTimes t = timer.time(static_cast<int>(cases.size()), [&](int i) {
      return position_profile(cases[i].start, cases[i].target, cases[i].lim, slope).duration();
    });
    print_times((std::string(to_string(slope)) + " random initial state").c_str(), static_cast<int>(cases.size()), t);
  }
}

MachineConfig xyz_machine() {
  return parse_machine_config(YAML::Load(R"(
cycle_time_us: 1000
axes:
  - {name: X, v_max: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002}
  - {name: Y, v_max: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002}
  - {name: Z, v_max: 150, a_max: 1500, j_max: 30000, kv: 35, velocity_lag_s: 0.0025}
)"));
}

// The generated program, written line by line (never held whole): random
// points, every transition a corner. Bytes written.
size_t write_program(const std::string& path, int64_t blocks) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) {
    std::perror(path.c_str());
    std::exit(1);
  }
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 100);
  size_t bytes = 0;
  for (int64_t i = 0; i < blocks; ++i) {
    // The points the bench always drew: g++ evaluated the earlier
    // snprintf's arguments right to left (Z first).
    const double z = u(rng) / 10;
    const double y = u(rng);
    const double x = u(rng);
    bytes += static_cast<size_t>(std::fprintf(out, "N%lld G01 X%.3f Y%.3f Z%.3f F6000\n", static_cast<long long>(i + 1),
                                              x, y, z));
  }
  bytes += static_cast<size_t>(std::fprintf(out, "M30\n"));
  std::fclose(out);
  return bytes;
}

// Decodes the program as the channel does (ProgramStream: the streamed
// decoder, M function pre-output, the lift's preparation); with `plan`,
// each motion block enters the look-ahead (corner rule, backward pass) and
// the front's stretch is planned when it leaves, as the interpolator does.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + t.tv_nsec * 1e-9;
}

// Times are CPU time of this process (the machine is shared: wall time
// carries the others' load), wall time beside it.
struct Pass {
  double seconds = 0;
  double wall = 0;
  int64_t blocks = 0;
  double planned_time = 0;
  bool error = false;
};
Pass run_pass(const std::string& path, const MachineConfig& machine, bool plan) {
  const auto t0 = clock_type::now();
  const double cpu0 = cpu_seconds();
  ProgramStream stream(program_file(path), machine, {0, 0, 0}, [](LiftRange) {});
  BlockSource& source = stream.blocks();
  LookAhead look_ahead(machine);
  Pass pass;
  double v_entry = 0;
  auto plan_front = [&] {
    const Stretch st = look_ahead.stretch(v_entry);
    pass.planned_time += block_profile({0, v_entry, 0, 0}, st.length, st.v_end, st.lim, st.slope).profile.duration();
    v_entry = look_ahead.front().v_end;
    look_ahead.pop_front();
  };
  Block block;
  for (size_t i = 0; source.next(block); ++i) {
    ++pass.blocks;
    if (!plan || !block.has_motion) continue;
    if (look_ahead.full()) plan_front();
    look_ahead.push(MotionPiece::of_block(block, i, PathSegment(block.motion, machine)));
  }
  while (!look_ahead.empty()) plan_front();
  pass.seconds = cpu_seconds() - cpu0;
  pass.wall = std::chrono::duration<double>(clock_type::now() - t0).count();
  pass.error = stream.take_error().has_value();
  return pass;
}

// One size, in this process: the program is generated into a temporary
// file and streamed from it, decoded alone, then decoded and planned.
void decode_and_plan(int64_t blocks, const std::string& dir) {
  const MachineConfig machine = xyz_machine();
  const std::string path = dir + "/planner_bench_" + std::to_string(::getpid()) + ".nc";
  const size_t bytes = write_program(path, blocks);
  const double rss_before = peak_rss_mib();
  const Pass decode = run_pass(path, machine, false);
  const Pass both = run_pass(path, machine, true);
  std::remove(path.c_str());
  const double plan_s = both.seconds - decode.seconds;
  const double n = static_cast<double>(blocks);
  std::printf("G01 program of %lld blocks (%.1f MiB file, streamed), CPU time: decode %.3f s (%.0f blocks/s), "
              "look-ahead + plan %.3f s (%.0f blocks/s), decode+plan %.3f s (%.0f blocks/s); wall %.3f / %.3f s; "
              "peak RSS %.1f MiB (%.1f before decoding); checksum %.6f s%s\n",
              static_cast<long long>(blocks), bytes / 1048576.0, decode.seconds, n / decode.seconds, plan_s,
              n / plan_s, both.seconds, n / both.seconds, decode.wall, both.wall, peak_rss_mib(), rss_before,
              both.planned_time,
              decode.error || both.error || both.blocks != blocks + 1 ? " (DECODE ERROR)" : "");
  std::fflush(stdout);
}

// Each size in a process of its own: peak RSS is per process.
void decode_and_plan_forked(int64_t blocks, const std::string& dir) {
  std::fflush(stdout);  // not printed again by the child
  const pid_t child = ::fork();
  if (child == 0) {
    decode_and_plan(blocks, dir);
    std::_Exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"planner_bench: jerk profiles per family, then decode + plan of 10 k, 1 M and 10 M blocks"};
  bool profiles_only = false;
  int64_t only = 0;
  std::string dir = "/tmp";
  app.add_flag("--profiles-only", profiles_only, "the profiles only");
  app.add_option("--blocks", only, "decode + plan of this many blocks only")->check(CLI::PositiveNumber);
  app.add_option("--dir", dir, "folder of the temporary NC file")->capture_default_str();
  app.footer("Documentation: docs/PERFORMANCE.md in the source tree");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  if (profiles_only) {
    profile_times(bench::CallTimer());
    return 0;
  }
  if (only > 0) {
    decode_and_plan(only, dir);
    return 0;
  }
  profile_times(bench::CallTimer());
  for (const int64_t blocks : {int64_t{10000}, int64_t{1000000}, int64_t{10000000}}) decode_and_plan_forked(blocks, dir);
  return 0;
}
