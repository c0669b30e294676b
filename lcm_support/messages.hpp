#pragma once
// Translation between the LCM-free values of the libraries and the hil LCM
// types. The only place that knows both.
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>

#include <string>

#include "event.hpp"
#include "hli.hpp"

namespace hil::lcm_support {

hil::event_t to_message(const Event& event, int64_t cycle, int64_t utime, const std::string& source);
Event from_message(const hil::event_t& message);

hil::hli_state_t to_message(const HliState& state, int64_t utime);
HliState from_message(const hil::hli_state_t& message);

hil::hli_control_t to_message(const HliControl& control, int64_t utime);
HliControl from_message(const hil::hli_control_t& message);

// The monitors named by axis_state_t MONITOR_* bits: "acceleration, velocity".
std::string monitor_names(int32_t bits);

}  // namespace hil::lcm_support
