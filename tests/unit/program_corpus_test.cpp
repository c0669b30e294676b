// KRN-8 (issue 34): the corpus of real-style part programs in
// tests/programs/ (each file says where it came from) decodes unchanged, and
// runs through the channel within every axis' limits to its M30, with the
// PLC acknowledging every technology function. The same programs run
// through the whole rig as scenarios/programs/*.yaml.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "decoder.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;
namespace fs = std::filesystem;

namespace {
// The .nc programs of a folder of the source tree, by name.
std::vector<fs::path> corpus(const std::string& folder = "tests/programs") {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(HIL_SOURCE_DIR) / folder))
    if (entry.path().extension() == ".nc") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string read(const fs::path& file) {
  return test::source_text(fs::relative(file, HIL_SOURCE_DIR).string());
}

// A light router of the kind jscut's programs are written for: every axis
// slower than config/xyz_machine.yaml's, each by other factors, so that the
// path's limits come from another axis in each direction.
MachineConfig light_router() {
  MachineConfig m = test::xyz_machine();
  m.name = "light router";
  const double v[] = {0.5, 0.8, 1}, a[] = {0.25, 0.5, 1}, j[] = {0.2, 0.5, 2};
  for (size_t i = 0; i < 3; ++i) {
    m.axes[i].v_max *= v[i];
    m.axes[i].v_rapid *= v[i];
    m.axes[i].a_max *= a[i];
    m.axes[i].j_max *= j[i];
  }
  return m;
}
}  // namespace

TEST_CASE("KRN-8 corpus: every program of tests/programs decodes unchanged to its M30", "[dialect][corpus]") {
  const std::vector<fs::path> files = corpus();
  CHECK(files.size() >= 10);
  for (const fs::path& file : files) {
    INFO(file.filename().string());
    const DecodedProgram p = decode_program(read(file), test::xyz_machine(), {0, 0, 0});
    if (p.error) FAIL_CHECK(describe(*p.error));
    REQUIRE_FALSE(p.blocks.empty());
    CHECK(p.blocks.back().program_end);
    CHECK(std::count_if(p.blocks.begin(), p.blocks.end(), [](const Block& b) { return b.has_motion; }) > 10);
  }
}

namespace {
// `program` through the channel to its end (at most `max_cycles`), the PLC
// acknowledging every technology function at once: every error event and
// every limit violation fails the test.
void run_within_limits(const MachineConfig& machine, const std::string& program, uint32_t skip_levels,
                       int64_t max_cycles) {
  Channel channel(machine, program);
  logger::LimitChecker checker(machine);
  HliControl c = test::start_command(true);
  c.program_block_ignore = {skip_levels, true};
  for (int64_t k = 0; k < max_cycles && !channel.finished(); ++k) {
    channel.step(k, c);
    checker.add_hli_state(channel.hli());
    for (size_t i = 0; i < channel.setpoints().size(); ++i)
      checker.add_setpoint(static_cast<int>(i), k, channel.setpoints()[i].position);
    c.program_start.command_w = false;
    const HliState& s = channel.hli();
    c.m_function_ack = {s.m_function_request_r && !c.m_function_ack.command_w, true};
    c.h_function_ack = {s.h_function_request_r && !c.h_function_ack.command_w, true};
    c.s_function_ack = {s.s_function_request_r && !c.s_function_ack.command_w, true};
    c.t_function_ack = {s.t_function_request_r && !c.t_function_ack.command_w, true};
    c.continue_motion = {s.stop_conditions_r != 0 && !c.continue_motion.command_w, true};  // M00 / M01
    for (const Event& e : channel.take_events())
      if (e.severity == Severity::error) FAIL_CHECK(describe(e));
  }
  CHECK(channel.hli().channel_state == ChannelState::program_end);
  const logger::CheckReport report = checker.finish();
  for (const auto& v : report.violations) FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value);
}
}  // namespace

TEST_CASE("KRN-8 KRN-3 corpus: every program runs through the channel within the axes' limits, "
          "with and without its skip levels",
          "[dialect][corpus]") {
  const MachineConfig machine = test::xyz_machine();
  for (const fs::path& file : corpus()) {
    for (const uint32_t skip_levels : {0u, 0x3FFu}) {
      INFO(file.filename().string() << ", program_block_ignore " << skip_levels);
      run_within_limits(machine, read(file), skip_levels, 200000);
    }
  }
}

// Real CAM output from public repositories (tests/programs/public/README.md),
// changed only where the dialect lacks a word: as written, contoured (G261)
// and smoothed (#HSC), on config/xyz_machine.yaml and a lighter machine.
TEST_CASE("KRN-8 KRN-3 KRN-6 KRN-9 public corpus: real CAM programs decode and run within the axes' limits, "
          "as written, with G261 and with #HSC",
          "[dialect][corpus]") {
  const std::vector<fs::path> files = corpus("tests/programs/public");
  CHECK(files.size() >= 2);
  const std::string ways[] = {"", "#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n", "#HSC ON [BSPLINE PATH_DEV=0.01 MERGE=1]\n"};
  for (const fs::path& file : files) {
    const std::string program = read(file);
    const DecodedProgram decoded = decode_program(program, test::xyz_machine(), {0, 0, 0});
    if (decoded.error) FAIL_CHECK(file.filename().string() << ": " << describe(*decoded.error));
    for (const MachineConfig& machine : {test::xyz_machine(), light_router()})
      for (const std::string& way : ways) {
        INFO(file.filename().string() << " on " << machine.name << " with '" << way << "'");
        run_within_limits(machine, way + program, 0, 1000000);
      }
  }
}
