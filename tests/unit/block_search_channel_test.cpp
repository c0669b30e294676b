// DPS-3 through the channel: a program interrupted by feed hold at a random
// distance, reset, searched at the block number and distance the PLC read
// at the stop, and continued, runs the rest of the path exactly as the
// uninterrupted run did (positions as a function of dist_prog_start). The
// search decodes from where the axes stand, so each program's starting
// movement is outside the distance (#DISTANCE PROG START OFF), as the text
// advises.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "dps_example_program.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;
using hil::test::run_program;

namespace {

struct Sample {
  double dist_mm = 0;
  std::vector<double> position;
};

std::vector<double> positions(const Channel& channel) {
  std::vector<double> p;
  for (const auto& s : channel.setpoints()) p.push_back(s.position);
  return p;
}

// M functions are acknowledged at once (MVS_SVS): a one-cycle edge, so
// that the next one, output in the cycle the CNC takes the edge, gets its own.
void acknowledge(const HliState& state, HliControl& control) {
  control.m_function_ack = {state.m_function_request_r && !control.m_function_ack.command_w, true};
}

struct Trace {
  std::vector<Sample> samples;
  std::vector<double> end;
  double end_dist_mm = 0;
};

Trace uninterrupted(const MachineConfig& machine, const std::string& program) {
  Channel channel(machine, program);
  Trace trace;
  run_program(channel, nullptr, [&](int64_t, const HliState& state, HliControl& control) {
    acknowledge(state, control);
    trace.samples.push_back({state.dist_prog_start / hli_units_per_mm, positions(channel)});
  });
  REQUIRE(channel.hli().channel_state == ChannelState::program_end);
  trace.end = positions(channel);
  trace.end_dist_mm = channel.hli().dist_prog_start / hli_units_per_mm;
  return trace;
}

// The uninterrupted run's position at distance d; none inside a section
// whose distance stands (#DISTANCE PROG START OFF): ambiguous there.
std::optional<std::vector<double>> reference_at(const Trace& reference, double d) {
  const auto& s = reference.samples;
  const auto it = std::lower_bound(s.begin(), s.end(), d, [](const Sample& a, double v) { return a.dist_mm < v; });
  if (it == s.end()) return std::nullopt;
  const size_t i = static_cast<size_t>(it - s.begin());
  const bool plateau = (i + 1 < s.size() && s[i + 1].dist_mm == it->dist_mm) || (i > 0 && s[i - 1].dist_mm == it->dist_mm);
  if (plateau) return std::nullopt;
  if (it->dist_mm == d || i == 0) return it->position;
  const Sample& a = s[i - 1];
  const double f = (d - a.dist_mm) / (it->dist_mm - a.dist_mm);
  std::vector<double> p(a.position.size());
  for (size_t k = 0; k < p.size(); ++k) p[k] = a.position[k] + f * (it->position[k] - a.position[k]);
  return p;
}

struct Interruption {
  double stop_dist_mm = 0;
  int64_t stop_block_nr = 0;
  size_t compared = 0;
  double worst_mm = 0;
};

// Feed hold once dist_prog_start reaches `at_mm`; standing: reset; then a
// block search (type 4) at what the PLC read at the stop, and start.
Interruption interrupt_and_continue(const MachineConfig& machine, const std::string& program, double at_mm,
                                    const Trace& reference) {
  Channel channel(machine, program);
  logger::LimitChecker checker(machine);
  Interruption result;
  int phase = 0;
  run_program(channel, &checker, [&](int64_t, const HliState& state, HliControl& control) {
    acknowledge(state, control);
    switch (phase) {
      case 0:
        if (state.dist_prog_start >= at_mm * hli_units_per_mm) {
          control.feedhold = {true, true};
          phase = 1;
        }
        break;
      case 1:
        if (state.feedhold.state_r && state.path_velocity == 0 && !state.m_function_request_r) {
          result.stop_dist_mm = state.dist_prog_start / hli_units_per_mm;
          result.stop_block_nr = state.block_nr_r;
          control.reset = {true, true};
          phase = 2;
        }
        break;
      case 2:
        REQUIRE(state.channel_state == ChannelState::ready);
        control.reset = {false, true};
        control.feedhold = {false, true};
        control.block_search.enable_w = true;
        control.block_search.command_w.type = 4;
        control.block_search.command_w.block_nr = static_cast<uint32_t>(result.stop_block_nr);
        control.block_search.command_w.distance = result.stop_dist_mm * hli_units_per_mm;
        control.program_start.command_w = true;
        phase = 3;
        break;
      case 3:
        control.program_start.command_w = false;
        control.block_search.enable_w = false;
        if (state.block_search.state_r.state == block_search_state::continued) {
          const double d = state.dist_prog_start / hli_units_per_mm;
          if (const auto expected = reference_at(reference, d)) {
            const std::vector<double> p = positions(channel);
            for (size_t k = 0; k < p.size(); ++k) result.worst_mm = std::max(result.worst_mm, std::abs(p[k] - (*expected)[k]));
            ++result.compared;
          }
        }
        break;
    }
  });
  INFO("stopped at " << result.stop_dist_mm << " mm in N" << result.stop_block_nr);
  INFO("at the end: block search state " << channel.hli().block_search.state_r.state << ", stop conditions 0x"
                                         << std::hex << channel.hli().stop_conditions_r << std::dec << ", N"
                                         << channel.hli().block_nr_r << ", dist " << channel.hli().dist_prog_start
                                         << ", v " << channel.hli().path_velocity);
  REQUIRE(phase == 3);
  REQUIRE(channel.hli().channel_state == ChannelState::program_end);
  const logger::CheckReport report = checker.finish();
  for (const auto& v : report.violations) FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value);
  const std::vector<double> end = positions(channel);
  for (size_t k = 0; k < end.size(); ++k) CHECK(std::abs(end[k] - reference.end[k]) < 1e-6);
  CHECK(std::abs(channel.hli().dist_prog_start / hli_units_per_mm - reference.end_dist_mm) < 1e-6);
  return result;
}

void check_random_interruptions(const std::string& program, unsigned seed, int count) {
  const MachineConfig machine = test::xyz_machine();
  const Trace reference = uninterrupted(machine, program);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> at(0.0, 0.95 * reference.end_dist_mm);
  for (int i = 0; i < count; ++i) {
    const double d = at(random);
    INFO("feed hold at dist_prog_start " << d << " mm (seed " << seed << ", #" << i << ")");
    const Interruption r = interrupt_and_continue(machine, program, d, reference);
    INFO("stopped at " << r.stop_dist_mm << " mm in N" << r.stop_block_nr << ", " << r.compared << " cycles compared");
    CHECK(r.compared > 0);
    CHECK(r.worst_mm <= 1e-3);  // 1 um
  }
}

}  // namespace

TEST_CASE("DPS-3 channel: interrupted at random distances, a contour of lines and arcs continues on its path",
          "[DPS-3][channel]") {
  check_random_interruptions(
      "N5 #DISTANCE PROG START OFF\n"  // the starting movement: from where the axes stand
      "N10 G90 G01 X0 Y0 Z5 F3000\n"
      "N15 #DISTANCE PROG START ON\n"
      "N20 M3\n"
      "N30 G01 Z0 F1500\n"
      "N40 G01 X40 Y0 F2400\n"
      "N50 G03 X60 Y20 I0 J20\n"
      "N60 G01 Y50\n"
      "N70 G02 X40 Y70 I-20 J0\n"
      "N80 G01 X0 Y70 M8\n"
      "N90 G03 X-20 Y50 I0 J-20\n"
      "N100 G01 X-20 Y10\n"
      "N110 G01 X0 Y0 Z5\n"
      "N120 M30\n",
      301, 8);
}

TEST_CASE("DPS-3 channel: interrupted at random distances, a G91 section continues on its path", "[DPS-3][channel]") {
  check_random_interruptions(
      "N5 #DISTANCE PROG START OFF\n"  // the starting movement: from where the axes stand
      "N10 G90 G01 X0 Y0 Z0 F3000\n"
      "N15 #DISTANCE PROG START ON\n"
      "N20 G91 X10 Y5\n"
      "N30 X10\n"
      "N40 Y10 Z-2\n"
      "N50 G03 X10 Y10 I10 J0\n"
      "N60 G90 G01 X0 Y40\n"
      "N70 G91 X5 Y-5\n"
      "N80 X5 Y-5\n"
      "N90 G90 X0 Y0 Z0\n"
      "N100 M30\n",
      302, 8);
}

TEST_CASE("DPS-3 channel: interrupted at random distances, a $FOR loop continues in the right iteration",
          "[DPS-3][channel]") {
  check_random_interruptions(
      "N5 #DISTANCE PROG START OFF\n"  // the starting movement: from where the axes stand
      "N10 G90 G01 X0 Y0 Z0 F3000\n"
      "N15 #DISTANCE PROG START ON\n"
      "N20 $FOR P1 = 1, 4, 1\n"
      "N30 G91 G01 X10 Y5\n"
      "N40 G03 X10 Y0 I5 J0\n"
      "N50 G01 Y-5\n"
      "N60 $ENDFOR\n"
      "N70 G90 G01 X0 Y0\n"
      "N80 M30\n",
      303, 8);
}

TEST_CASE("DPS-3 channel: interrupted at random distances, #DISTANCE PROG START OFF sections and G92 offsets",
          "[DPS-3][channel]") {
  check_random_interruptions(test::dps_example_program, 304, 8);  // DPS-2
}
