// RIG-5 (issue "A verdict you can trust", 5 and 3): what the scenario and
// machine loaders refuse. A typo'd key used to be ignored (a run passing on
// zero checks, or without following-error monitoring), .nan / .inf passed as
// numbers, a directory read as an empty NC program.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "config_error.hpp"
#include "scenario.hpp"
#include "scenario_set.hpp"

using namespace hil;
namespace fs = std::filesystem;

namespace {

const std::string axis_x = "{name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002";
const std::string machine_yaml = "machine:\n  axes:\n    - " + axis_x + "}\n    - " +
                                 "{name: Y, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}\n";

Scenario scenario(const std::string& rest) {
  return parse_scenario(YAML::Load(machine_yaml + "nc_program: \"G01 X1 F100\\n\"\n" + rest));
}

AxisConfig axis(const std::string& extra) {
  return parse_machine_config(YAML::Load("axes:\n  - " + axis_x + extra + "}\n")).axes.at(0);
}

// A fresh folder for files, removed at the end of the test.
struct TempDir {
  fs::path path = fs::temp_directory_path() / ("hil_config_input_" + std::to_string(::getpid()));
  TempDir() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return (path / name).string();
  }
};

}  // namespace

TEST_CASE("RIG-5 closest key: typos, swapped letters, case and prefixes; nothing near suggests nothing", "[config]") {
  const std::vector<std::string> keys = {"slep_max", "slep_min", "swe_toleranz", "expect", "expect_events"};
  CHECK(closest_key("slep_mx", keys) == "slep_max");
  CHECK(closest_key("slpe_max", keys) == "slep_max");
  CHECK(closest_key("SLEP_MIN", keys) == "slep_min");
  CHECK(closest_key("swe_tolerance", keys) == "swe_toleranz");
  CHECK(closest_key("expectations", keys) == "expect");
  CHECK(closest_key("expect_event", keys) == "expect_events");
  CHECK(closest_key("velocity", keys).empty());
  CHECK(std::string(unknown_key("run", "wall", {"a", "b"}).what()) == "run.wall: unknown key (known: a, b)");
}

TEST_CASE("RIG-5 unknown keys are refused in every mapping the loaders read, with the path and the closest key",
          "[config]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"expectations:\n  - when: program_end\n", "expectations: unknown key, did you mean expect?"},
      {"run: {max_time: 5}\n", "run.max_time: unknown key, did you mean max_time_s?"},
      {"run: {settle_time: 1}\n", "run.settle_time: unknown key, did you mean settle_time_s?"},
      {"plc: {m_function_ack_cylces: 3}\n",
       "plc.m_function_ack_cylces: unknown key, did you mean m_function_ack_cycles?"},
      {"plc: {timline: []}\n", "plc.timline: unknown key, did you mean timeline?"},
      {"plc:\n  timeline:\n    - {wen: {cycle: 1}, set: {feedhold.command_w: true}}\n",
       "plc.timeline[0].wen: unknown key, did you mean when?"},
      {"plc:\n  timeline:\n    - {when: {cycel: 1}, set: {feedhold.command_w: true}}\n",
       "plc.timeline[0].when.cycel: unknown key, did you mean cycle?"},
      {"expect:\n  - {when: {block_nr_r: 20}, tolerance: 0.1}\n",
       "expect[0].tolerance: unknown key, did you mean tolerance_mm?"},
      {"expect:\n  - {when: program_end, axis_positions_mm: {X: 1}}\n",
       "expect[0].axis_positions_mm: unknown key, did you mean axis_position_mm?"},
      {"expect:\n  - {when: program_end, chanel_state: ERROR}\n",
       "expect[0].chanel_state: unknown key, did you mean channel_state?"},
      {"expect:\n  - {when: {dist_prog_start: 5}}\n",
       "expect[0].when.dist_prog_start: unknown key, did you mean dist_prog_start_mm?"},
      {"expect_events:\n  - {id: 0, count: 2}\n", "expect_events[0].count: unknown key, did you mean count_min?"},
      {"expect_events:\n  - {id: 0, severtiy: error}\n",
       "expect_events[0].severtiy: unknown key, did you mean severity?"},
      {"expect_events:\n  - {id: 0, absnet: true}\n", "expect_events[0].absnet: unknown key, did you mean absent?"},
      {"expect_violations:\n  - {axis: X, quantitiy: following error}\n",
       "expect_violations[0].quantitiy: unknown key, did you mean quantity?"},
      {"run: {max_time_s: 5, max_time_s: 50}\n", "run.max_time_s: given twice"},
  };
  for (const auto& [yaml, message] : cases) {
    INFO(yaml);
    CHECK_THROWS_WITH(scenario(yaml), Catch::Contains(message));
  }
  auto machine = [](const std::string& top, const std::string& second_axis) {
    return parse_machine_config(YAML::Load(top + "axes:\n  - " + axis_x +
                                           "}\n  - {name: Y, v_max: 100, "
                                           "a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002" +
                                           second_axis + "}\n"));
  };
  CHECK_THROWS_WITH(machine("", ", slep_mx: 0.5"),
                    Catch::Contains("machine.axes[1].slep_mx: unknown key, did you mean slep_max?"));
  CHECK_THROWS_WITH(
      machine("", ", dyn_monitoring_a_er: 3000"),
      Catch::Contains("machine.axes[1].dyn_monitoring_a_er: unknown key, did you mean dyn_monitoring_a_err?"));
  CHECK_THROWS_WITH(machine("", ", swe_tolerance: 1"), Catch::Contains("did you mean swe_toleranz?"));
  CHECK_THROWS_WITH(machine("cycle_time: 2000\n", ""),
                    Catch::Contains("machine.cycle_time: unknown key, did you mean cycle_time_us?"));
  CHECK_THROWS_WITH(machine("fb_storage: 1000\n", ""), Catch::Contains("did you mean fb_storage_size?"));
  // Keys that only mean something with another one are not silently ignored either.
  CHECK_THROWS_WITH(machine("", ", slep_min: 0.1"),
                    Catch::Contains("P-AXIS-00169 slep_min needs P-AXIS-00168 slep_max"));
  CHECK_THROWS_WITH(machine("", ", swe_toleranz: 0.2"), Catch::Contains("P-AXIS-00179 swe_toleranz needs"));
  CHECK_THROWS_WITH(scenario("expect_events:\n  - {id: 0, absent: true, count_min: 2}\n"),
                    Catch::Contains("expect_events[0]: give 'count_min' or 'absent: true', not both"));
  CHECK_THROWS_WITH(scenario("expect_violations:\n  - {axis: X, quantity: ''}\n"),
                    Catch::Contains("expect_violations[0].quantity: must not be empty"));
}

TEST_CASE("RIG-5 a scenario file's errors name the file: its machine file's and NC file's too", "[config]") {
  TempDir dir;
  dir.write("machine.yaml", "name: m\naxes:\n  - " + axis_x +
                                "}\n  - {name: Y, v_max: 100, a_max: 1000, "
                                "j_max: 10000, kv: 40, velocity_lag_s: 0.002, slep_mx: 0.5}\n");
  const std::string with_machine = dir.write("s.yaml", "machine: machine.yaml\nnc_program: \"M30\\n\"\n");
  CHECK_THROWS_WITH(load_scenario_file(with_machine),
                    Catch::Contains(dir.path.string() +
                                    "/machine.yaml: machine.axes[1].slep_mx: unknown key, did "
                                    "you mean slep_max? (the machine of " +
                                    with_machine + ")"));
  const std::string typo = dir.write("t.yaml", machine_yaml + "nc_program: \"M30\\n\"\nrun: {max_time: 5}\n");
  CHECK_THROWS_WITH(load_scenario_file(typo), Catch::Contains(typo + ": run.max_time: unknown key"));
}

TEST_CASE("RIG-5 a directory where a file is expected is refused: scenario, machine, nc_file", "[config]") {
  TempDir dir;
  fs::create_directories(dir.path / "folder");
  const std::string folder = (dir.path / "folder").string();
  CHECK_THROWS_WITH(load_scenario_file(folder), Catch::Contains(folder + ": scenario is a directory, not a file"));
  const std::string machine = dir.write("m.yaml", "machine: folder\nnc_program: \"M30\\n\"\n");
  CHECK_THROWS_WITH(load_scenario_file(machine), Catch::Contains("folder: machine file is a directory, not a file"));
  const std::string nc = dir.write("n.yaml", machine_yaml + "nc_file: folder\n");
  CHECK_THROWS_WITH(load_scenario_file(nc), Catch::Contains("folder: NC program is a directory, not a file"));
}

TEST_CASE("RIG-5 an NC program with NUL bytes or other binary is refused, naming the line", "[config]") {
  TempDir dir;
  const char binary[] =
      "N10 G01 X1 F100\nN20 X2\nN30 X\0"
      "3\nN40 M30\n";
  dir.write("part.nc", std::string(binary, sizeof binary - 1));
  const std::string s = dir.write("s.yaml", machine_yaml + "nc_file: part.nc\n");
  CHECK_THROWS_WITH(load_scenario_file(s),
                    Catch::Contains(dir.path.string() + "/part.nc: line 3: byte 0x00 (NUL) is not text"));
  dir.write("escape.nc", "N10 G01 X1 F100\n\x1b[0mN20 M30\n");
  const std::string e = dir.write("e.yaml", machine_yaml + "nc_file: escape.nc\n");
  CHECK_THROWS_WITH(load_scenario_file(e), Catch::Contains("escape.nc: line 2: byte 0x1B is not text"));
  CHECK_THROWS_WITH(parse_scenario(YAML::Load(machine_yaml + "nc_program: \"N10 G01 X1\\nN20 \\0\"\n")),
                    Catch::Contains("nc_program: line 2: byte 0x00 (NUL) is not text"));
  // Text passes: tabs, CR LF line ends, comments in UTF-8 or Latin-1.
  const std::string text =
      "N10 G01\tX1 F100 ; Stirnfl\xc3\xa4"
      "che\r\nN20 M30 ( \xb5m )\r\n";
  dir.write("text.nc", text);
  CHECK(load_scenario_file(dir.write("ok.yaml", machine_yaml + "nc_file: text.nc\n")).nc_program == text);
}

TEST_CASE("RIG-5 scenario numbers: run times, counts and tolerances must be finite and in range", "[config]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"run: {max_time_s: .inf}\n", "run.max_time_s: must be a number > 0 and <= 1e+06, not .inf"},
      {"run: {max_time_s: .nan}\n", "run.max_time_s: must be a number > 0"},
      {"run: {max_time_s: 0}\n", "run.max_time_s: must be a number > 0"},
      {"run: {max_time_s: -1}\n", "run.max_time_s: must be a number > 0"},
      {"run: {settle_time_s: .nan}\n", "run.settle_time_s: must be a number within 0 .. 1e+06, not .nan"},
      {"run: {settle_time_s: -0.1}\n", "run.settle_time_s: must be a number within 0 .. 1e+06"},
      {"run: {settle_time_s: .inf}\n", "run.settle_time_s: must be a number within 0 .. 1e+06"},
      {"run: {allow_errors: maybe}\n", "run.allow_errors: must be true or false, not maybe"},
      {"plc: {m_function_ack_cycles: -1}\n",
       "plc.m_function_ack_cycles: must be a whole number within 0 .. 2147483647"},
      {"plc: {m_function_ack_cycles: 2.5}\n", "plc.m_function_ack_cycles: must be a whole number"},
      {"plc: {m_function_ack_cycles: .nan}\n", "plc.m_function_ack_cycles: must be a whole number"},
      {"plc: {m_function_ack_cycles: 3000000000}\n", "plc.m_function_ack_cycles: must be a whole number"},
      {"plc:\n  timeline:\n    - {when: {cycle: -5}, set: {feedhold.command_w: true}}\n",
       "plc.timeline[0].when.cycle: must be a whole number within 0"},
      {"plc:\n  timeline:\n    - {when: {cycle: 1.5}, set: {feedhold.command_w: true}}\n",
       "plc.timeline[0].when.cycle: must be a whole number"},
      {"plc:\n  timeline:\n    - {when: {time_s: .nan}, set: {feedhold.command_w: true}}\n",
       "plc.timeline[0].when.time_s: must be a number >= 0, not .nan"},
      {"expect:\n  - {when: {dist_prog_start_mm: .inf}}\n",
       "expect[0].when.dist_prog_start_mm: must be a finite number"},
      {"expect:\n  - {when: {m_function_nr_r: -3}}\n", "expect[0].when.m_function_nr_r: must be a whole number"},
      {"expect:\n  - {when: program_end, block_nr_r: -10}\n", "expect[0].block_nr_r: must be a whole number"},
      {"expect:\n  - {when: program_end, tolerance_mm: .nan}\n",
       "expect[0].tolerance_mm: must be a number >= 0, not .nan"},
      {"expect:\n  - {when: program_end, tolerance_mm: -0.001}\n", "expect[0].tolerance_mm: must be a number >= 0"},
      {"expect:\n  - {when: program_end, tolerance_mm: .inf}\n", "expect[0].tolerance_mm: must be a number >= 0"},
      {"expect:\n  - {when: program_end, dist_prog_start_mm: .nan}\n",
       "expect[0].dist_prog_start_mm: must be a finite number"},
      {"expect:\n  - {when: program_end, axis_position_mm: {X: .nan}}\n",
       "expect[0].axis_position_mm.X: must be a finite number, not .nan"},
      {"expect_events:\n  - {id: 0, count_min: -1}\n", "expect_events[0].count_min: must be a whole number within 0"},
      {"expect_events:\n  - {id: 0, count_min: 1.5}\n", "expect_events[0].count_min: must be a whole number"},
      {"expect_events:\n  - {id: -2}\n", "expect_events[0].id: must be a whole number within 0"},
      {"expect_events:\n  - {id: 0, nc_line: -1}\n", "expect_events[0].nc_line: must be a whole number within 0"},
      {"requirements: RIG-5\n", "requirements: must be a list"},
  };
  for (const auto& [yaml, message] : cases) {
    INFO(yaml);
    CHECK_THROWS_WITH(scenario(yaml), Catch::Contains(message));
  }
  // Whole numbers may be written as 1e3 or 5.0; a tolerance may be 0.
  const Scenario s =
      scenario("plc: {m_function_ack_cycles: 1e3}\nexpect:\n  - {when: {cycle: 5.0}, tolerance_mm: 0}\n");
  CHECK(s.m_function_ack_cycles == 1000);
  CHECK(s.expectations.at(0).when.cycle->min == 5);
}

TEST_CASE("RIG-3 RIG-4 machine numbers: NaN and infinity are refused in every numeric parameter", "[config]") {
  // clang-format off
  const std::vector<std::string> numeric = {
      "v_max", "v_rapid", "a_max", "j_max", "kv", "velocity_lag_s", "velocity_loop_order", "velocity_damping",
      "velocity_feedforward", "drive_acceleration_limit", "friction_coulomb", "friction_viscous",
      "dyn_monitoring_a_warn", "dyn_monitoring_a_err", "dyn_monitoring_v_warn", "dyn_monitoring_v_err", "slep_max",
      "following_error_monitoring", "swe_toleranz"};
  // clang-format on
  for (const std::string& key : numeric)
    for (const std::string value : {".nan", ".inf", "-.inf"}) {
      INFO(key << ": " << value);
      YAML::Node a = YAML::Load(axis_x + "}");
      a[key] = value;  // read back from its text, as from a file
      if (key == "swe_toleranz") a["swe_neg"] = -1, a["swe_pos"] = 1;
      YAML::Node machine;
      machine["axes"].push_back(a);
      CHECK_THROWS_WITH(parse_machine_config(machine), Catch::Contains("machine.axes[0]." + key + ": must be a "));
    }
  const std::vector<std::pair<std::string, std::string>> axis_cases = {
      {", slep_max: 0.5, slep_min: .nan",
       "machine.axes[0].slep_min: must be a number within 0.0001 .. 1000 mm, not .nan"},
      {", swe_neg: .nan, swe_pos: 5", "machine.axes[0].swe_neg: must be a number within -1e+06 .. 1e+06 mm, not .nan"},
      {", swe_neg: -5, swe_pos: .inf", "machine.axes[0].swe_pos: must be a number within -1e+06 .. 1e+06 mm, not .inf"},
      {", dyn_monitoring_a_err: 2000.5", "machine.axes[0].dyn_monitoring_a_err: must be a whole number"},
  };
  for (const auto& [yaml, message] : axis_cases) CHECK_THROWS_WITH(axis(yaml), Catch::Contains(message));
  auto machine = [](const std::string& top) {
    return parse_machine_config(YAML::Load(top + "axes:\n  - " + axis_x + "}\n"));
  };
  const std::vector<std::pair<std::string, std::string>> machine_cases = {
      {"cycle_time_us: .nan\n", "machine.cycle_time_us: must be a whole number within 100 .. 100000, not .nan"},
      {"cycle_time_us: 1000.5\n", "machine.cycle_time_us: must be a whole number"},
      {"override_max_percent: .inf\n", "machine.override_max_percent: must be a whole number"},
      {"fb_storage_size: -1\n", "machine.fb_storage_size: must be a whole number within 0"},
      {"m_pre_outp: {7: .nan}\n", "machine.m_pre_outp[7]: must be a number within 0 .. 1e+10 x 0.1 um, not .nan"},
      {"m_pre_outp: {-7: 10}\n", "machine.m_pre_outp: must be a whole number within 0"},
      {"name: [a]\n", "machine.name: must be text, not a list"},
  };
  for (const auto& [yaml, message] : machine_cases) CHECK_THROWS_WITH(machine(yaml), Catch::Contains(message));
  CHECK(machine("cycle_time_us: 2e3\n").cycle_time_us == 2000);
}

TEST_CASE("RIG-5 every scenario and machine file of the repository loads", "[config]") {
  int files = 0;
  for (const char* folder : {"scenarios", "tests/integration/scenarios"})
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(HIL_SOURCE_DIR) / folder)) {
      if (entry.path().extension() != ".yaml" || entry.path().filename() == "unknown_control_field.yaml") continue;
      INFO(entry.path());
      CHECK_NOTHROW(load_scenario_set(entry.path().string()));  // with or without variants
      ++files;
    }
  for (const auto& entry : fs::directory_iterator(fs::path(HIL_SOURCE_DIR) / "config")) {
    INFO(entry.path());
    CHECK_NOTHROW(parse_machine_config(YAML::LoadFile(entry.path().string())));
    ++files;
  }
  CHECK(files >= 24);  // the folders were found
}

TEST_CASE("RIG-6 RIG-8 watchdogs: per drive and for the PLC, in cycles, 20 by default, at least 1", "[config]") {
  CHECK(axis("").watchdog_cycles == 20);
  CHECK(axis(", watchdog_cycles: 5").watchdog_cycles == 5);
  CHECK_THROWS_WITH(axis(", watchdog_cycles: 0"), Catch::Contains("watchdog_cycles"));
  const auto machine = [](const std::string& top) {
    return parse_machine_config(YAML::Load(top + "axes:\n  - " + axis_x + "}\n"));
  };
  CHECK(machine("").plc_watchdog_cycles == 20);
  CHECK(machine("plc_watchdog_cycles: 50\n").plc_watchdog_cycles == 50);
  CHECK_THROWS_WITH(machine("plc_watchdog_cycles: -1\n"), Catch::Contains("plc_watchdog_cycles"));
}
