// RIG-5: scenario files, the PLC simulator's timeline and expectations;
// RIG-3: the unit of P-AXIS-00441/00442 is checked when a machine is read.
#include <catch2/catch.hpp>

#include "config_error.hpp"
#include "scenario.hpp"
#include "scenario_fixture.hpp"
#include "scenario_engine.hpp"

using namespace hil;

namespace {

Scenario scenario(const std::string& rest) { return test::one_axis_scenario(rest); }

HliState state(int64_t cycle, ChannelState cs = ChannelState::ready, int64_t block = 0) {
  HliState s;
  s.cycle = cycle;
  s.channel_state = cs;
  s.block_nr_r = block;
  s.axis_name = {"X"};
  s.axis_position_r = {0};
  return s;
}

}  // namespace

TEST_CASE("RIG-5 scenario: timeline steps write control unit fields once, when their trigger holds",
          "[scenario]") {
  const Scenario s = scenario(R"(
plc:
  timeline:
    - when: {cycle: 3}
      set: {program_start.enable_w: true, program_start.command_w: true}
    - when: {channel_state: ACTIVE, block_nr_r: 20}
      set: {program_start.command_w: false}
)");
  plc::ScenarioEngine engine(s);
  CHECK_FALSE(engine.cycle(state(2)).program_start.command_w);
  CHECK(engine.cycle(state(3)).program_start.command_w);
  CHECK(engine.cycle(state(4)).program_start.enable_w);
  CHECK(engine.cycle(state(5, ChannelState::active, 10)).program_start.command_w);
  const HliControl& c = engine.cycle(state(6, ChannelState::active, 20));
  CHECK_FALSE(c.program_start.command_w);
  CHECK(c.program_start.enable_w);
  CHECK(c.cycle == 6);
}

TEST_CASE("RIG-5 scenario: unknown HLI fields and triggers are refused with their place", "[scenario]") {
  CHECK_THROWS_WITH(scenario("plc:\n  timeline:\n    - when: {cycle: 1}\n      set: {feed_hold.command_w: true}\n"),
                    Catch::Contains("plc.timeline[0].set.feed_hold.command_w: unknown HLI field, did you mean "
                                    "feedhold.command_w?"));
  CHECK_THROWS_WITH(scenario("plc:\n  timeline:\n    - when: {velocity: 1}\n      set: {}\n"),
                    Catch::Contains("plc.timeline[0].when.velocity: unknown key (known: cycle, time_s"));
  CHECK_THROWS_WITH(scenario("expect:\n  - when: program_end\n    axis_position_mm: {Q: 1}\n"),
                    Catch::Contains("axis 'Q' is not on the machine"));
}

TEST_CASE("RIG-5 scenario: control units' request_r / state_r as triggers and checks", "[scenario]") {
  const Scenario s = scenario(R"(
plc:
  timeline:
    - when: {delete_distance_to_go.state_r: true}
      set: {feedhold.command_w: true}
expect:
  - when: {backward_motion.request_r: true}
    delete_distance_to_go.state_r: false
    m_function_request_r: true
)");
  plc::ScenarioEngine engine(s);
  HliState st = state(1);
  CHECK_FALSE(engine.cycle(st).feedhold.command_w);
  st.delete_distance_to_go.state_r = true;
  st.backward_motion.request_r = true;
  CHECK(engine.cycle(st).feedhold.command_w);
  const auto results = engine.finish();
  REQUIRE(results.size() == 1);
  CHECK_FALSE(results[0].passed);
  CHECK_THAT(results[0].detail, Catch::Contains("delete_distance_to_go.state_r 1 != 0"));
  CHECK_THAT(results[0].detail, Catch::Contains("m_function_request_r 0 != 1"));
  CHECK_THROWS_WITH(scenario("expect:\n  - when: program_end\n    feedhold.state_r: maybe\n"),
                    Catch::Contains("'feedhold.state_r' takes true, false or a whole number"));
}

TEST_CASE("RIG-5 scenario: expectations pass, fail with the reason, or were never reached", "[scenario]") {
  const Scenario s = scenario(R"(
expect:
  - when: program_end
    block_nr_r: 30
    axis_position_mm: {X: 1.0}
  - when: {block_nr_r: 20}
    channel_state: ACTIVE
  - when: {block_nr_r: 99}
    channel_state: ACTIVE
expect_events:
  - {id: 50810, severity: warning}
)");
  plc::ScenarioEngine engine(s);
  engine.cycle(state(1, ChannelState::active, 20));
  HliState end = state(2, ChannelState::program_end, 30);
  end.axis_position_r = {10005};  // 1.0005 mm: inside the default 0.001 mm
  engine.cycle(end);
  Event warning;
  warning.severity = Severity::warning;
  warning.id = 50810;
  engine.observe(warning);
  Event error;
  error.message = "something broke";
  engine.observe(error);
  const auto results = engine.finish();
  REQUIRE(results.size() == 5);
  CHECK(results[0].passed);
  CHECK(results[1].passed);
  CHECK_FALSE(results[2].passed);
  CHECK_THAT(results[2].detail, Catch::Contains("never reached"));
  CHECK(results[3].passed);  // the expected warning was seen
  CHECK_FALSE(results[4].passed);  // an error nobody expected
  CHECK_THAT(results[4].detail, Catch::Contains("something broke"));
}

TEST_CASE("RIG-5 scenario: a failed check says what was found", "[scenario]") {
  const Scenario s = scenario("expect:\n  - when: program_end\n    axis_position_mm: {X: 2}\n");
  plc::ScenarioEngine engine(s);
  HliState end = state(1, ChannelState::program_end);
  end.axis_position_r = {10000};
  engine.cycle(end);
  const auto results = engine.finish();
  REQUIRE(results.size() == 1);
  CHECK_FALSE(results[0].passed);
  CHECK_THAT(results[0].detail, Catch::Contains("axis_position_mm.X 1, expected 1.999<=axis_position_mm.X<=2.001"));
}

TEST_CASE("RIG-3 machine: P-AXIS-00441/00442 below 1000 (limit under a_max) are refused", "[scenario]") {
  const std::string axis = "{name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002";
  auto machine = [&](const std::string& extra) {
    return parse_machine_config(YAML::Load("axes:\n  - " + axis + extra + "}\n")).axes.at(0);
  };
  CHECK(machine("").accel_error_limit() == 2000);
  CHECK(machine(", dyn_monitoring_a_warn: 1100, dyn_monitoring_a_err: 1200").accel_warning_limit() == 1100);
  CHECK_THROWS_WITH(machine(", dyn_monitoring_a_warn: 500"), Catch::Contains("P-AXIS-00441"));
  CHECK_THROWS_WITH(machine(", dyn_monitoring_a_warn: 1500, dyn_monitoring_a_err: 1000"),
                    Catch::Contains("P-AXIS-00442"));
  CHECK_THROWS_WITH(parse_machine_config(YAML::Load(
                        "axes: [{name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: -1, velocity_lag_s: 0.002}]")),
                    Catch::Contains("machine.axes[0].kv: must be a number within 0.1 .. 10000 1/s, not -1"));
  CHECK_THROWS_WITH(parse_machine_config(YAML::Load("axes: []")), Catch::Contains("non-empty"));
}

TEST_CASE("RIG-3 machine: drive model keys and monitoring parameters P-AXIS-00439/00440, 00168/00169/00172, 00177/00178/00179",
          "[scenario]") {
  const std::string axis = "{name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002";
  auto machine = [&](const std::string& extra) {
    return parse_machine_config(YAML::Load("axes:\n  - " + axis + extra + "}\n")).axes.at(0);
  };
  const AxisConfig defaults = machine("");
  CHECK(defaults.velocity_warning_limit() == Approx(105));
  CHECK(defaults.velocity_error_limit() == Approx(109));
  CHECK(defaults.following_error_monitoring == 0);
  CHECK_FALSE(defaults.software_limits);
  CHECK_THROWS_WITH(machine(", dyn_monitoring_v_warn: 50"), Catch::Contains("P-AXIS-00439"));
  CHECK_THROWS_WITH(machine(", dyn_monitoring_v_err: 1000"), Catch::Contains("P-AXIS-00440"));
  const AxisConfig fe = machine(", slep_max: 0.5, slep_min: 0.1");
  CHECK(fe.following_error_monitoring == 4);
  CHECK(fe.slep_min == 0.1);
  CHECK(machine(", slep_max: 0.5").slep_min == 0.5);
  CHECK(machine(", slep_max: 0.5, following_error_monitoring: 0").following_error_monitoring == 0);
  CHECK_THROWS_WITH(machine(", slep_max: 0.5, following_error_monitoring: 1"), Catch::Contains("P-AXIS-00172"));
  CHECK_THROWS_WITH(machine(", following_error_monitoring: 4"), Catch::Contains("P-AXIS-00168"));
  const AxisConfig drive = machine(", velocity_loop_order: 2, velocity_damping: 0.5, velocity_feedforward: 0.8, "
                                   "drive_acceleration_limit: 3000, friction_coulomb: 10, friction_viscous: 2");
  CHECK(drive.velocity_loop_order == 2);
  CHECK(drive.velocity_damping == 0.5);
  CHECK(drive.velocity_feedforward == 0.8);
  CHECK(drive.drive_acceleration_limit == 3000);
  CHECK(drive.friction_coulomb == 10);
  CHECK(drive.friction_viscous == 2);
  CHECK_THROWS_WITH(machine(", velocity_loop_order: 3"), Catch::Contains("velocity_loop_order"));
  CHECK_THROWS_WITH(machine(", velocity_feedforward: 1.5"), Catch::Contains("velocity_feedforward"));
  CHECK_THROWS_WITH(machine(", friction_coulomb: -1"), Catch::Contains("friction_coulomb"));
  const AxisConfig swe = machine(", swe_neg: -5, swe_pos: 500");
  CHECK(swe.software_limits);
  CHECK(swe.swe_toleranz == 0.1);
  CHECK_THROWS_WITH(machine(", swe_pos: 500"), Catch::Contains("P-AXIS-00177"));
  CHECK_THROWS_WITH(machine(", swe_neg: 5, swe_pos: 5"), Catch::Contains("P-AXIS-00177 swe_neg must be below"));
  CHECK_THROWS_WITH(machine(", swe_neg: -5, swe_pos: 5, swe_toleranz: -1"),
                    Catch::Contains("machine.axes[0].swe_toleranz: must be a number within 0 .. 1000 mm, not -1"));
}

TEST_CASE("RIG-5 scenario: expected events match by parameter, ID and NC line; absent ones must not appear",
          "[scenario]") {
  const Scenario s = scenario(R"(
expect_events:
  - {parameter: P-AXIS-00442, severity: error}
  - {id: 0, severity: error, nc_line: 7}
  - {id: 0, severity: error, nc_line: 8}
  - {parameter: P-AXIS-00441, severity: warning, absent: true}
)");
  plc::ScenarioEngine engine(s);
  Event overload;
  overload.parameter = "P-AXIS-00442";
  overload.id = 12345;  // a parameter-only expectation takes any number
  engine.observe(overload);
  Event decode;
  decode.nc_line = 7;
  engine.observe(decode);
  Event warning;
  warning.severity = Severity::warning;
  warning.parameter = "P-AXIS-00441";
  engine.observe(warning);
  const auto results = engine.finish();
  REQUIRE(results.size() == 4);  // both errors were expected: no "unexpected error" entry
  CHECK(results[0].passed);
  CHECK(results[1].passed);
  CHECK_FALSE(results[2].passed);  // nothing on line 8
  CHECK_FALSE(results[3].passed);  // the warning appeared although it must not
  CHECK_THAT(results[3].what, Catch::Contains("no warning (P-AXIS-00441)"));
}

TEST_CASE("KRN-1 machine file: m_pre_outp (P-CHAN-00070) in 0.1 um, refused when negative", "[scenario]") {
  const Scenario s = parse_scenario(YAML::Load(R"(
machine:
  m_pre_outp: {7: 250000, 11: 0}
  axes:
    - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}
nc_program: "M30\n"
)"));
  CHECK(s.machine.m_pre_output_mm.at(7) == Approx(25.0));
  CHECK(s.machine.m_pre_output_mm.at(11) == 0);
  CHECK_THROWS_WITH(parse_scenario(YAML::Load(R"(
machine:
  m_pre_outp: {7: -1}
  axes:
    - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}
nc_program: "M30\n"
)")),
                    Catch::Contains("machine.m_pre_outp[7]: must be a number within 0 .. 1e+10 x 0.1 um, not -1"));
}

namespace {

// X and a lift axis Z.
Scenario lift_scenario(const std::string& rest) {
  return parse_scenario(YAML::Load(R"(
machine:
  cycle_time_us: 1000
  axes:
    - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}
    - {name: Z, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}
nc_program: "G01 X1 F100\n"
)" + rest));
}

HliState xz_state(int64_t cycle, double z_mm, bool lift_active, ChannelState cs = ChannelState::active) {
  HliState s;
  s.cycle = cycle;
  s.channel_state = cs;
  s.axis_name = {"X", "Z"};
  s.axis_position_r = {0, std::llround(z_mm * hli_units_per_mm)};
  s.lift_active = {false, lift_active};
  s.lift_suppressed = {false, false};
  return s;
}

}  // namespace

TEST_CASE("LIFT-7 RIG-5 scenario: lift_active / lift_suppressed per axis by name in triggers and expectations",
          "[scenario][lift]") {
  const Scenario s = lift_scenario(R"(
plc:
  timeline:
    - when: {lift_active: {Z: true}}
      set: {feedhold.command_w: true}
expect:
  - when: {lift_active: {Z: true}}
    lift_suppressed: {Z: false, X: false}
  - when: program_end
    lift_active: {Z: true}
)");
  plc::ScenarioEngine engine(s);
  CHECK_FALSE(engine.cycle(xz_state(1, 0, false)).feedhold.command_w);
  CHECK(engine.cycle(xz_state(2, 1, true)).feedhold.command_w);
  engine.cycle(xz_state(3, 0, false, ChannelState::program_end));
  const auto results = engine.finish();
  REQUIRE(results.size() == 2);
  CHECK(results[0].passed);
  CHECK_THAT(results[0].what, Catch::Contains("lift_active.Z=true"));
  CHECK_FALSE(results[1].passed);
  CHECK_THAT(results[1].detail, Catch::Contains("lift_active.Z false != true"));
  // Per axis only: a BOOL, an unknown axis, a non-BOOL value are refused.
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    lift_active: true\n"),
                    Catch::Contains("expect[0].lift_active: must map axis names to true or false"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: {lift_active: {Q: true}}\n"),
                    Catch::Contains("expect[0].when.lift_active: axis 'Q' is not on the machine"));
  CHECK_THROWS_WITH(lift_scenario("plc:\n  timeline:\n    - when: {lift_suppressed: {Y: true}}\n      set: {}\n"),
                    Catch::Contains("plc.timeline[0].when.lift_suppressed: axis 'Y' is not on the machine"));
  CHECK_THROWS(lift_scenario("expect:\n  - when: program_end\n    lift_active: {Z: 2}\n"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    lift_activ: {Z: true}\n"),
                    Catch::Contains("unknown key, did you mean lift_active?"));
}

TEST_CASE("LIFT-2 RIG-5 scenario: an axis' highest and lowest commanded position over a window (since .. when)",
          "[scenario][lift]") {
  const Scenario s = lift_scenario(R"(
expect:
  - since: {lift_active: {Z: true}}
    when: {lift_active: {Z: false}}
    axis_max_mm: {Z: 30}
    axis_min_mm: {Z: 5}
    axis_max_at_most_mm: {Z: 30}
  - when: program_end
    axis_max_at_least_mm: {Z: 31}
    axis_min_at_most_mm: {Z: 0}
    axis_min_at_least_mm: {Z: 1}
    axis_max_mm: {X: 0}
    tolerance_mm: 0.01
)");
  plc::ScenarioEngine engine(s);
  // Z at 0, lifts to 30 (5 cycles at 5 .. 30), lands at 10; the lift window
  // opens with the first lift_active and closes with the first cycle without.
  const double z[] = {0, 0, 5, 20, 30, 25, 10, 10};
  const bool lift[] = {false, false, true, true, true, true, false, false};
  for (int k = 0; k < 8; ++k) engine.cycle(xz_state(k, z[k], lift[k], k == 7 ? ChannelState::program_end : ChannelState::active));
  const auto results = engine.finish();
  REQUIRE(results.size() == 2);
  // 'when' (Z not lifting) held from cycle 0 on, but counts only from the
  // window's start: highest 30, lowest 5 (its first cycle), 0 is outside.
  CHECK(results[0].passed);
  CHECK_THAT(results[0].what, Catch::Contains("since lift_active.Z=true"));
  CHECK_FALSE(results[1].passed);  // the whole run: highest 30 < 31, lowest 0 < 1
  CHECK_THAT(results[1].detail, Catch::Contains("highest Z 30 mm < 31 mm"));
  CHECK_THAT(results[1].detail, Catch::Contains("lowest Z 0 mm < 1 mm"));
  CHECK_THAT(results[1].detail, !Catch::Contains("lowest Z 0 mm >"));
  CHECK_THAT(results[1].detail, !Catch::Contains("X"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    axis_max_mm: {Q: 1}\n"),
                    Catch::Contains("expect[0].axis_max_mm: axis 'Q' is not on the machine"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    axis_max_mm: {Z: .nan}\n"),
                    Catch::Contains("expect[0].axis_max_mm.Z"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    axis_peak_mm: {Z: 1}\n"),
                    Catch::Contains("expect[0].axis_peak_mm: unknown key"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    since: {lift_active: {Z: true, Z: false}}\n"),
                    Catch::Contains("expect[0].since.lift_active"));
}

TEST_CASE("LIFT-2 RIG-5 scenario: the time from the window's start to 'when' (path time)", "[scenario][lift]") {
  const Scenario s = lift_scenario(R"(
expect:
  - since: {channel_state: ACTIVE}
    when: program_end
    time_s_at_least: 0.002
    time_s_at_most: 0.003
  - when: program_end
    time_s_at_most: 0.003
  - since: {lift_active: {Z: true}}
    when: program_end
)");
  plc::ScenarioEngine engine(s);
  engine.cycle(xz_state(0, 0, false, ChannelState::ready));
  engine.cycle(xz_state(1, 0, false, ChannelState::ready));
  engine.cycle(xz_state(2, 0, false));
  engine.cycle(xz_state(3, 0, false));
  engine.cycle(xz_state(4, 0, false));
  engine.cycle(xz_state(5, 0, false, ChannelState::program_end));
  const auto results = engine.finish();
  REQUIRE(results.size() == 3);
  CHECK(results[0].passed);  // ACTIVE at 0.002 s, PROGRAM_END at 0.005 s: 0.003 s
  CHECK_FALSE(results[1].passed);  // without 'since': from the run's start, 0.005 s
  CHECK_THAT(results[1].detail, Catch::Contains("time 0.005 s > 0.003 s"));
  CHECK_FALSE(results[2].passed);
  CHECK_THAT(results[2].detail, Catch::Contains("'since' never held"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    time_s_at_least: 2\n    time_s_at_most: 1\n"),
                    Catch::Contains("time_s_at_least is more than time_s_at_most"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    time_s_at_most: -1\n"),
                    Catch::Contains("expect[0].time_s_at_most"));
}

TEST_CASE("LIFT-2 LIFT-8 RIG-5 scenario: the largest path velocity over a window", "[scenario][lift]") {
  const Scenario s = lift_scenario(R"(
expect:
  - since: {lift_active: {Z: true}}
    when: {lift_active: {Z: false}}
    path_velocity_max_at_most_mm_s: 20
  - when: program_end
    path_velocity_max_at_most_mm_s: 20
    path_velocity_max_at_least_mm_s: 50
)");
  plc::ScenarioEngine engine(s);
  const double v[] = {50, 30, 20, 10, 15, 0};  // the lift in cycles 2 .. 3, the window 2 .. 4
  const bool lift[] = {false, false, true, true, false, false};
  for (int k = 0; k < 6; ++k) {
    HliState st = xz_state(k, 0, lift[k], k == 5 ? ChannelState::program_end : ChannelState::active);
    st.path_velocity = k == 1 ? -v[k] : v[k];  // backward motion counts by its magnitude
    engine.cycle(st);
  }
  const auto results = engine.finish();
  REQUIRE(results.size() == 2);
  CHECK(results[0].passed);  // 20, 10, 15 in the window; 50 and 30 before it
  CHECK_FALSE(results[1].passed);
  CHECK_THAT(results[1].detail, Catch::Contains("path_velocity up to 50 mm/s > 20 mm/s"));
  CHECK_THAT(results[1].detail, !Catch::Contains(" < 50"));
  CHECK_THROWS_WITH(lift_scenario("expect:\n  - when: program_end\n    path_velocity_max_at_most_mm_s: -1\n"),
                    Catch::Contains("expect[0].path_velocity_max_at_most_mm_s"));
}

TEST_CASE("RIG-6 scenario: run.realtime chooses real-time mode; lock-step without it; other keys stay errors",
          "[scenario][RIG-6]") {
  CHECK_FALSE(scenario("").realtime);
  CHECK(scenario("run: {realtime: true}\n").realtime);
  CHECK_FALSE(scenario("run: {realtime: false}\n").realtime);
  CHECK_THROWS_WITH(scenario("run: {realtime: soon}\n"), Catch::Contains("run.realtime: must be true or false"));
  CHECK_THROWS_WITH(scenario("run: {real_time: true}\n"),
                    Catch::Contains("run.real_time: unknown key, did you mean realtime?"));
}
