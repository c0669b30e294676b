#include "run_scenario.hpp"

#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "config_error.hpp"
#include "drive_model.hpp"
#include "plots.hpp"
#include "process.hpp"
#include "report.hpp"
#include "run_log.hpp"
#include "scenario.hpp"
#include "scenario_engine.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

std::string timestamp() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&now));
  return buf;
}

}  // namespace

std::string rig_url(int port) {
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0&recv_buf_size=4194304";
}

RunResult run_scenario(const RunOptions& options) {
  const Scenario scenario = load_scenario_file(options.scenario_file);
  plc::ScenarioEngine validate_timeline(scenario);  // refuses unknown HLI fields before anything starts
  for (const AxisConfig& axis : scenario.machine.axes) {  // and drive models that would not be stable
    try {
      axis::DriveModel(axis::drive_parameters(axis, scenario.machine.cycle_time_s()));
    } catch (const std::invalid_argument& e) {
      throw ConfigError("machine: axis " + axis.name + ": " + e.what());
    }
  }

  RunResult result;
  result.run_dir = options.run_dir.empty() ? "runs/" + scenario.name + "-" + timestamp() : options.run_dir;
  fs::create_directories(result.run_dir);
  const fs::path dir = fs::absolute(result.run_dir);
  const std::string resolved = (dir / "scenario.yaml").string();
  std::ofstream(resolved) << to_yaml(scenario) << '\n';
  result.log_file = (dir / "run.lcmlog").string();
  fs::remove(result.log_file);

  const int port = options.port > 0 ? options.port : 20000 + static_cast<int>(::getpid() % 20000);
  const std::string url = rig_url(port);
  const fs::path bin = options.bin_dir;
  auto node_output = [&](const std::string& name) { return (dir / (name + ".out")).string(); };

  const auto wall_start = std::chrono::steady_clock::now();
  std::vector<std::unique_ptr<Process>> nodes;
  nodes.push_back(std::make_unique<Process>(
      "logger", std::vector<std::string>{(bin / "hil_logger").string(), "--url", url, "--out", result.log_file},
      node_output("logger")));
  for (const AxisConfig& axis : scenario.machine.axes)
    nodes.push_back(std::make_unique<Process>(
        "axis_sim " + axis.name,
        std::vector<std::string>{(bin / "axis_sim").string(), "--scenario", resolved, "--url", url, "--axis",
                                 axis.name},
        node_output("axis_sim_" + axis.name)));
  nodes.push_back(std::make_unique<Process>(
      "plc_sim", std::vector<std::string>{(bin / "plc_sim").string(), "--scenario", resolved, "--url", url},
      node_output("plc_sim")));
  Process cnc("cnc", {(bin / "cnc").string(), "--scenario", resolved, "--url", url}, node_output("cnc"));

  // Lock-step runs faster than real time; this bound only catches a hang.
  const auto wall_limit = std::chrono::milliseconds(static_cast<int64_t>(60000 + 20000 * scenario.max_time_s));
  std::ostringstream processes;
  const std::optional<int> cnc_status = cnc.wait_for(wall_limit);
  bool all_ok = cnc_status && *cnc_status == 0;
  processes << "cnc " << (cnc_status ? std::to_string(*cnc_status) : "hung, killed: " + std::to_string(cnc.stop()));
  for (auto& node : nodes) {
    std::optional<int> status = node->wait_for(std::chrono::seconds(10));
    const int code = status ? *status : node->stop();
    // plc_sim exits 1 for failed expectations: reported below, not a crash.
    all_ok = all_ok && (code == 0 || (node->name() == "plc_sim" && code == 1));
    processes << ", " << node->name() << ' ' << (status ? std::to_string(code) : "hung, killed");
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  std::optional<logger::CheckReport> check;
  const logger::RunLog log = logger::read_run_log(result.log_file, &check);
  int expectations_failed = 0, expectations_passed = 0;
  for (const auto& e : log.events) {
    expectations_passed += e.event.verdict == Verdict::pass ? 1 : 0;
    expectations_failed += e.event.verdict == Verdict::fail ? 1 : 0;
  }
  // Violations the scenario provokes on purpose must be found; no other may be.
  bool check_passed = check.has_value();
  std::ostringstream violations_expected;
  if (check) {
    for (const auto& v : check->violations) {
      bool expected = false;
      for (const auto& e : scenario.expected_violations) expected = expected || e.matches(v.axis, v.quantity);
      check_passed = check_passed && expected;
    }
    for (const auto& e : scenario.expected_violations) {
      bool found = false;
      for (const auto& v : check->violations) found = found || e.matches(v.axis, v.quantity);
      check_passed = check_passed && found;
      violations_expected << "expected violation: axis " << e.axis << " " << e.quantity << ": "
                          << (found ? "found" : "NOT FOUND") << '\n';
    }
  }
  result.passed = all_ok && log.run_end_seen && check_passed && expectations_failed == 0 && log.undecodable == 0;

  std::ostringstream out;
  const double simulated_s = (log.last_cycle + 1) * scenario.machine.cycle_time_s();
  int64_t messages = 0;
  for (const auto& entry : log.messages_per_channel) messages += entry.second;
  out << "scenario " << scenario.name;
  if (!scenario.requirements.empty()) {
    out << " (";
    for (size_t i = 0; i < scenario.requirements.size(); ++i) out << (i ? " " : "") << scenario.requirements[i];
    out << ")";
  }
  out << ": " << (result.passed ? "PASSED" : "FAILED") << '\n'
      << "run folder: " << result.run_dir << '\n'
      << "LCM: " << url << '\n'
      << "log: " << result.log_file << " (" << messages << " messages, " << log.last_cycle + 1 << " cycles = "
      << simulated_s << " s simulated in " << wall_s << " s wall, " << simulated_s / wall_s
      << " x real time)\n"
      << "exit status: " << processes.str() << (log.run_end_seen ? "" : "; no RUN_END in the log") << '\n'
      << "expectations (plc_sim): " << expectations_passed << " passed, " << expectations_failed << " failed\n";
  if (check) out << format_check(log, *check) << violations_expected.str() << draw_plots(log, *check, (dir / "plots").string()) << '\n';
  else out << "offline check: the log has no manifest\n";
  result.report = out.str();
  std::ofstream(dir / "report.txt") << result.report;
  return result;
}

}  // namespace hil::rig
