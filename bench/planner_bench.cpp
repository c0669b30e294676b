// Benchmarks of the motion planner (issues 3 and 17, KRN-3): time per 1-D
// profile per case family (bench/profile_cases.hpp), and decode + plan
// throughput of a generated G01 program. Prints figures; asserts nothing.
// Run: build/bin/planner_bench [--profiles-only]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "decoder.hpp"
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

void decode_and_plan(int blocks) {
  const MachineConfig machine = parse_machine_config(YAML::Load(R"(
cycle_time_us: 1000
axes:
  - {name: X, v_max: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002}
  - {name: Y, v_max: 250, a_max: 2000, j_max: 40000, kv: 40, velocity_lag_s: 0.002}
  - {name: Z, v_max: 150, a_max: 1500, j_max: 30000, kv: 35, velocity_lag_s: 0.0025}
)"));
  std::string program;
  program.reserve(static_cast<size_t>(blocks) * 40);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 100);
  char line[96];
  for (int i = 0; i < blocks; ++i) {
    std::snprintf(line, sizeof line, "N%d G01 X%.3f Y%.3f Z%.3f F6000\n", i + 1, u(rng), u(rng), u(rng) / 10);
    program += line;
  }
  program += "M30\n";
  const auto t0 = clock_type::now();
  const DecodedProgram decoded = decode_program(program, machine, {0, 0, 0});
  const auto t1 = clock_type::now();
  // As the channel does it: each block enters the look-ahead (corner rule,
  // backward pass); the front's stretch is planned when the block starts.
  LookAhead look_ahead(machine);
  double v_entry = 0, planned_time = 0;
  auto plan_front = [&] {
    const Stretch st = look_ahead.stretch(v_entry);
    planned_time += block_profile({0, v_entry, 0, 0}, st.length, st.v_end, st.lim, st.slope).duration();
    v_entry = look_ahead.front().v_end;
    look_ahead.pop_front();
  };
  for (size_t i = 0; i < decoded.blocks.size(); ++i) {
    if (!decoded.blocks[i].has_motion) continue;
    if (look_ahead.full()) plan_front();
    look_ahead.push(i, PathSegment(decoded.blocks[i].motion, machine), decoded.blocks[i].slope);
  }
  while (!look_ahead.empty()) plan_front();
  const auto t2 = clock_type::now();
  const double decode_s = std::chrono::duration<double>(t1 - t0).count();
  const double plan_s = std::chrono::duration<double>(t2 - t1).count();
  std::printf("G01 program of %d blocks (%.1f MiB text): decode %.3f s (%.0f blocks/s), look-ahead + plan"
              " %.3f s (%.0f blocks/s), decode+plan %.0f blocks/s; checksum %.6f s%s\n",
              blocks, program.size() / 1048576.0, decode_s, blocks / decode_s, plan_s, blocks / plan_s,
              blocks / (decode_s + plan_s), planned_time, decoded.error ? " (DECODE ERROR)" : "");
}

}  // namespace

int main(int argc, char** argv) {
  profile_times(bench::CallTimer());
  if (argc > 1 && std::string(argv[1]) == "--profiles-only") return 0;
  decode_and_plan(1000000);
  std::printf("peak memory (max RSS): %.1f MiB\n", peak_rss_mib());
  return 0;
}
