// KRN-4: the HLI's one table (common/hli_table.hpp) gives the scenario names,
// the LCM conversion and the types; a UDINT keeps bit 31 end to end.
#include "wire.hpp"

#include <string>

#include "hli_names.hpp"
#include "messages.hpp"
#include "scenario.hpp"
#include "scenario_engine.hpp"

using namespace hil;
using test::through_the_wire;

namespace {

Scenario scenario(const std::string& rest) {
  return parse_scenario(YAML::Load(
      "machine: {axes: [{name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}]}\n"
      "nc_program: \"M30\\n\"\n" +
      rest));
}

HliControl control_round_trip(const HliControl& c) {
  return lcm_support::from_message(through_the_wire(lcm_support::to_message(c, 0)));
}

HliState state_round_trip(const HliState& s) {
  return lcm_support::from_message(through_the_wire(lcm_support::to_message(s, 0)));
}

// Each field, alone set to the top of its type by name, is in the message
// (its bytes differ from the default's) and comes back in that field only.
template <typename Record, typename RoundTrip>
void check_every_field(RoundTrip round_trip) {
  const auto default_bytes = test::encoded(lcm_support::to_message(Record{}, 0));
  for (const HliField<Record>& field : hli_fields<Record>()) {
    INFO(field.name << " " << field.type);
    Record record;
    REQUIRE(write_hli_field(record, field.name, field.max));
    CHECK(test::encoded(lcm_support::to_message(record, 0)) != default_bytes);
    const Record back = round_trip(record);
    for (const HliField<Record>& other : hli_fields<Record>()) {
      INFO("read back " << other.name);
      CHECK(other.read(back) == (other.name == field.name ? field.max : other.read(Record{})));
    }
  }
}

}  // namespace

TEST_CASE("KRN-4 HLI table: every control field written by name reaches the LCM message and back", "[hli]") {
  // 10 control units with command_w and enable_w (reset included); insert_cmd (ISC-1): 5 command_w fields,
  // enable_w, semaphor_rw; block_search (DPS-3): 3 command_w fields, enable_w; KRN-8: h/s/t_function_ack,
  // program_block_ignore, zero_offset (3 command_w fields, enable_w).
  CHECK(hli_fields<HliControl>().size() == 43);
  CHECK(find_hli_field<HliControl>("reset.command_w") != nullptr);
  CHECK(find_hli_field<HliControl>("block_search.enable_w") != nullptr);
  CHECK(std::string(find_hli_field<HliControl>("insert_cmd.command_w.dist_or_pos")->type) == "LREAL");
  CHECK(std::string(find_hli_field<HliControl>("insert_cmd.command_w.rel_abs_mode")->type) == "UINT");
  CHECK(std::string(find_hli_field<HliControl>("insert_cmd.command_w.add_nr")->type) == "DINT");
  CHECK(std::string(find_hli_field<HliControl>("insert_cmd.semaphor_rw")->type) == "BOOL");
  CHECK(find_hli_field<HliControl>("continue_motion.command_w") != nullptr);
  CHECK(find_hli_field<HliControl>("m01_stop_enable.command_w") != nullptr);
  check_every_field<HliControl>(control_round_trip);
  CHECK(std::string(find_hli_field<HliControl>("program_start.command_w")->type) == "BOOL");
  CHECK(std::string(find_hli_field<HliControl>("override.command_w")->type) == "DINT");
  CHECK(std::string(find_hli_field<HliControl>("delete_distance_to_go_activation.command_w")->type) == "UDINT");
  CHECK(find_hli_field<HliControl>("feed_hold.command_w") == nullptr);
}

TEST_CASE("KRN-4 HLI table: every state field read by name comes through the LCM message", "[hli]") {
  check_every_field<HliState>(state_round_trip);
  for (const char* name : {"program_start.request_r", "feedhold.state_r", "override.state_r",
                           "delete_distance_to_go.state_r", "delete_distance_to_go_activation.state_r",
                           "backward_motion.request_r", "m_function_request_r", "m_function_nr_r",
                           "stop_conditions_r", "block_nr_r", "delete_distance_to_go_active_r",
                           "insert_cmd.semaphor_rw", "insert_cmd.state_r.distance_of_next_stop",
                           "insert_cmd.state_r.position_at_next_stop[0]", "insert_cmd.state_r.position_at_next_stop[2]",
                           "insert_cmd.state_r.state", "m_function_add_nr_r", "continue_motion.state_r"}) {
    INFO(name);
    CHECK(find_hli_field<HliState>(name) != nullptr);
  }
  CHECK(std::string(find_hli_field<HliState>("delete_distance_to_go_activation.state_r")->type) == "UDINT");
  // The rest of the state is not by name but must travel too.
  HliState s;
  s.channel_state = ChannelState::program_end;
  s.dist_prog_start = 12.5;
  s.path_velocity = -3.25;
  s.axis_name = {"X", "Y", "Z"};
  s.axis_position_r = {1, -2, 3};
  const HliState t = state_round_trip(s);
  CHECK(t.channel_state == ChannelState::program_end);
  CHECK(t.dist_prog_start == 12.5);
  CHECK(t.path_velocity == -3.25);
  CHECK(t.axis_name == s.axis_name);
  CHECK(t.axis_position_r == s.axis_position_r);
}

TEST_CASE("KRN-4 DDTG-5 bit 31 of the activation mask: scenario -> LCM -> library", "[hli]") {
  for (const auto& [text, mask] : {std::pair<std::string, uint32_t>{"0x80000000", 0x80000000u},
                                   {"2147483648", 0x80000000u},
                                   {"4294967295", 0xFFFFFFFFu},
                                   {"0x80000014", 0x80000014u}}) {
    INFO(text);
    const Scenario s = scenario("plc:\n  timeline:\n    - when: {cycle: 0}\n      set: {"
                                "delete_distance_to_go_activation.command_w: " + text +
                                ", delete_distance_to_go_activation.enable_w: true}\n"
                                "expect:\n  - when: {cycle: 0}\n    delete_distance_to_go_activation.state_r: " +
                                text + "\n");
    REQUIRE(s.timeline[0].set[0].value == static_cast<int64_t>(mask));
    plc::ScenarioEngine engine(s);
    HliState state;
    state.delete_distance_to_go_activation = {true, mask};
    const HliControl sent = engine.cycle(state_round_trip(state));
    const hil::hli_control_t wire = through_the_wire(lcm_support::to_message(sent, 0));
    CHECK(wire.delete_distance_to_go_activation.command_w == static_cast<int64_t>(mask));
    const HliControl received = lcm_support::from_message(wire);
    CHECK(received.delete_distance_to_go_activation.command_w == mask);
    CHECK(received.delete_distance_to_go_activation.enable_w);
    const auto results = engine.finish();
    REQUIRE(results.size() == 1);
    CHECK(results[0].passed);  // the state_r the CNC sent back compared as the UDINT it is
  }
}

TEST_CASE("KRN-4 values outside a field's type are refused, naming the field", "[hli]") {
  auto set = [](const std::string& field, const std::string& value) {
    return "plc:\n  timeline:\n    - when: {cycle: 1}\n      set: {" + field + ": " + value + "}\n";
  };
  const std::string mask = "delete_distance_to_go_activation.command_w";
  for (const char* value : {"-1", "4294967296", "0x100000000"})
    CHECK_THROWS_WITH(scenario(set(mask, value)),
                      Catch::Contains("plc.timeline[0]: '" + mask + "' is a UDINT (0 .. 4294967295), not " + value));
  CHECK_THROWS_WITH(scenario(set("feedhold.command_w", "2")),
                    Catch::Contains("'feedhold.command_w' is a BOOL (true or false), not 2"));
  CHECK_THROWS_WITH(scenario(set("override.command_w", "2147483648")),
                    Catch::Contains("'override.command_w' is a DINT (-2147483648 .. 2147483647), not 2147483648"));
  CHECK_THROWS_WITH(scenario(set("override.command_w", "1.5")),
                    Catch::Contains("'override.command_w' takes true, false or a whole number, not '1.5'"));
  CHECK_THROWS_WITH(scenario("expect:\n  - when: program_end\n    delete_distance_to_go_activation.state_r: -1\n"),
                    Catch::Contains("expect[0]: 'delete_distance_to_go_activation.state_r' is a UDINT"));
  CHECK_THROWS_WITH(scenario("plc:\n  timeline:\n    - when: {feedhold.state_r: 3}\n      set: {}\n"),
                    Catch::Contains("'feedhold.state_r' is a BOOL (true or false), not 3"));
  for (const char* value : {"0", "4294967295", "true"}) CHECK_NOTHROW(scenario(set(mask, value)));
}
