// RIG-2, KRN-4: the nodes' translation between library values and LCM
// messages loses no field, including through LCM's own encoding.
#include "wire.hpp"

#include "channels.hpp"
#include "messages.hpp"

using namespace hil;
using test::through_the_wire;

TEST_CASE("KRN-4 messages: HLI state and control survive encoding unchanged", "[messages]") {
  HliState s;
  s.cycle = 42;
  s.channel_state = ChannelState::error;
  s.block_nr_r = 30;
  s.block_count_r = 5;
  s.stop_conditions_r = stop_condition::channel_error;
  s.dist_prog_start = 1234567.5;
  s.path_velocity = 50.25;
  s.last_error_id = 20001;
  s.axis_name = {"X", "Y"};
  s.axis_position_r = {100000, -25};
  s.program_start.request_r = true;
  s.program_start.state_r = true;
  s.feedhold.state_r = true;
  s.override.request_r = true;
  s.override.state_r = 1200;
  s.delete_distance_to_go = {true, true};
  s.delete_distance_to_go_activation = {true, 0x14};
  s.delete_distance_to_go_active_r = true;
  s.m_function_request_r = true;
  s.m_function_nr_r = 48;
  s.backward_motion.request_r = true;
  const HliState t = lcm_support::from_message(through_the_wire(lcm_support::to_message(s, 42000)));
  CHECK(t.cycle == 42);
  CHECK(t.channel_state == ChannelState::error);
  CHECK(t.block_nr_r == 30);
  CHECK(t.block_count_r == 5);
  CHECK(t.stop_conditions_r == stop_condition::channel_error);
  CHECK(t.dist_prog_start == 1234567.5);
  CHECK(t.path_velocity == 50.25);
  CHECK(t.last_error_id == 20001);
  CHECK(t.axis_name == s.axis_name);
  CHECK(t.axis_position_r == s.axis_position_r);
  CHECK(t.program_start.request_r);
  CHECK(t.program_start.state_r);
  CHECK(t.feedhold.state_r);
  CHECK(t.override.request_r);
  CHECK(t.override.state_r == 1200);
  CHECK(t.delete_distance_to_go.state_r);
  CHECK(t.delete_distance_to_go_activation.state_r == 0x14);
  CHECK(t.delete_distance_to_go_active_r);
  CHECK(t.m_function_request_r);
  CHECK(t.m_function_nr_r == 48);
  CHECK(t.backward_motion.request_r);
  CHECK(t.lift_active == std::vector<bool>{false, false});  // LCM's arrays all have n_axes elements

  HliControl c;
  c.cycle = 7;
  c.program_start.command_w = true;
  c.program_start.enable_w = true;
  c.feedhold = {true, true};
  c.override = {734, true};
  c.delete_distance_to_go = {true, true};
  c.delete_distance_to_go_activation = {0x105, true};
  c.m_function_ack = {true, true};
  c.backward_motion = {true, true};
  const HliControl d = lcm_support::from_message(through_the_wire(lcm_support::to_message(c, 7000)));
  CHECK(d.cycle == 7);
  CHECK(d.program_start.command_w);
  CHECK(d.program_start.enable_w);
  CHECK(d.feedhold.command_w);
  CHECK(d.override.command_w == 734);
  CHECK(d.delete_distance_to_go.command_w);
  CHECK(d.delete_distance_to_go_activation.command_w == 0x105);
  CHECK(d.m_function_ack.command_w);
  CHECK(d.backward_motion.command_w);
  CHECK(d.override.enable_w);
}

TEST_CASE("KRN-2 messages: an event keeps its ID, parameter, NC line, block and values", "[messages]") {
  Event e;
  e.severity = Severity::warning;
  e.id = 50810;
  e.parameter = "P-AXIS-00441";
  e.axis = "Z";
  e.nc_line = 12;
  e.block_nr = 110;
  e.value = 3100.5;
  e.limit = 3000;
  e.message = "acceleration above the warning limit";
  const hil::event_t m = through_the_wire(lcm_support::to_message(e, 9, 9000, "axis_sim Z"));
  CHECK(m.source == "axis_sim Z");
  CHECK(m.cycle == 9);
  const Event f = lcm_support::from_message(m);
  CHECK(f.severity == Severity::warning);
  CHECK(f.id == 50810);
  CHECK(f.parameter == "P-AXIS-00441");
  CHECK(f.axis == "Z");
  CHECK(f.nc_line == 12);
  CHECK(f.block_nr == 110);
  CHECK(f.value == 3100.5);
  CHECK(f.limit == 3000);
  CHECK(f.message == e.message);
  CHECK(f.verdict == Verdict::none);
}

TEST_CASE("RIG-5 KRN-4 messages: an expectation's verdict is a field of the event, PASS or FAIL", "[messages]") {
  for (Verdict verdict : {Verdict::none, Verdict::pass, Verdict::fail}) {
    Event e;
    e.severity = verdict == Verdict::fail ? Severity::error : Severity::info;
    e.verdict = verdict;
    e.message = "at program_end: all checks hold";  // the text says nothing of it
    const hil::event_t m = through_the_wire(lcm_support::to_message(e, 3, 3000, "plc_sim"));
    CHECK(m.verdict == static_cast<int8_t>(verdict));
    CHECK(lcm_support::from_message(m).verdict == verdict);
  }
  CHECK(hil::event_t::VERDICT_NONE == static_cast<int8_t>(Verdict::none));
  CHECK(hil::event_t::VERDICT_PASS == static_cast<int8_t>(Verdict::pass));
  CHECK(hil::event_t::VERDICT_FAIL == static_cast<int8_t>(Verdict::fail));
}

TEST_CASE("RIG-2 channels: the axis of an axis channel name, the inverse of axis_command / axis_state", "[messages]") {
  CHECK(channels::axis_of_command(channels::axis_command("X")) == "X");
  CHECK(channels::axis_of_state(channels::axis_state("Z")) == "Z");
  CHECK(channels::axis_of_command(channels::axis_state("X")).empty());
  CHECK(channels::axis_of_state("AXIS__STATE").empty());
  CHECK(channels::axis_of_command("HLI_STATE").empty());
}

TEST_CASE("LIFT-7 messages: lift_active / lift_suppressed per axis survive encoding", "[messages][lift]") {
  HliState s;
  s.axis_name = {"X", "Y", "Z"};
  s.axis_position_r = {0, 0, 300000};
  s.lift_active = {false, false, true};
  s.lift_suppressed = {true, false, true};
  const hil::hli_state_t m = lcm_support::to_message(s, 0);
  CHECK(m.n_axes == 3);
  CHECK(m.lift_active == std::vector<int8_t>{0, 0, 1});
  const HliState t = lcm_support::from_message(through_the_wire(m));
  CHECK(t.lift_active == s.lift_active);
  CHECK(t.lift_suppressed == s.lift_suppressed);
}
