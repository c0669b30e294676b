// The `hil_logger` process (RIG-1, RIG-4, RIG-9): the logger
// (logger_node.hpp) on LCM, with its heartbeat to the CNC and the wait for
// every participant's end.
#include <spdlog/spdlog.h>

#include <chrono>

#include "command_line.hpp"
#include "logger_node.hpp"
#include "node_options.hpp"
#include "udpm_bus.hpp"
#include "participant.hpp"
#include "run_identity.hpp"
#include "scenario.hpp"

int main(int argc, char** argv) {
  using clock_type = std::chrono::steady_clock;
  CLI::App app{"hil_logger: records every channel of a rig run into an LCM event log"};
  std::string url, path, scenario_file, key_file;
  int64_t run_id = 0;
  std::vector<std::string> participants;
  double linger_s = 3.0;
  app.add_option("--url", url, "LCM URL of the rig")->required();
  app.add_option("--out", path, "log file to write")->required();
  app.add_option("--run-id", run_id, "the run to record (default: the run of the first manifest heard)");
  app.add_option("--participants", participants,
                 "every node whose RUN_END closes the log (default: the manifest's participants and the cnc)");
  app.add_option("--scenario", scenario_file, "the resolved scenario file: written into the log after the manifest")
      ->check(CLI::ExistingFile);
  hil::lcm_support::add_key_file_option(app, key_file)->needs("--run-id");
  app.add_option("--linger-s", linger_s, "after the CNC's RUN_END, wait at most this long for the others");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  return hil::lcm_support::guarded_main("logger", [&] {
    const auto bus = hil::lcm_support::run_bus(url, key_file, run_id, {std::chrono::milliseconds(1)});
    std::optional<std::pair<std::string, std::string>> scenario;
    if (!scenario_file.empty())
      scenario.emplace(hil::read_text(scenario_file), hil::load_scenario_file(scenario_file).nc_program);
    hil::logger::LoggerNode node(*bus, path, run_id, participants, std::move(scenario));
    // With a run id the logger is a participant: READY, then a heartbeat.
    hil::lcm_support::Inbox inbox(*bus, run_id);
    std::optional<hil::lcm_support::Participant> participant;
    if (run_id > 0) {
      participant.emplace(inbox, "logger");
      if (!participant->wait_for_start(std::chrono::seconds(30))) {
        spdlog::error("the CNC did not start a run within 30 s");
        node.seal();
        return 2;
      }
    }
    auto last_message = clock_type::now(), next_alive = clock_type::now();
    int64_t announced_cycle = -1;
    int64_t heard = node.heard();  // neither another rig's traffic nor its own heartbeat is a sign of the run
    clock_type::time_point cnc_end{};
    const hil::logger::Attendance& attendance = node.attendance();
    while (!attendance.complete()) {
      const auto now = clock_type::now();
      // On time, and as the recording progresses: the CNC's flow control.
      if (participant && (now >= next_alive || node.recorded_cycle() >= announced_cycle + 32)) {
        announced_cycle = node.recorded_cycle();
        participant->announce_alive(announced_cycle);
        next_alive = now + std::chrono::milliseconds(100);
      }
      if (bus->handle_timeout(50) < 0) throw std::runtime_error("LCM receive failed");
      if (node.heard() != heard) {
        heard = node.heard();
        last_message = now;
      }
      if (attendance.cnc_ended() && cnc_end == clock_type::time_point{}) cnc_end = now;
      if (attendance.cnc_ended() && now - cnc_end > std::chrono::duration<double>(linger_s)) break;
      if (!attendance.cnc_ended() && now - last_message > hil::lcm_support::cnc_silence) {
        spdlog::error("no message of the run for {} s and no RUN_END from the CNC: log closed early",
                      hil::lcm_support::cnc_silence.count());
        node.seal();
        return 2;
      }
    }
    node.seal();
    return node.finish(path, linger_s);
  });
}
