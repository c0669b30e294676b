// Benchmarks of the motion planner (issue 3, KRN-3): time per 1-D profile
// over seeded random states, and decode + plan throughput of a generated
// G01 program. Prints figures; asserts nothing. Run: build/bin/planner_bench
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

using namespace hil;
using namespace hil::cnc;
using clock_type = std::chrono::steady_clock;

namespace {

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

void profile_times(int cases, SlopeType slope) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  std::vector<double> ns(cases);
  double checksum = 0;
  for (int i = 0; i < cases; ++i) {
    const Limits lim{std::pow(10.0, -2 + 2 * w(rng)), std::pow(10.0, -1 + 2.5 * w(rng)),
                     std::pow(10.0, 3.5 * w(rng))};
    MotionState s{0.02 * u(rng), lim.v * u(rng), lim.a * u(rng), 0};
    const double target = 0.02 * u(rng);
    const auto t0 = clock_type::now();
    const MotionProfile p = position_profile(s, target, lim, slope);
    const auto t1 = clock_type::now();
    checksum += p.duration();
    ns[i] = std::chrono::duration<double, std::nano>(t1 - t0).count();
  }
  double mean = 0;
  for (double x : ns) mean += x;
  mean /= cases;
  std::sort(ns.begin(), ns.end());
  std::printf("position_profile %-6s %d random cases: mean %.0f ns, p50 %.0f ns, p99 %.0f ns, max %.0f ns"
              " (checksum %.6g)\n",
              to_string(slope), cases, mean, ns[cases / 2], ns[cases * 99 / 100], ns.back(), checksum);
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

int main() {
  profile_times(1000000, SlopeType::trapez);
  profile_times(200000, SlopeType::step);
  profile_times(200000, SlopeType::sin2);
  decode_and_plan(1000000);
  std::printf("peak memory (max RSS): %.1f MiB\n", peak_rss_mib());
  return 0;
}
