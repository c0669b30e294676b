// RIG-11 (issue 33, item 5b): every number of a machine file lies in a
// physical range (common/machine_ranges.hpp), refused at load naming the
// key, the value and the range. Machine limits of 1e-320 and a kv of 2^31
// used to pass: the axis never moved and the run timed out naming nothing.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "machine_config.hpp"
#include "scenario.hpp"

using namespace hil;
namespace fs = std::filesystem;

namespace {

const std::string axis_x = "{name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}";

// A machine of one axis `name` with `key` set to `value` (as written in a
// file) and `extra` keys besides.
MachineConfig with(const std::string& key, const std::string& value, const std::string& extra = "",
                   const std::string& name = "X") {
  YAML::Node axis = YAML::Load(axis_x);
  axis["name"] = name;
  if (!extra.empty())
    for (const auto& item : YAML::Load("{" + extra + "}")) axis[item.first.Scalar()] = item.second.Scalar();
  axis[key] = value;
  YAML::Node machine;
  machine["axes"].push_back(axis);
  return parse_machine_config(YAML::Load(YAML::Dump(machine)));  // read back from text, as from a file
}

MachineConfig channel_with(const std::string& top) {
  return parse_machine_config(YAML::Load(top + "axes:\n  - " + axis_x + "\n"));
}

// One key's range: the bounds accepted, a value beyond each refused, and the
// range as the message says it.
struct KeyRange {
  std::string key, lowest, highest, too_low, too_high, range, extra;
};

void check_range(const KeyRange& r, const std::string& name = "X") {
  INFO(r.key << " on axis " << name);
  CHECK_NOTHROW(with(r.key, r.lowest, r.extra, name));
  CHECK_NOTHROW(with(r.key, r.highest, r.extra, name));
  for (const std::string& bad : {r.too_low, r.too_high})
    CHECK_THROWS_WITH(with(r.key, bad, r.extra, name),
                      "machine.axes[0]." + r.key + ": must be a number " + r.range + ", not " + bad);
}

}  // namespace

TEST_CASE("RIG-11 issue 33: limits of 1e-320 and a kv of 2^31 are refused, naming key, value and range",
          "[config][RIG-11]") {
  CHECK_THROWS_WITH(with("j_max", "1e-320"),
                    "machine.axes[0].j_max: must be a number within 0.1 .. 1e+09 mm/s^3, not 1e-320");
  CHECK_THROWS_WITH(with("a_max", "1e-320"),
                    "machine.axes[0].a_max: must be a number within 0.01 .. 1e+07 mm/s^2, not 1e-320");
  CHECK_THROWS_WITH(with("kv", "2147483648"),
                    "machine.axes[0].kv: must be a number within 0.1 .. 10000 1/s, not 2147483648");
  // 1e-320 lies within 0 .. 1, but no double holds it as a normal number.
  CHECK_THROWS_WITH(with("velocity_feedforward", "1e-320"),
                    "machine.axes[0].velocity_feedforward: must be a number within 0 .. 1, not 1e-320 (below the "
                    "smallest normal double, 2.2e-308: write 0 for none)");
}

TEST_CASE("RIG-11 machine ranges: the axis' limits v_max, v_rapid, a_max, j_max", "[config][RIG-11]") {
  check_range({"v_max", "0.001", "1e5", "0.0005", "2e5", "within 0.001 .. 100000 mm/s", ""});
  check_range({"v_rapid", "0.001", "1e5", "0.0005", "2e5", "within 0.001 .. 100000 mm/s", "v_max: 1e5"});
  check_range({"a_max", "0.01", "1e7", "0.005", "2e7", "within 0.01 .. 1e+07 mm/s^2", ""});
  check_range({"j_max", "0.1", "1e9", "0.05", "2e9", "within 0.1 .. 1e+09 mm/s^3", ""});
  // A rotary axis says its units: deg.
  CHECK_THROWS_WITH(with("j_max", "2e9", "", "C"),
                    "machine.axes[0].j_max: must be a number within 0.1 .. 1e+09 deg/s^3, not 2e9");
  CHECK_THROWS_WITH(with("v_max", "-1", "", "C"),
                    "machine.axes[0].v_max: must be a number within 0.001 .. 100000 deg/s, not -1");
}

TEST_CASE("RIG-11 machine ranges: the drive model (RIG-3)", "[config][RIG-11]") {
  check_range({"kv", "0.1", "1e4", "0.05", "2e4", "within 0.1 .. 10000 1/s", ""});
  check_range({"velocity_lag_s", "1e-5", "10", "5e-6", "20", "within 1e-05 .. 10 s", ""});
  check_range({"velocity_damping", "0.01", "10", "0.005", "20", "within 0.01 .. 10", ""});
  check_range({"velocity_feedforward", "0", "1", "-0.1", "1.5", "within 0 .. 1", ""});
  check_range({"drive_acceleration_limit", "0.01", "1e7", "0", "2e7", "within 0.01 .. 1e+07 mm/s^2", ""});
  check_range({"friction_coulomb", "0", "1e7", "-1", "2e7", "within 0 .. 1e+07 mm/s^2", ""});
  check_range({"friction_viscous", "0", "1e4", "-1", "2e4", "within 0 .. 10000 1/s", ""});
  CHECK_THROWS_WITH(with("velocity_loop_order", "3"),
                    "machine.axes[0].velocity_loop_order: must be a whole number within 1 .. 2, not 3");
}

TEST_CASE("RIG-11 machine ranges: following error, software limit switches, positions", "[config][RIG-11]") {
  check_range({"slep_max", "1e-4", "1e3", "5e-5", "2e3", "within 0.0001 .. 1000 mm", ""});
  check_range({"slep_min", "1e-4", "1e3", "5e-5", "2e3", "within 0.0001 .. 1000 mm", "slep_max: 1"});
  check_range({"swe_neg", "-1e6", "-1", "-2e6", "2e6", "within -1e+06 .. 1e+06 mm", "swe_pos: 1e6"});
  check_range({"swe_pos", "1", "1e6", "-2e6", "2e6", "within -1e+06 .. 1e+06 mm", "swe_neg: -1e6"});
  check_range({"swe_toleranz", "0", "1e3", "-0.1", "2e3", "within 0 .. 1000 mm", "swe_neg: -5, swe_pos: 5"});
  check_range({"reference_position", "-1e6", "1e6", "-2e6", "2e6", "within -1e+06 .. 1e+06 mm", ""});
  check_range({"modulo_upper", "1e3", "1e6", "-2e6", "2e6", "within -1e+06 .. 1e+06 deg", "modulo_lower: -1"},
              "C");
  check_range({"modulo_lower", "-1e6", "0", "-2e6", "2e6", "within -1e+06 .. 1e+06 deg", "modulo_upper: 360"},
              "C");
  CHECK_THROWS_WITH(with("modulo_upper", "1e-3", "modulo_lower: 0", "C"),
                    Catch::Contains("modulo_upper - modulo_lower must be at least 1 deg"));
  CHECK(with("modulo_upper", "1", "modulo_lower: 0", "C").axes[0].modulo_range() == 1);
}

TEST_CASE("RIG-11 machine ranges: monitoring per mille P-AXIS-00439 .. 00442 and watchdog cycles",
          "[config][RIG-11]") {
  for (const std::string key :
       {"dyn_monitoring_a_warn", "dyn_monitoring_a_err", "dyn_monitoring_v_warn", "dyn_monitoring_v_err"}) {
    INFO(key);
    const bool warning = key.find("warn") != std::string::npos;
    const std::string pair = key.substr(0, key.size() - (warning ? 4 : 3)) + (warning ? "err: 10000" : "warn: 1000");
    CHECK_NOTHROW(with(key, "1000", pair));
    CHECK_NOTHROW(with(key, "10000", pair));
    CHECK_THROWS_WITH(with(key, "10001", pair),
                      "machine.axes[0]." + key + ": must be a whole number within 1000 .. 10000, not 10001");
    // Below 1000 the limit would lie under a_max / v_max: a percentage was meant.
    CHECK_THROWS_WITH(with(key, "50", pair), Catch::Contains(key + " must be >= 1000"));
  }
  CHECK(with("watchdog_cycles", "100000").axes[0].watchdog_cycles == 100000);
  CHECK_THROWS_WITH(with("watchdog_cycles", "100001"),
                    "machine.axes[0].watchdog_cycles: must be a whole number within 1 .. 100000, not 100001");
  CHECK(channel_with("plc_watchdog_cycles: 1\n").plc_watchdog_cycles == 1);
  CHECK_THROWS_WITH(channel_with("plc_watchdog_cycles: 1e6\n"),
                    "machine.plc_watchdog_cycles: must be a whole number within 1 .. 100000, not 1e6");
}

TEST_CASE("RIG-11 machine ranges: the channel's numbers", "[config][RIG-11]") {
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"cycle_time_us: 99\n", "machine.cycle_time_us: must be a whole number within 100 .. 100000, not 99"},
      {"cycle_time_us: 100001\n", "machine.cycle_time_us: must be a whole number within 100 .. 100000, not 100001"},
      {"override_max_percent: 201\n", "machine.override_max_percent: must be a whole number within 100 .. 200"},
      {"fb_storage_size: 4294967296\n",
       "machine.fb_storage_size: must be a whole number within 0 .. 4294967295, not 4294967296"},
      {"lift_min_dist: 4294967296\n", "machine.lift_min_dist: must be a whole number within 0 .. 4294967295"},
      {"m_pre_outp: {7: 2e10}\n", "machine.m_pre_outp[7]: must be a number within 0 .. 1e+10 x 0.1 um, not 2e10"},
      {"m_pre_outp: {7: 1e-320}\n", "machine.m_pre_outp[7]: must be a number within 0 .. 1e+10 x 0.1 um, not 1e-320"},
  };
  for (const auto& [yaml, message] : refused) {
    INFO(yaml);
    CHECK_THROWS_WITH(channel_with(yaml), Catch::StartsWith(message));
  }
  const MachineConfig widest =
      channel_with("cycle_time_us: 100000\noverride_max_percent: 200\nfb_storage_size: 4294967295\n"
                   "m_pre_outp: {7: 1e10}\nlift_min_dist: 4294967295\n");
  CHECK(widest.cycle_time_us == 100000);
  CHECK(widest.fb_storage_size == 4294967295);
  CHECK(widest.m_pre_output_mm.at(7) == Approx(1e6));
}

TEST_CASE("RIG-11 numbers that underflow a double are refused in every file; 0 stays 0", "[config][RIG-11]") {
  CHECK_THROWS_WITH(with("velocity_feedforward", "1e-400"), Catch::Contains("not 1e-400 (below the smallest normal"));
  CHECK_THROWS_WITH(with("friction_viscous", "4.9e-324"), Catch::Contains("not 4.9e-324 (below the smallest normal"));
  for (const std::string zero : {"0", "0.0", "-0", "0e5", "0.000"})
    CHECK(with("velocity_feedforward", zero).axes[0].velocity_feedforward == 0);
  CHECK(with("velocity_feedforward", "2.3e-308").axes[0].velocity_feedforward == Approx(2.3e-308));
  // A scenario's numbers go through the same reader.
  CHECK_THROWS_WITH(parse_scenario(YAML::Load("machine:\n  axes:\n    - " + axis_x +
                                              "\nnc_program: \"M30\\n\"\nrun: {settle_time_s: 1e-320}\n")),
                    Catch::Contains("run.settle_time_s: must be a number within 0 .. 1e+06, not 1e-320 (below"));
}

TEST_CASE("RIG-11 a machine file's range error names the file, the key, the value and the range",
          "[config][RIG-11]") {
  const fs::path dir = fs::temp_directory_path() / ("hil_machine_ranges_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ifstream source(std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml");
  std::string text((std::istreambuf_iterator<char>(source)), std::istreambuf_iterator<char>());
  const std::string z_jerk = "j_max: 30000";
  REQUIRE(text.find(z_jerk) != std::string::npos);
  text.replace(text.find(z_jerk), z_jerk.size(), "j_max: 1e-320");
  std::ofstream(dir / "machine.yaml") << text;
  std::ofstream(dir / "s.yaml") << "machine: machine.yaml\nnc_program: \"M30\\n\"\n";
  CHECK_THROWS_WITH(load_scenario_file((dir / "s.yaml").string()),
                    (dir / "machine.yaml").string() +
                        ": machine.axes[2].j_max: must be a number within 0.1 .. 1e+09 mm/s^3, not 1e-320 (the "
                        "machine of " +
                        (dir / "s.yaml").string() + ")");
  fs::remove_all(dir);
}
