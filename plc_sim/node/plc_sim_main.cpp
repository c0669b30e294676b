// The `plc_sim` node (RIG-1, RIG-5): the PLC. Answers every HLI_STATE with
// an HLI_CONTROL from the scenario's timeline, checks the expectations and
// reports them at the end of the run: one event per expectation, its
// verdict a field, and their number in its RUN_END, so that the rig can
// tell a log that lost a verdict from one that holds them all (RIG-9).
// Failed expectations are a verdict, not an error: the exit status is 0
// whenever the node did its job.
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <spdlog/spdlog.h>

#include "channels.hpp"
#include "inbox.hpp"
#include "messages.hpp"
#include "node_options.hpp"
#include "participant.hpp"
#include "scenario.hpp"
#include "scenario_engine.hpp"

namespace {

using namespace hil;
const std::string source = "plc_sim";

class PlcSimNode {
 public:
  PlcSimNode(const Scenario& scenario, lcm::LCM& lcm, lcm_support::Inbox& inbox)
      : engine_(scenario), lcm_(lcm), run_id_(inbox.run_id()) {
    inbox.on<hil::hli_state_t>(channels::hli_state, [this](const hil::hli_state_t& m, const lcm::ReceiveBuffer&) {
      if (m.cycle != last_cycle_ + 1) return false;  // each cycle once, in order
      on_state(m);
      return true;
    });
    inbox.on<hil::event_t>(channels::event, [this](const hil::event_t& m, const lcm::ReceiveBuffer&) {
      if (m.source != source) engine_.observe(lcm_support::from_message(m));
      return true;
    });
  }

  // Publishes one event per expectation, its verdict a field (the text is
  // for people); returns how many it published.
  int report(int64_t cycle) {
    int published = 0;
    for (const plc::ExpectationResult& r : engine_.finish()) {
      Event e;
      e.severity = r.passed ? Severity::info : Severity::error;
      e.verdict = r.passed ? Verdict::pass : Verdict::fail;  // what the rig counts
      e.message = std::string(r.passed ? "PASS " : "FAIL ") + r.what + ":" + r.detail;
      (r.passed ? spdlog::info("{}", e.message) : spdlog::error("{}", e.message));
      hil::event_t m = lcm_support::to_message(e, cycle, utime_, source);
      m.run_id = run_id_;
      lcm_.publish(channels::event, &m);
      ++published;
    }
    return published;
  }

 private:
  void on_state(const hil::hli_state_t& m) {
    last_cycle_ = m.cycle;
    utime_ = m.utime;
    const HliControl& control = engine_.cycle(lcm_support::from_message(m));
    hil::hli_control_t out = lcm_support::to_message(control, m.utime);
    out.run_id = run_id_;
    lcm_.publish(channels::hli_control, &out);
  }

  plc::ScenarioEngine engine_;
  lcm::LCM& lcm_;
  int64_t run_id_;
  int64_t last_cycle_ = -1;
  int64_t utime_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"plc_sim: simulated PLC of the HIL rig, runs the scenario timeline"};
  hil::lcm_support::NodeOptions options;
  hil::lcm_support::add_node_options(app, options);
  CLI11_PARSE(app, argc, argv);
  return hil::lcm_support::guarded_main(source, [&] {
    const hil::Scenario scenario = hil::load_scenario_file(options.scenario_file);
    lcm::LCM lcm(options.url);
    hil::lcm_support::require_good(lcm, options.url);
    hil::lcm_support::Inbox inbox(lcm, options.run_id);
    PlcSimNode node(scenario, lcm, inbox);
    hil::lcm_support::Participant participant(lcm, inbox, source);
    if (!participant.wait_for_start(std::chrono::seconds(30))) {
      spdlog::error("the CNC did not start a run within 30 s");
      return 2;
    }
    if (!participant.serve_until_end(std::chrono::seconds(10))) {
      spdlog::error("no message for 10 s: the CNC is gone");
      return 2;
    }
    const int verdicts = node.report(participant.end_cycle());
    participant.announce_end(participant.end_cycle(), verdicts);
    if (!inbox.ledger().empty()) spdlog::warn("refused: {}", inbox.ledger().describe());
    return 0;
  });
}
