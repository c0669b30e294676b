// RIG-6, RIG-9: what receivers refuse, the CNC's lock-step answers, the
// verdict — the LCM-free parts, and the wire convention hil compare uses.
#include "wire.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <hil/scenario_text_t.hpp>

#include <cstring>

#include "inbox.hpp"
#include "lock_step.hpp"
#include "run_identity.hpp"
#include "test_machine.hpp"
#include "traffic.hpp"
#include "verdict.hpp"

using namespace hil;

TEST_CASE("RIG-9 traffic: refusals are counted per channel and kind; only this run's or unreadable fail it",
          "[traffic]") {
  traffic::Ledger ledger;
  CHECK(ledger.describe() == "none");
  ledger.refuse("HLI_CONTROL", traffic::Refusal::foreign_run);
  ledger.refuse("HLI_CONTROL", traffic::Refusal::foreign_run);
  CHECK_FALSE(ledger.fails_run());  // another rig on the port: told apart
  ledger.refuse("AXIS_Y_STATE", traffic::Refusal::wrong_cycle);
  ledger.refuse(traffic::malformed_datagram, traffic::Refusal::undecodable);
  CHECK(ledger.fails_run());
  CHECK(ledger.describe() ==
        "(malformed datagram): 1 undecodable; AXIS_Y_STATE: 1 wrong cycle; HLI_CONTROL: 2 foreign run");
  for (int i = 0; i < 1000; ++i) ledger.refuse("INVENTED_" + std::to_string(i), traffic::Refusal::undecodable);
  CHECK(ledger.by_channel().size() == traffic::max_channels + 1);  // bounded: the rest in one row
  CHECK(ledger.by_channel().at(traffic::other_channels).undecodable == 1000 - 61);
  // Through the wire (a RUN_END) and back.
  CHECK(lcm_support::from_message(lcm_support::to_message(ledger)).describe() == ledger.describe());
}

TEST_CASE("RIG-6 lock-step: only the answer to the cycle waited for, first; a forged cycle ahead changes nothing",
          "[traffic]") {
  cnc_node::LockStep lock_step(test::xyz_machine(), true, 5000, 2000);
  CHECK_FALSE(lock_step.take_axis(1, 0, 0));  // nothing is waited for before cycle 0
  lock_step.begin(0);
  CHECK_FALSE(lock_step.take_axis(1, 1000000, 0));  // a forged AXIS_Y_STATE far ahead
  CHECK_FALSE(lock_step.take_plc(1000000, HliControl{}));
  CHECK_FALSE(lock_step.complete());
  CHECK(lock_step.take_axis(0, 0, 0));
  CHECK(lock_step.take_axis(1, 0, 4));
  CHECK_FALSE(lock_step.take_axis(1, 0, 0));  // a second answer to the same cycle
  CHECK(lock_step.take_axis(2, 0, 0));
  CHECK(lock_step.take_plc(0, HliControl{}));
  REQUIRE(lock_step.complete());
  cnc_node::LockStep::Taken taken = lock_step.take();
  CHECK(taken.control);
  CHECK(taken.axis_errors == std::vector<int32_t>{0, 4, 0});
  CHECK(taken.lost.empty());
  lock_step.begin(1);  // axis Y answers cycle 1 as usual: it is not ignored
  CHECK(lock_step.take_axis(1, 1, 0));
  CHECK_FALSE(lock_step.take_axis(1, 0, 0));  // late: an answer to the cycle before
}

TEST_CASE("RIG-6 lock-step: a silent participant is lost once, then not waited for; a silent logger too",
          "[traffic]") {
  cnc_node::LockStep lock_step(test::xyz_machine(), true, 5000, 2000);
  lock_step.logger_alive(1'000'000, -1);
  lock_step.begin(7);
  lock_step.take_axis(0, 7, 0);
  lock_step.take_axis(2, 7, 0);
  lock_step.take_plc(7, HliControl{});
  lock_step.lose_silent();  // the watchdog fired: axis Y did not answer
  REQUIRE(lock_step.complete());
  cnc_node::LockStep::Taken taken = lock_step.take();
  REQUIRE(taken.lost.size() == 1);
  CHECK(taken.lost[0].name == "axis_sim Y");
  CHECK(taken.lost[0].axis == "Y");
  CHECK(taken.lost[0].what == "no answer to cycle 7 within 5000 ms");
  lock_step.begin(8);
  lock_step.take_axis(0, 8, 0);
  lock_step.take_axis(2, 8, 0);
  CHECK_FALSE(lock_step.take_axis(1, 8, 0));  // lost is lost
  CHECK_FALSE(lock_step.complete());          // the PLC still answers
  lock_step.take_plc(8, HliControl{});
  CHECK(lock_step.complete());
  lock_step.check_logger(2'900'000);  // 1.9 s of silence: within its timeout
  CHECK(lock_step.take().lost.empty());
  lock_step.check_logger(3'100'000);
  taken = lock_step.take();
  REQUIRE(taken.lost.size() == 1);
  CHECK(taken.lost[0].name == "logger");
  CHECK(taken.lost[0].axis.empty());
  CHECK(lock_step.lost() == std::vector<std::pair<std::string, int64_t>>{{"axis_sim Y", 7}, {"logger", 8}});
}

TEST_CASE("RIG-9 lock-step: the cnc waits while the logger is more than 128 cycles behind, and loses it when it "
          "does not catch up within its timeout",
          "[traffic]") {
  cnc_node::LockStep lock_step(test::xyz_machine(), true, 5000, 2000);
  lock_step.logger_alive(1'000'000, -1);
  lock_step.begin(127);
  CHECK_FALSE(lock_step.logger_behind());  // cycles 0..127 may be on their way
  lock_step.begin(128);
  CHECK(lock_step.logger_behind());
  lock_step.logger_alive(1'100'000, 1);  // the logger has recorded cycle 1
  CHECK_FALSE(lock_step.logger_behind());
  lock_step.begin(500);
  CHECK(lock_step.logger_behind());
  lock_step.logger_alive(1'200'000, 0);  // an older heartbeat takes nothing back
  lock_step.check_logger(1'300'000);     // behind from now on, heartbeats flowing
  lock_step.logger_alive(3'200'000, 300);
  lock_step.check_logger(3'250'000);  // 1.95 s behind: within its timeout
  CHECK(lock_step.take().lost.empty());
  lock_step.logger_alive(3'300'000, 300);
  lock_step.check_logger(3'350'000);  // 2.05 s behind
  const cnc_node::LockStep::Taken taken = lock_step.take();
  REQUIRE(taken.lost.size() == 1);
  CHECK(taken.lost[0].name == "logger");
  CHECK(taken.lost[0].what ==
        "it has recorded up to cycle 300 and not caught up with cycle 500 within 2000 ms: the run is no longer recorded");
  CHECK_FALSE(lock_step.logger_behind());  // lost: no longer waited for
}

TEST_CASE("RIG-9 lock-step: a logger that catches up is not lost", "[traffic]") {
  cnc_node::LockStep lock_step(test::xyz_machine(), true, 5000, 2000);
  lock_step.logger_alive(0, -1);
  lock_step.begin(1000);
  lock_step.check_logger(100'000);
  lock_step.logger_alive(1'000'000, 900);
  lock_step.check_logger(1'000'000);  // caught up: the clock starts again
  lock_step.begin(2000);
  lock_step.check_logger(1'500'000);
  lock_step.logger_alive(2'400'000, 1000);
  lock_step.check_logger(2'400'000);  // behind for 0.9 s only
  CHECK(lock_step.take().lost.empty());
}

TEST_CASE("RIG-9 verdict: a failed expectation FAILS as a verdict, a crash as a crash; both need every exit 0",
          "[traffic][verdict]") {
  logger::LogFacts whole;
  whole.manifest = whole.scenario = whole.sealed = true;
  whole.participants = {"plc_sim", "cnc"};
  whole.ended = {"plc_sim", "cnc"};
  whole.end_cycle = 1;
  whole.lock_step["HLI_STATE"] = {0, 1};
  whole.expectations = 1;
  whole.verdict_pass = 1;
  whole.verdicts_announced = 1;
  const std::vector<logger::ProcessExit> all_zero = {{"cnc", 0}, {"logger", 0}, {"plc_sim", 0}};
  CHECK(logger::judge_run(all_zero, whole, "").passed);

  logger::LogFacts failed = whole;
  failed.verdict_pass = 0;
  failed.verdict_fail = 1;
  CHECK(logger::judge_run(all_zero, failed, "").reasons == std::vector<std::string>{"1 expectation(s) failed"});

  const std::vector<logger::ProcessExit> plc_crashed = {{"cnc", 0}, {"logger", 0}, {"plc_sim", 1}};
  CHECK(logger::judge_run(plc_crashed, whole, "").reasons ==
        std::vector<std::string>{"plc_sim exited with status 1"});
  CHECK(logger::judge_run({{"cnc", std::nullopt}}, whole, "").reasons ==
        std::vector<std::string>{"cnc hung and was killed"});

  logger::LogFacts lost_verdict = whole;  // the logger stopped before plc_sim's verdicts
  lost_verdict.verdict_pass = 0;
  lost_verdict.ended = {"cnc"};
  lost_verdict.verdicts_announced.reset();
  const logger::RunVerdict v = logger::judge_run(all_zero, lost_verdict, "");
  CHECK_FALSE(v.passed);
  CHECK(v.reasons == std::vector<std::string>{"log: no RUN_END from plc_sim",
                                              "log: the scenario has 1 expectation(s), the log holds 0 verdict(s)"});

  logger::LogFacts foreign = whole;  // another rig's traffic, told apart: no reason to fail
  foreign.refused["cnc"].refuse("AXIS_X_STATE", traffic::Refusal::foreign_run);
  CHECK(logger::judge_run(all_zero, foreign, "").passed);
  CHECK(logger::describe_refused(foreign) == "\n  cnc: AXIS_X_STATE: 1 foreign run");
}

TEST_CASE("RIG-9 wire: every rig message carries its run id right after the fingerprint", "[traffic]") {
  // hil compare masks bytes 8..15 of every message: the one field in which
  // two runs of the same scenario differ.
  auto run_id_at_8 = [](auto message) {
    message.run_id = 0x0102030405060708;
    const std::vector<uint8_t> bytes = test::encoded(message);
    return bytes.size() >= 16 && bytes[8] == 1 && bytes[15] == 8;
  };
  CHECK(run_id_at_8(hil::axis_setpoint_t{}));
  CHECK(run_id_at_8(hil::axis_state_t{}));
  CHECK(run_id_at_8(hil::event_t{}));
  CHECK(run_id_at_8(hil::hli_control_t{}));
  CHECK(run_id_at_8(hil::hli_state_t{}));
  CHECK(run_id_at_8(hil::participant_t{}));
  CHECK(run_id_at_8(hil::run_manifest_t{}));
  CHECK(run_id_at_8(hil::scenario_text_t{}));
  CHECK(run_id_at_8(hil::log_summary_t{}));
}

TEST_CASE("RIG-9 wire: identify reads run and cycle of a rig message, nothing from other bytes", "[traffic]") {
  hil::axis_state_t s{};
  s.run_id = 42;
  s.cycle = 7;
  const std::vector<uint8_t> bytes = test::encoded(s);
  const auto id = lcm_support::identify("AXIS_Y_STATE", bytes.data(), static_cast<uint32_t>(bytes.size()));
  REQUIRE(id);
  CHECK(id->run_id == 42);
  CHECK(id->cycle == 7);
  CHECK_FALSE(lcm_support::identify("HLI_STATE", bytes.data(), static_cast<uint32_t>(bytes.size())));  // wrong type
  CHECK_FALSE(lcm_support::identify("AXIS_Y_STATE", bytes.data(), static_cast<uint32_t>(bytes.size() - 1)));
  CHECK_FALSE(lcm_support::identify("SOMETHING_ELSE", bytes.data(), static_cast<uint32_t>(bytes.size())));
  // What LCM 1.3.1 hands on for a datagram whose channel name has no NUL.
  lcm::ReceiveBuffer unframed{};
  unframed.data_size = static_cast<uint32_t>(-1);
  CHECK_FALSE(lcm_support::framed(unframed));
  unframed.data_size = 19;
  CHECK(lcm_support::framed(unframed));
}

TEST_CASE("RIG-9 run identity: ids differ, the digest tells scenarios apart, a log's scenario reads back",
          "[traffic]") {
  CHECK(new_run_id() > 0);
  CHECK(new_run_id() != new_run_id());
  CHECK(scenario_digest("a", "b") == scenario_digest("a", "b"));
  CHECK(scenario_digest("a", "b") != scenario_digest("a", "c"));
  const std::string yaml =
      "name: s\nmachine:\n  axes:\n    - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}\nnc_file: program.nc\n";
  CHECK(scenario_from_text(yaml, "N10 G01 X1 F100\n").nc_program == "N10 G01 X1 F100\n");
}

TEST_CASE("RIG-9 attendance: the logger waits for every participant it was told of, READY heard or not",
          "[traffic][verdict]") {
  logger::Attendance attendance;
  for (const char* name : {"cnc", "plc_sim", "axis_sim X", "logger"}) attendance.expect(name);
  attendance.ended("axis_sim X", 208, {});
  attendance.ended("cnc", 208, {});
  CHECK(attendance.cnc_ended());
  CHECK_FALSE(attendance.complete());  // plc_sim's verdicts come after the cnc's RUN_END
  CHECK(attendance.missing() == std::vector<std::string>{"plc_sim"});
  attendance.ended("plc_sim", 208, {});
  CHECK(attendance.complete());

  logger::Attendance lost;  // the cnc lost axis_sim X: nobody waits for its end
  lost.expect("axis_sim X");
  lost.ended("cnc", 1243, {"axis_sim X"});
  CHECK(lost.complete());
  CHECK(lost.lost() == std::set<std::string>{"axis_sim X"});
  CHECK(lost.end_cycle() == 1243);
}
