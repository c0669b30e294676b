// KRN-8 (issue 34): the corpus of real-style part programs in
// tests/programs/ (each file says where it came from) decodes unchanged, and
// runs through the channel within every axis' limits to its M30, with the
// PLC acknowledging every technology function. The same programs run
// through the whole rig as scenarios/programs/*.yaml.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "channel.hpp"
#include "channel_runner.hpp"
#include "decoder.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;
namespace fs = std::filesystem;

namespace {
std::vector<fs::path> corpus() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(HIL_SOURCE_DIR) / "tests" / "programs"))
    if (entry.path().extension() == ".nc") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
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

TEST_CASE("KRN-8 KRN-3 corpus: every program runs through the channel within the axes' limits, "
          "with and without its skip levels",
          "[dialect][corpus]") {
  const MachineConfig machine = test::xyz_machine();
  for (const fs::path& file : corpus()) {
    for (const uint32_t skip_levels : {0u, 0x3FFu}) {
      INFO(file.filename().string() << ", program_block_ignore " << skip_levels);
      Channel channel(machine, read(file));
      logger::LimitChecker checker(machine);
      HliControl c = test::start_command(true);
      c.program_block_ignore = {skip_levels, true};
      int64_t k = 0;
      for (; k < 200000 && !channel.finished(); ++k) {
        channel.step(k, c);
        checker.add_hli_state(channel.hli());
        for (size_t i = 0; i < channel.setpoints().size(); ++i)
          checker.add_setpoint(static_cast<int>(i), k, channel.setpoints()[i].position);
        c.program_start.command_w = false;
        const HliState& s = channel.hli();
        // The PLC acknowledges every technology function at once.
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
  }
}
