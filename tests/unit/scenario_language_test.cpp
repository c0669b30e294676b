// RIG-5: the scenario language's comparisons (issue 19): ranges of numeric
// fields, path_velocity_mm_s, never: / always: over a window, stop
// conditions by name, and the cycle each verdict was decided in.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "config_error.hpp"
#include "scenario.hpp"
#include "scenario_fixture.hpp"
#include "scenario_engine.hpp"

using namespace hil;

namespace {

Scenario scenario(const std::string& rest) { return test::one_axis_scenario(rest); }

// A state of cycle `cycle`: X at `x_mm`, the path at `v` mm/s.
HliState state(int64_t cycle, double x_mm = 0, double v = 0, ChannelState cs = ChannelState::active) {
  HliState s;
  s.cycle = cycle;
  s.channel_state = cs;
  s.path_velocity = v;
  s.axis_name = {"X"};
  s.axis_position_r = {static_cast<int64_t>(x_mm * hli_units_per_mm + (x_mm < 0 ? -0.5 : 0.5))};
  return s;
}

}  // namespace

TEST_CASE("RIG-5 ranges: {min, max} inclusive, either bound may be left out", "[scenario][ranges]") {
  const Scenario s = scenario(R"(
plc:
  timeline:
    - when: {path_velocity_mm_s: {min: 10, max: 20}, axis_position_mm: {X: {max: 5}}}
      set: {feedhold.enable_w: true}
expect:
  - when: {cycle: {min: 3}}
    path_velocity_mm_s: {max: 20}
    axis_position_mm: {X: {min: 2, max: 2.5}}
    override.state_r: {min: 500, max: 1000}
)");
  const Condition& when = s.timeline.at(0).when;
  CHECK(when.holds(state(0, 1, 10), 0.001));   // both bounds inclusive
  CHECK(when.holds(state(0, 5, 20), 0.001));
  CHECK_FALSE(when.holds(state(0, 1, 20.01), 0.001));
  CHECK_FALSE(when.holds(state(0, 5.001, 15), 0.001));
  CHECK(when.describe() == "10<=path_velocity_mm_s<=20 axis_position_mm.X<=5");

  plc::ScenarioEngine engine(s);
  HliState at = state(3, 2.5, 20);
  at.override.state_r = 500;
  engine.cycle(at);
  auto results = engine.finish();
  REQUIRE(results.size() == 1);
  CHECK(results[0].passed);
  CHECK(results[0].what == "at cycle>=3");

  plc::ScenarioEngine breaking(s);
  at.override.state_r = 1200;
  at.axis_position_r = {25001};
  breaking.cycle(at);
  results = breaking.finish();
  CHECK_FALSE(results[0].passed);
  CHECK_THAT(results[0].detail, Catch::Contains("override.state_r 1200, expected 500<=override.state_r<=1000"));
  CHECK_THAT(results[0].detail, Catch::Contains("axis_position_mm.X 2.5001, expected 2<=axis_position_mm.X<=2.5"));
}

TEST_CASE("RIG-5 ranges: every numeric trigger key takes one", "[scenario][ranges]") {
  const Scenario s = scenario(R"(
plc:
  timeline:
    - when: {cycle: {max: 2}, time_s: {max: 0.002}, block_nr_r: {min: 10, max: 20}, block_count_r: {min: 1},
             dist_prog_start_mm: {max: 1}, delete_distance_to_go_activation.state_r: {max: 3}}
      set: {feedhold.enable_w: true}
)");
  const Condition& c = s.timeline.at(0).when;
  HliState st = state(2);
  st.block_nr_r = 20;
  st.block_count_r = 1;
  st.dist_prog_start = 1 * hli_units_per_mm;
  st.delete_distance_to_go_activation.state_r = 3;
  CHECK(c.holds(st, 0.001));
  st.cycle = 3;  // cycle and time_s past their max
  CHECK_FALSE(c.holds(st, 0.001));
  st.cycle = 2;
  st.block_nr_r = 21;
  CHECK_FALSE(c.holds(st, 0.001));
  st.block_nr_r = 10;
  st.dist_prog_start = 1.0001 * hli_units_per_mm;
  CHECK_FALSE(c.holds(st, 0.001));
}

TEST_CASE("RIG-5 ranges: min > max, unknown keys, no bound and wrong types are refused", "[scenario][ranges]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"expect:\n  - when: {path_velocity_mm_s: {min: 5, max: 4}}\n",
       "expect[0].when.path_velocity_mm_s: min 5 is more than max 4"},
      {"expect:\n  - when: {block_nr_r: {min: 10, mx: 20}}\n",
       "expect[0].when.block_nr_r.mx: unknown key, did you mean max?"},
      {"expect:\n  - when: program_end\n    dist_prog_start_mm: {}\n",
       "expect[0].dist_prog_start_mm: a range needs 'min' and/or 'max'"},
      {"expect:\n  - when: {block_nr_r: {min: 1.5}}\n", "expect[0].when.block_nr_r.min: must be a whole number"},
      {"expect:\n  - when: {feedhold.state_r: {min: 0, max: 2}}\n", "expect[0].when.feedhold.state_r.max: must be a whole number within 0 .. 1"},
      {"expect:\n  - when: {axis_position_mm: {X: 5}}\n",
       "expect[0].when.axis_position_mm.X: give a range {min: .., max: ..}"},
      {"expect:\n  - when: {axis_position_mm: {Q: {min: 5}}}\n",
       "expect[0].when.axis_position_mm: axis 'Q' is not on the machine"},
      {"expect:\n  - when: {time_s: {min: -1}}\n", "expect[0].when.time_s.min: must be a number >= 0"},
      {"expect:\n  - when: {path_velocity_mm_s: [1, 2]}\n", "expect[0].when.path_velocity_mm_s: must be a number"},
  };
  for (const auto& [yaml, message] : cases) {
    INFO(yaml);
    CHECK_THROWS_AS(scenario(yaml), ConfigError);
    CHECK_THROWS_WITH(scenario(yaml), Catch::Contains(message));
  }
}

TEST_CASE("RIG-5 path_velocity_mm_s: a trigger fires once it is reached, a check wants the value", "[scenario][path_velocity]") {
  const Scenario s = scenario(R"(
plc:
  timeline:
    - when: {path_velocity_mm_s: 50}
      set: {feedhold.enable_w: true, feedhold.command_w: true}
expect:
  - when: {path_velocity_mm_s: 50}
    path_velocity_mm_s: 60
  - when: {cycle: 3}
    path_velocity_mm_s: {min: 0, max: 10}
)");
  CHECK(s.timeline.at(0).when.describe() == "path_velocity_mm_s>=50");
  plc::ScenarioEngine engine(s);
  CHECK_FALSE(engine.cycle(state(1, 0, 49.9)).feedhold.command_w);
  CHECK(engine.cycle(state(2, 0, 60)).feedhold.command_w);
  engine.cycle(state(3, 0, 12));
  const auto results = engine.finish();
  REQUIRE(results.size() == 2);
  CHECK(results[0].passed);
  CHECK_FALSE(results[1].passed);
  CHECK_THAT(results[1].detail, Catch::Contains("path_velocity_mm_s 12, expected 0<=path_velocity_mm_s<=10"));
}

TEST_CASE("RIG-5 never: a condition that must not hold in any cycle of the window", "[scenario][never]") {
  const Scenario s = scenario(R"(
expect:
  - never: {axis_position_mm: {X: {min: 100.001}}}
  - never: {path_velocity_mm_s: {min: 30}}
    since: {cycle: 2}
    until: {channel_state: PROGRAM_END}
)");
  REQUIRE(s.expectations.size() == 2);
  CHECK(s.expectations[0].kind == Expectation::Kind::never);
  SECTION("it holds: PASS at the window's end") {
    plc::ScenarioEngine engine(s);
    engine.cycle(state(0, 0, 40));  // before the window of the second
    engine.cycle(state(1, 50, 40));
    engine.cycle(state(2, 100.001 - 0.0001, 20));
    engine.cycle(state(3, 100, 0, ChannelState::program_end));
    engine.cycle(state(4, 100, 50, ChannelState::program_end));  // after the window
    const auto results = engine.finish(4);
    REQUIRE(results.size() == 2);
    CHECK(results[0].passed);
    CHECK(results[0].detail == " held in cycles 0..4");
    CHECK_FALSE(results[0].cycle);  // a whole-run window: decided at the run's end
    CHECK(results[1].passed);
    CHECK(results[1].detail == " held in cycles 2..2");
    CHECK(results[1].cycle == 3);
    CHECK(results[1].what == "never path_velocity_mm_s>=30 since cycle>=2 until channel_state=PROGRAM_END");
  }
  SECTION("it breaks: FAIL names the first cycle and the value seen") {
    plc::ScenarioEngine engine(s);
    engine.cycle(state(0));
    engine.cycle(state(1, 100.0011));
    engine.cycle(state(2, 100.5, 35));
    engine.cycle(state(3, 100.5, 0, ChannelState::program_end));
    const auto results = engine.finish(3);
    CHECK_FALSE(results[0].passed);
    CHECK(results[0].detail == " broken in cycle 1: axis_position_mm.X=100.0011");
    CHECK(results[0].cycle == 1);
    CHECK_FALSE(results[1].passed);
    CHECK(results[1].detail == " broken in cycle 2: path_velocity_mm_s=35");
    CHECK(results[1].cycle == 2);
  }
  SECTION("not seen to the end: no PASS") {
    plc::ScenarioEngine engine(s);
    engine.cycle(state(0));
    engine.cycle(state(1));
    engine.cycle(state(2));
    const auto results = engine.finish(5);  // the run went on to cycle 5: the PLC missed 3..5
    CHECK_FALSE(results[0].passed);
    CHECK_THAT(results[0].detail, Catch::Contains("the PLC saw cycles up to 2 of 5"));
    CHECK_FALSE(results[1].passed);
    CHECK(results[1].detail == " 'until' never held");
  }
  SECTION("a cycle missed in the window: no PASS") {
    plc::ScenarioEngine engine(s);
    engine.cycle(state(0));
    engine.cycle(state(3));  // cycles 1, 2 lost on the way
    engine.cycle(state(4, 0, 0, ChannelState::program_end));
    const auto results = engine.finish(4);
    CHECK_FALSE(results[0].passed);
    CHECK(results[0].detail == " cycles 1..2 not seen by the PLC: not checked");
    CHECK(results[0].cycle == 3);
  }
}

TEST_CASE("RIG-5 always: a condition that must hold in every cycle of the window", "[scenario][always]") {
  const Scenario s = scenario(R"(
expect:
  - always: {channel_state: ACTIVE, path_velocity_mm_s: {max: 100}}
    since: {path_velocity_mm_s: 1}
    until: program_end
)");
  SECTION("it holds") {
    plc::ScenarioEngine engine(s);
    engine.cycle(state(0, 0, 0, ChannelState::ready));  // before the window
    engine.cycle(state(1, 0, 1));
    engine.cycle(state(2, 0, 100));
    engine.cycle(state(3, 0, 0, ChannelState::program_end));
    const auto results = engine.finish(3);
    REQUIRE(results.size() == 1);
    CHECK(results[0].passed);
    CHECK(results[0].detail == " held in cycles 1..2");
    CHECK(results[0].cycle == 3);
  }
  SECTION("it breaks") {
    plc::ScenarioEngine engine(s);
    engine.cycle(state(0, 0, 1));
    engine.cycle(state(1, 0, 100.5));
    const auto results = engine.finish(1);
    CHECK_FALSE(results[0].passed);
    CHECK(results[0].detail == " broken in cycle 1: path_velocity_mm_s 100.5, expected path_velocity_mm_s<=100;");
    CHECK(results[0].cycle == 1);
  }
}

TEST_CASE("RIG-5 never/always: what they take is checked when the scenario is read", "[scenario][never][always]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"expect:\n  - never: {cycle: 1}\n    always: {cycle: 1}\n", "expect[0]: give 'never' or 'always', not both"},
      {"expect:\n  - never: {cycle: 1}\n    when: program_end\n",
       "expect[0].when: a never/always expectation takes only never or always, since and until"},
      {"expect:\n  - always: {cycle: 1}\n    channel_state: ACTIVE\n",
       "expect[0].channel_state: a never/always expectation takes only"},
      {"expect:\n  - when: program_end\n    until: {cycle: 3}\n", "expect[0].until: ends the window of never: or always:"},
      {"expect:\n  - never: {axis_postion_mm: {X: {min: 1}}}\n",
       "expect[0].never.axis_postion_mm: unknown key, did you mean axis_position_mm?"},
      {"expect:\n  - never: {axis_position_mm: {X: {min: 2, max: 1}}}\n",
       "expect[0].never.axis_position_mm.X: min 2 is more than max 1"},
      {"expect:\n  - always: {lift_active: {Q: true}}\n", "expect[0].always.lift_active: axis 'Q' is not on the machine"},
      {"expect:\n  - since: {cycle: 1}\n", "expect[0]: 'when' is missing (or give 'never' or 'always')"},
  };
  for (const auto& [yaml, message] : cases) {
    INFO(yaml);
    CHECK_THROWS_WITH(scenario(yaml), Catch::Contains(message));
  }
}

TEST_CASE("RIG-5 stop_conditions_r by bit names: exactly these, or contains", "[scenario][stop_conditions]") {
  const Scenario s = scenario(R"(
plc:
  timeline:
    - when: {stop_conditions_r: {contains: [PLC_ACKNOWLEDGE]}}
      set: {feedhold.enable_w: true}
expect:
  - when: {cycle: 1}
    stop_conditions_r: [FEEDHOLD, HLI_SC_M00_OR_M01]
  - when: {cycle: 1}
    stop_conditions_r: 17
  - when: {cycle: 1}
    stop_conditions_r: [FEEDHOLD]
)");
  const Condition& when = s.timeline.at(0).when;
  HliState st = state(0);
  st.stop_conditions_r = stop_condition::plc_acknowledge | stop_condition::wait_techno_ack;
  CHECK(when.holds(st, 0.001));  // others free
  st.stop_conditions_r = stop_condition::wait_techno_ack;
  CHECK_FALSE(when.holds(st, 0.001));
  CHECK(when.describe() == "stop_conditions_r contains PLC_ACKNOWLEDGE");

  plc::ScenarioEngine engine(s);
  st = state(1);
  st.stop_conditions_r = stop_condition::feedhold | stop_condition::m00_or_m01;
  engine.cycle(st);
  const auto results = engine.finish();
  REQUIRE(results.size() == 3);
  CHECK(results[0].passed);
  CHECK(results[1].passed);  // numbers keep working: 17 = 0x11
  CHECK_FALSE(results[2].passed);  // exact: M00_OR_M01 is one too many
  CHECK_THAT(results[2].detail, Catch::Contains("stop_conditions_r FEEDHOLD|M00_OR_M01 != FEEDHOLD"));

  CHECK_THROWS_WITH(scenario("expect:\n  - when: {stop_conditions_r: [FEEDHOLT]}\n"),
                    Catch::Contains("expect[0].when.stop_conditions_r[0]: unknown stop condition 'FEEDHOLT', did you "
                                    "mean FEEDHOLD?"));
  CHECK_THROWS_WITH(scenario("expect:\n  - when: {stop_conditions_r: {contains: [HLI_SC_PLC_ACK]}}\n"),
                    Catch::Contains("unknown stop condition 'HLI_SC_PLC_ACK', did you mean PLC_ACKNOWLEDGE?"));
  CHECK_THROWS_WITH(scenario("expect:\n  - when: {stop_conditions_r: {contains: []}}\n"),
                    Catch::Contains("name at least one stop condition"));
  CHECK_THROWS_WITH(scenario("expect:\n  - when: {stop_conditions_r: {has: [FEEDHOLD]}}\n"),
                    Catch::Contains("stop_conditions_r.has: unknown key"));
}

TEST_CASE("RIG-5 stop condition names come from hli.hpp's one list", "[scenario][stop_conditions]") {
  CHECK(find_stop_condition("FEEDHOLD") == stop_condition::feedhold);
  CHECK(find_stop_condition("HLI_SC_INSERT_STOP_AT_DIST") == stop_condition::insert_stop_at_dist);
  CHECK(find_stop_condition("m0_stop") == stop_condition::m0_stop);
  CHECK(find_stop_condition("FEED") == 0);
  CHECK(stop_conditions_text(0) == "0");
  CHECK(stop_conditions_text(stop_condition::delay_time | 0x100) == "DELAY_TIME|0x100");
  int32_t all = 0;
  for (const StopConditionName& n : stop_condition_names()) {
    CHECK((all & n.bit) == 0);  // one bit each, none twice
    all |= n.bit;
  }
  // KRN-4: every bit of TF5200_insert_stop_cmd.txt's table of stop conditions.
  const std::vector<std::pair<std::string, int32_t>> text = {
      {"FEEDHOLD", 0x0001},          {"VFG", 0x0002},
      {"SINGLE_BLOCK", 0x0004},      {"M00_OR_M01", 0x0010},
      {"PLC_ACKNOWLEDGE", 0x0020},   {"OVERRIDE_ZERO", 0x0040},
      {"OVERRIDE_RAPID_ZERO", 0x0080}, {"DELAY_TIME", 0x0200},
      {"CHANNEL_SYNC", 0x0800},      {"IPO_INPUT_EMPTY", 0x1000},
      {"IPO_INPUT_DISABLED", 0x2000}, {"WAIT_FOR_AXES", 0x8000},
      {"CHANNEL_ERROR", 0x00010000}, {"WAIT_TECHNO_ACK", 0x00020000},
      {"W_C_AFTER_COLLISION", 0x00040000}, {"SLOPE_SUPPLY_PROBLEM", 0x00080000},
      {"BACK_INTERPOLATION", 0x00100000}, {"STOP_REVERSIBLE", 0x00200000},
      {"BREAKPOINT_STOP", 0x00400000}, {"M0_STOP", 0x02000000},
      {"M1_STOP", 0x04000000},       {"INSERT_STOP_AT_DIST", 0x08000000},
      {"DEC_SYN_CHAN_EMPTY", 0x10000000}};
  REQUIRE(stop_condition_names().size() == text.size());
  for (const auto& [name, bit] : text) {
    CAPTURE(name);
    CHECK(find_stop_condition("HLI_SC_" + name) == bit);
  }
}

TEST_CASE("RIG-5 verdicts carry the cycle they were decided in", "[scenario]") {
  const Scenario s = scenario(R"(
expect:
  - when: {cycle: 2}
    channel_state: ACTIVE
  - when: {cycle: 9}
  - never: {path_velocity_mm_s: {min: 1000}}
)");
  plc::ScenarioEngine engine(s);
  for (int64_t k = 0; k <= 4; ++k) engine.cycle(state(k));
  const auto results = engine.finish(4);
  REQUIRE(results.size() == 3);
  CHECK(results[0].cycle == 2);
  CHECK_FALSE(results[1].passed);  // never reached: decided at the end
  CHECK_FALSE(results[1].cycle);
  CHECK(results[2].passed);
  CHECK_FALSE(results[2].cycle);
}

TEST_CASE("RIG-5 m_function_nr_r: a trigger waits for the M function, a check reads the field", "[scenario]") {
  const Scenario s = scenario(R"(
expect:
  - when: {cycle: 1}
    m_function_nr_r: 3
  - when: {m_function_nr_r: 3}
)");
  plc::ScenarioEngine engine(s);
  HliState st = state(1);
  st.m_function_nr_r = 3;  // the last one output, acknowledged: none waits
  engine.cycle(st);
  const auto results = engine.finish(1);
  REQUIRE(results.size() == 2);
  CHECK(results[0].passed);
  CHECK_FALSE(results[1].passed);
  CHECK_THAT(results[1].detail, Catch::Contains("never reached"));
}
