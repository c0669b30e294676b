// RIG-4: a run's log as CSV files outside the rig (logger/csv_export.hpp,
// docs/EXPORT.md): one file per channel, SI units, strings per RFC 4180,
// unknown types and undecodable messages counted, a non-log refused.
#include <catch2/catch.hpp>

#include <hil/axis_setpoint_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "csv_export.hpp"
#include "hli_names.hpp"

using namespace hil;
namespace fs = std::filesystem;

namespace {

void write_bytes(lcm::LogFile& log, const std::string& channel, std::vector<uint8_t> bytes, int64_t timestamp) {
  lcm::LogEvent e;
  e.timestamp = timestamp;
  e.channel = channel;
  e.datalen = static_cast<int32_t>(bytes.size());
  e.data = bytes.data();
  REQUIRE(log.writeEvent(&e) == 0);
}

template <typename T>
std::vector<uint8_t> encoded(const T& msg) {
  std::vector<uint8_t> buf(msg.getEncodedSize());
  msg.encode(buf.data(), 0, static_cast<int>(buf.size()));
  return buf;
}

// An RFC 4180 reader, independent of the writer: rows of fields.
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream all;
  all << in.rdbuf();
  const std::string s = all.str();
  std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
  bool quoted = false;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (quoted) {
      if (c == '"' && i + 1 < s.size() && s[i + 1] == '"') rows.back().back() += '"', ++i;
      else if (c == '"') quoted = false;
      else rows.back().back() += c;
    } else if (c == '"') quoted = true;
    else if (c == ',') rows.back().emplace_back();
    else if (c == '\n') rows.emplace_back(1);
    else rows.back().back() += c;
  }
  if (rows.back() == std::vector<std::string>(1)) rows.pop_back();
  return rows;
}

// Row `i` (0 = the header) as column -> cell.
std::map<std::string, std::string> row(const std::vector<std::vector<std::string>>& csv, size_t i) {
  std::map<std::string, std::string> r;
  REQUIRE(csv.at(i).size() == csv.at(0).size());
  for (size_t k = 0; k < csv[0].size(); ++k) r[csv[0][k]] = csv[i][k];
  return r;
}

double num(const std::string& cell) { return std::stod(cell); }

// An empty folder of this test's own (per process).
fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("RIG-4 export: every channel a CSV file, SI units, RFC 4180 strings, unknown types counted", "[export]") {
  const fs::path dir = fresh_dir("hil_csv_test");
  const std::string log_path = (dir / "run.lcmlog").string();
  {
    lcm::LogFile log(log_path, "w");
    hil::run_manifest_t manifest{};
    manifest.run_id = 7;
    manifest.cycle_us = 2000;
    manifest.rig_version = "v1";
    manifest.scenario_name = "csv";
    write_bytes(log, "HIL_MANIFEST", encoded(manifest), 1'000'000);

    hil::axis_setpoint_t x{};
    x.run_id = 7;
    x.cycle = 5;
    x.utime = 10'000;
    x.axis = "X";
    x.position = 12.5;        // mm
    x.velocity = 100;         // mm/s
    x.acceleration = 2000;    // mm/s^2
    write_bytes(log, "AXIS_X_CMD", encoded(x), 1'000'250);
    hil::axis_setpoint_t c = x;
    c.axis = "C";
    c.position = 90;  // deg
    write_bytes(log, "AXIS_C_CMD", encoded(c), 1'000'300);

    hil::hli_state_t hli{};
    hli.run_id = 7;
    hli.cycle = 6;
    hli.channel_state = hil::hli_state_t::CHANNEL_ACTIVE;
    hli.dist_prog_start = 1e7;  // 0.1 um
    hli.path_velocity = 50;     // mm/s
    hli.n_axes = 2;
    hli.axis_name = {"X", "C"};
    hli.axis_position_r = {123456, 900000};  // 12.3456 mm, 90 deg
    hli.lift_active = {true, false};
    hli.lift_suppressed = {false, false};
    hli.override.state_r = 1000;  // 0.1 %
    hli.stop_conditions_r = hil::stop_condition::feedhold;
    write_bytes(log, "HLI_STATE", encoded(hli), 1'000'400);
    hil::hli_state_t one = hli;  // an array of another length: empty cells
    one.cycle = 7;
    one.n_axes = 1;
    one.axis_name = {"X"};
    one.axis_position_r = {-5000};
    one.lift_active = {false};
    one.lift_suppressed = {false};
    write_bytes(log, "HLI_STATE", encoded(one), 1'000'500);
    std::vector<uint8_t> cut = encoded(one);  // the type's fingerprint, then too short
    cut.resize(20);
    write_bytes(log, "HLI_STATE", cut, 1'000'600);

    hil::event_t event{};
    event.run_id = 7;
    event.cycle = 8;
    event.severity = hil::event_t::SEVERITY_ERROR;
    event.source = "cnc";
    event.message = "a \"quoted\", two-line\nmessage";
    write_bytes(log, "HIL_EVENT", encoded(event), 1'000'700);

    write_bytes(log, "SOMEONE_ELSES", {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 1'000'800);
    write_bytes(log, "AXIS/X_CMD", encoded(x), 1'000'900);  // the same file name as AXIS_X_CMD
  }

  const logger::CsvExport result = logger::export_csv(log_path, (dir / "csv").string());
  CHECK(result.messages == 9);
  REQUIRE(result.cycle_s);
  CHECK(*result.cycle_s == Approx(0.002));
  REQUIRE(result.channels.size() == 6);
  std::map<std::string, logger::CsvChannel> by;
  for (const auto& ch : result.channels) by[ch.channel] = ch;
  CHECK(by["HLI_STATE"].type == "hli_state_t");
  CHECK(by["HLI_STATE"].rows == 2);
  CHECK(by["HLI_STATE"].skipped == 1);
  CHECK(by["HIL_MANIFEST"].simulated_time == false);
  REQUIRE(result.unknown.size() == 1);
  CHECK(result.unknown[0] == std::make_pair(std::string("SOMEONE_ELSES"), int64_t{1}));
  CHECK(!fs::exists(dir / "csv" / "SOMEONE_ELSES.csv"));
  CHECK(fs::path(by["AXIS/X_CMD"].file).filename() == "AXIS_X_CMD_2.csv");
  CHECK(read_csv(by["AXIS/X_CMD"].file).size() == 2);

  const auto cmd = read_csv((dir / "csv" / "AXIS_X_CMD.csv").string());
  REQUIRE(cmd.size() == 2);
  CHECK(cmd[0] == std::vector<std::string>{"t_s", "log_t_s", "run_id", "utime_s", "cycle", "axis", "position_m",
                                           "velocity_m_s", "acceleration_m_s2"});
  auto r = row(cmd, 1);
  CHECK(num(r["t_s"]) == Approx(0.010));  // cycle 5 * 2 ms, simulated
  CHECK(r["log_t_s"] == "0.000250");      // since the log's first message
  CHECK(num(r["utime_s"]) == Approx(0.010));
  CHECK(r["axis"] == "X");
  CHECK(r["position_m"] == "0.0125");
  CHECK(num(r["velocity_m_s"]) == Approx(0.1));
  CHECK(num(r["acceleration_m_s2"]) == Approx(2.0));

  r = row(read_csv((dir / "csv" / "AXIS_C_CMD.csv").string()), 1);
  CHECK(num(r["position_rad"]) == Approx(M_PI / 2));
  CHECK(r.count("position_m") == 0);

  const auto hli = read_csv((dir / "csv" / "HLI_STATE.csv").string());
  REQUIRE(hli.size() == 3);
  r = row(hli, 1);
  CHECK(r["channel_state"] == "1");
  CHECK(r["channel_state_name"] == "ACTIVE");  // issue 37: names beside the numbers
  CHECK(r["stop_conditions_r_names"] == "FEEDHOLD");
  CHECK(num(r["dist_prog_start_m"]) == Approx(1.0));
  CHECK(num(r["path_velocity_m_s"]) == Approx(0.05));
  CHECK(r["axis_name[1]"] == "C");
  CHECK(num(r["axis_position_r.X_m"]) == Approx(0.0123456));  // by the axis' name (issue 37)
  CHECK(num(r["axis_position_r.C_rad"]) == Approx(M_PI / 2));
  CHECK(r["lift_active.X"] == "1");
  CHECK(r["lift_active.C"] == "0");
  CHECK(num(r["override.state_r_ratio"]) == Approx(1.0));
  CHECK(r.count("insert_cmd.state_r.position_at_next_stop[2]_m") == 1);
  CHECK(r.count("block_search.state_r.continuation_distance_m") == 1);
  r = row(hli, 2);
  CHECK(num(r["axis_position_r.X_m"]) == Approx(-0.0005));
  CHECK(r["axis_name[1]"] == "");
  CHECK(r["axis_position_r.C_rad"] == "");

  r = row(read_csv((dir / "csv" / "HIL_EVENT.csv").string()), 1);
  CHECK(r["message"] == "a \"quoted\", two-line\nmessage");
  CHECK(r["severity"] == "2");

  const auto manifest = read_csv((dir / "csv" / "HIL_MANIFEST.csv").string());
  CHECK(manifest[0][0] == "log_t_s");  // no simulated time: the handshake follows the wall clock
  CHECK(num(row(manifest, 1)["cycle_time_s"]) == Approx(0.002));

  SECTION("a file that is not an LCM log is refused") {
    const std::string text = (dir / "notes.txt").string();
    std::ofstream(text) << "just some text, no LCM event log\n";
    CHECK_THROWS_WITH(logger::export_csv(text, (dir / "csv2").string()),
                      Catch::Contains("is not an LCM event log"));
    CHECK_THROWS_WITH(logger::export_csv((dir / "missing.lcmlog").string(), (dir / "csv2").string()),
                      Catch::Contains("cannot open"));
  }
  fs::remove_all(dir);
}

TEST_CASE("RIG-4 export: RFC 4180 quoting", "[export]") {
  CHECK(logger::csv_quoted("plain") == "\"plain\"");
  CHECK(logger::csv_quoted("say \"hi\", then\r\nleave") == "\"say \"\"hi\"\", then\r\nleave\"");
}

// The HLI columns are written field by field (with their units), the HLI
// table (common/hli_table.hpp) lists the fields: a field added to the table
// must not go missing from the export unnoticed.
TEST_CASE("RIG-4 export: every field of the HLI table has its column", "[export]") {
  const fs::path dir = fresh_dir("hil_csv_table_test");
  const std::string log_path = (dir / "run.lcmlog").string();
  {
    lcm::LogFile log(log_path, "w");
    hil::hli_state_t state{};
    state.n_axes = 1;
    state.axis_name = {"X"};
    state.axis_position_r = {0};
    state.lift_active = {false};
    state.lift_suppressed = {false};
    write_bytes(log, "HLI_STATE", encoded(state), 1'000'000);
    write_bytes(log, "HLI_CONTROL", encoded(hil::hli_control_t{}), 1'000'100);
  }
  const logger::CsvExport result = logger::export_csv(log_path, (dir / "csv").string());
  auto has_column = [](const std::vector<std::string>& header, const std::string& field) {
    for (const std::string& column : header)  // the name, or the name and its unit
      if (column == field || column.rfind(field + "_", 0) == 0) return true;
    return false;
  };
  const auto state_header = read_csv((dir / "csv" / "HLI_STATE.csv").string()).at(0);
  for (const HliField<HliState>& f : hli_fields<HliState>()) {
    INFO(f.name);
    CHECK(has_column(state_header, f.name));
  }
  const auto control_header = read_csv((dir / "csv" / "HLI_CONTROL.csv").string()).at(0);
  for (const HliField<HliControl>& f : hli_fields<HliControl>()) {
    INFO(f.name);
    CHECK(has_column(control_header, f.name));
  }
  fs::remove_all(dir);
}
