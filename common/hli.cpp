#include "hli.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace hil {

const char* to_string(ChannelState state) {
  switch (state) {
    case ChannelState::ready: return "READY";
    case ChannelState::active: return "ACTIVE";
    case ChannelState::program_end: return "PROGRAM_END";
    case ChannelState::error: return "ERROR";
  }
  return "?";
}

bool parse_channel_state(const std::string& text, ChannelState& state) {
  std::string upper = text;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  for (ChannelState candidate : {ChannelState::ready, ChannelState::active,
                                 ChannelState::program_end, ChannelState::error}) {
    if (upper == to_string(candidate)) {
      state = candidate;
      return true;
    }
  }
  return false;
}

namespace {

const std::vector<std::pair<std::string, ControlUnitState HliState::*>> bool_units = {
    {"program_start", &HliState::program_start},
    {"feedhold", &HliState::feedhold},
    {"delete_distance_to_go", &HliState::delete_distance_to_go},
    {"backward_motion", &HliState::backward_motion},
};
const std::vector<std::pair<std::string, ControlUnitValueState HliState::*>> value_units = {
    {"override", &HliState::override},
    {"delete_distance_to_go_activation", &HliState::delete_distance_to_go_activation},
};

}  // namespace

std::optional<int64_t> read_state_field(const HliState& state, const std::string& name) {
  for (const auto& [unit, member] : bool_units) {
    if (name == unit + ".request_r") return (state.*member).request_r;
    if (name == unit + ".state_r") return (state.*member).state_r;
  }
  for (const auto& [unit, member] : value_units) {
    if (name == unit + ".request_r") return (state.*member).request_r;
    if (name == unit + ".state_r") return (state.*member).state_r;
  }
  if (name == "m_function_request_r") return state.m_function_request_r;
  if (name == "stop_conditions_r") return state.stop_conditions_r;
  return std::nullopt;
}

std::vector<std::string> state_field_names() {
  std::vector<std::string> names;
  for (const auto& unit : bool_units) names.insert(names.end(), {unit.first + ".request_r", unit.first + ".state_r"});
  for (const auto& unit : value_units) names.insert(names.end(), {unit.first + ".request_r", unit.first + ".state_r"});
  names.insert(names.end(), {"m_function_request_r", "stop_conditions_r"});
  return names;
}

}  // namespace hil
