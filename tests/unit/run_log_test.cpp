// RIG-4 / RIG-6: reading a rig log back, and comparing two logs.
#include <catch2/catch.hpp>

#include <hil/axis_setpoint_t.hpp>
#include <hil/event_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "channels.hpp"
#include "plot_export.hpp"
#include "run_log.hpp"

using namespace hil;

namespace {

template <typename T>
void write(lcm::LogFile& log, const std::string& channel, const T& msg) {
  std::vector<uint8_t> buf(msg.getEncodedSize());
  msg.encode(buf.data(), 0, static_cast<int>(buf.size()));
  lcm::LogEvent e;
  e.timestamp = 0;
  e.channel = channel;
  e.datalen = static_cast<int32_t>(buf.size());
  e.data = buf.data();
  REQUIRE(log.writeEvent(&e) == 0);
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("hil_test_" + name)).string();
}

// A log of an X axis moving at `v` mm/s for 100 cycles.
void write_log(const std::string& path, double v, bool with_event) {
  std::ifstream machine(std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml");
  std::stringstream yaml;
  yaml << "name: synthetic\nmachine:\n";
  for (std::string line; std::getline(machine, line);) yaml << "  " << line << '\n';
  yaml << "nc_program: \"M30\\n\"\n";
  lcm::LogFile log(path, "w");
  REQUIRE(log.good());
  hil::run_manifest_t manifest;
  manifest.scenario_yaml = yaml.str();
  manifest.rig_version = "test";
  write(log, channels::manifest, manifest);
  for (int k = 0; k < 100; ++k) {
    hil::axis_setpoint_t sp;
    sp.cycle = k;
    sp.axis = "X";
    sp.position = v * k * 0.001;
    write(log, channels::axis_command("X"), sp);
  }
  if (with_event) {
    hil::event_t e;
    e.cycle = 50;
    e.severity = hil::event_t::SEVERITY_WARNING;
    e.id = 50810;
    e.source = "cnc";
    write(log, channels::event, e);
  }
}

}  // namespace

TEST_CASE("RIG-4 run log: a log is read back with its manifest, events and a limit check", "[log]") {
  const std::string path = temp_path("read.lcmlog");
  write_log(path, 300, true);  // X v_max is 250
  std::optional<logger::CheckReport> report;
  const logger::RunLog log = logger::read_run_log(path, &report);
  REQUIRE(log.scenario);
  CHECK(log.scenario->name == "synthetic");
  CHECK(log.rig_version == "test");
  CHECK(log.messages_per_channel.at("AXIS_X_CMD") == 100);
  REQUIRE(log.events.size() == 1);
  CHECK(log.events[0].event.id == 50810);
  CHECK(log.events[0].cycle == 50);
  REQUIRE(report);
  REQUIRE_FALSE(report->passed());
  CHECK(report->violations[0].quantity == "commanded velocity");
  CHECK(report->violations[0].value == Approx(300));
  std::remove(path.c_str());
}

TEST_CASE("RIG-6 run log: comparison finds the first differing message, or none", "[log]") {
  const std::string a = temp_path("a.lcmlog"), b = temp_path("b.lcmlog"), c = temp_path("c.lcmlog");
  write_log(a, 100, false);
  write_log(b, 100, false);
  write_log(c, 101, false);
  CHECK(logger::compare_run_logs(a, b).empty());
  CHECK(logger::compare_run_logs(a, c) == "channel AXIS_X_CMD differs at message 1");
  for (const auto& p : {a, b, c}) std::remove(p.c_str());
}

TEST_CASE("RIG-4 run log: a file that is not an LCM log is an error, not a crash", "[log]") {
  const std::string path = temp_path("garbage.lcmlog");
  std::ofstream(path) << "this is not an LCM log";
  CHECK_THROWS(logger::read_run_log(path));
  CHECK_THROWS(logger::read_run_log(temp_path("does_not_exist")));
  std::remove(path.c_str());
}

TEST_CASE("RIG-4 plots: the traces and a gnuplot script with limit lines and shaded violations", "[log]") {
  const std::string path = temp_path("plot.lcmlog"), dir = temp_path("plots");
  write_log(path, 300, false);  // X v_max is 250: a violation from cycle 1 on
  std::optional<logger::CheckReport> report;
  const logger::RunLog log = logger::read_run_log(path, &report);
  REQUIRE(log.axes.size() == 3);
  CHECK(log.axes[0].cmd_cycle.size() == 100);
  const logger::PlotFiles files = logger::write_plot_files(log, *report, dir);
  REQUIRE(files.images.size() == 5);  // axis_X, axis_Y, axis_Z, xy, path
  CHECK(std::filesystem::path(files.images[3]).filename() == "xy.png");
  CHECK(std::filesystem::path(files.images[0]).filename() == "axis_X.png");
  std::ifstream script(files.script);
  const std::string text((std::istreambuf_iterator<char>(script)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::Contains("set object 1 rect from 0.0005, graph 0"));  // the violation, shaded
  CHECK_THAT(text, Catch::Contains("4000.000000 w l dt 2 lc rgb \"red\" t \"P-AXIS-00442\""));
  CHECK_THAT(text, Catch::Contains("set output \"path.png\""));
  std::ifstream data(dir + "/axis_X.tsv");
  int lines = 0;
  for (std::string line; std::getline(data, line);) lines += line[0] == '#' ? 0 : 1;
  CHECK(lines == 100);
  std::filesystem::remove_all(dir);
  std::remove(path.c_str());
}
