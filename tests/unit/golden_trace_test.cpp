// RIG-7, issue 35: golden traces (logger/golden_trace.hpp, docs/GOLDEN.md):
// a run's setpoints, HLI state and events kept compactly and compared with
// a later run within 1e-9 mm per setpoint, naming channel, cycle, field and
// both values.
#include <catch2/catch.hpp>

#include <hil/axis_setpoint_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "bus.hpp"
#include "event_log_reader.hpp"
#include "golden_trace.hpp"

using namespace hil;
using logger::GoldenTrace;

namespace {

logger::LogRecord setpoint(int64_t cycle, double position_mm, double velocity = 0, double acceleration = 0) {
  hil::axis_setpoint_t m{};
  m.run_id = 1000 + cycle;  // differs from run to run: not kept
  m.utime = cycle * 1000;
  m.cycle = cycle;
  m.axis = "X";
  m.position = position_mm;
  m.velocity = velocity;
  m.acceleration = acceleration;
  return {0, cycle, cycle, "AXIS_X_CMD", lcm_support::encode(m)};
}

logger::LogRecord event(int64_t cycle, const std::string& source, const std::string& message) {
  hil::event_t m{};
  m.cycle = cycle;
  m.utime = cycle * 1000;
  m.source = source;
  m.message = message;
  return {0, cycle, cycle, "HIL_EVENT", lcm_support::encode(m)};
}

// A jerk-limited start, a cruise and a curve's wobble: what the predictor meets.
GoldenTrace motion(double shift_mm_at_cycle_700 = 0) {
  GoldenTrace t;
  for (int64_t k = 0; k < 1000; ++k) {
    const double s = k < 100 ? 1e4 * std::pow(k * 1e-3, 3) / 6 : 1e4 * std::pow(0.1, 3) / 6 + 50 * (k - 100) * 1e-3;
    const double wobble = k > 500 ? 0.3 * std::sin(k * 1e-3 * 7) : 0;
    t.add(setpoint(k, s + wobble + (k == 700 ? shift_mm_at_cycle_700 : 0), 50 + wobble * 10, wobble * 100));
  }
  t.add(event(3, "plc_sim", "PASS at x: all checks hold"));
  t.add(event(3, "cnc", "tab\there, \"quoted\", back\\slash"));
  t.add(setpoint(1000, std::nan("")));
  t.finish();
  return t;
}

const logger::TraceCell& cell(const logger::TraceRow& row, const std::string& name) {
  const auto at = std::find(row.names->begin(), row.names->end(), name);
  REQUIRE(at != row.names->end());
  return row.cells[static_cast<size_t>(at - row.names->begin())];
}

std::string temp_file(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()) + ".trace.xz")).string();
}

}  // namespace

TEST_CASE("RIG-7 a golden trace reads back as it was written, in steps below its tolerance", "[RIG-7][golden]") {
  const GoldenTrace original = motion();
  const std::string path = temp_file("golden_roundtrip");
  original.write(path);
  CHECK(logger::is_golden_trace_file(path));
  const GoldenTrace read = GoldenTrace::read(path);
  std::filesystem::remove(path);
  REQUIRE(read.channels().size() == 2);
  const logger::TraceChannel& x = read.channels()[0];
  CHECK(x.name == "AXIS_X_CMD");
  REQUIRE(x.rows.size() == 1001);
  CHECK(std::find(x.rows[0].names->begin(), x.rows[0].names->end(), "run_id") == x.rows[0].names->end());
  const auto& o = original.channels()[0].rows;
  for (size_t i = 0; i < 1000; ++i)
    for (size_t k = 0; k < o[i].cells.size(); ++k)
      if (o[i].cells[k].kind == logger::CellKind::number)
        REQUIRE(std::fabs(o[i].cells[k].number - x.rows[i].cells[k].number) <=
                logger::golden_tolerance_of((*o[i].names)[k], 0) / 10);
  CHECK(std::isnan(cell(x.rows[1000], "position_m").number));
  // Events of one cycle by content (nodes publish them in wall-clock order); texts kept whole.
  const logger::TraceChannel& e = read.channels()[1];
  REQUIRE(e.rows.size() == 2);
  CHECK(cell(e.rows[0], "source").text == "cnc");
  CHECK(cell(e.rows[0], "message").text == "tab\there, \"quoted\", back\\slash");
  CHECK(cell(e.rows[1], "source").text == "plc_sim");
  CHECK(logger::compare_golden_traces(original, read).same());
  CHECK(logger::compare_golden_traces(read, original).same());
}

TEST_CASE("RIG-7 a golden trace comparison fails beyond 1e-9 mm and names cycle, field and both values",
          "[RIG-7][golden]") {
  const GoldenTrace golden = motion();
  CHECK(logger::compare_golden_traces(golden, motion(0.5e-9)).same());
  const logger::TraceComparison c = logger::compare_golden_traces(golden, motion(2e-9));
  REQUIRE(c.count == 1);
  REQUIRE(c.differences.size() == 1);
  CHECK_THAT(c.differences[0], Catch::Contains("AXIS_X_CMD message 700 cycle 700 position_m: golden 0.") &&
                                   Catch::Contains(", now 0."));
  // Missing messages and channels are differences too.
  GoldenTrace shorter;
  for (int64_t k = 0; k < 10; ++k) shorter.add(setpoint(k, 0));
  const logger::TraceComparison s = logger::compare_golden_traces(golden, shorter, 3);
  CHECK(s.differences.size() == 3);
  const logger::TraceComparison all = logger::compare_golden_traces(golden, shorter, 1000);
  CHECK(all.count == s.count);
  CHECK(std::find(all.differences.begin(), all.differences.end(), "AXIS_X_CMD: 1001 message(s) golden, 10 now") !=
        all.differences.end());
  CHECK(all.differences.back() == "HIL_EVENT: 2 message(s) in the golden trace, none now");
}

TEST_CASE("RIG-7 a file that is no golden trace is refused with its place", "[RIG-7][golden]") {
  CHECK_THROWS_WITH(GoldenTrace::parse("something else\n", "f"), Catch::Contains("f:1: not a golden trace"));
  CHECK_THROWS_WITH(GoldenTrace::parse("hil golden trace 1\n@AXIS_X_CMD\taxis_setpoint_t\n=n:position_m\n12x\n", "f"),
                    Catch::Contains("f:4: '12x' is no whole number"));
  CHECK_THROWS_WITH(GoldenTrace::parse("hil golden trace 1\n@AXIS_X_CMD\taxis_setpoint_t\n=n:a\tn:b\n1\n", "f"),
                    Catch::Contains("f:4: 1 cells where the columns are 2"));
  const std::string path = temp_file("golden_not_xz");
  std::ofstream(path) << "hil golden trace 1\n";
  CHECK_FALSE(logger::is_golden_trace_file(path));
  CHECK_THROWS_WITH(GoldenTrace::read(path), Catch::Contains("not a whole xz stream"));
  std::filesystem::remove(path);
}
