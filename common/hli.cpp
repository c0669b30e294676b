#include "hli.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

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

const std::vector<StopConditionName>& stop_condition_names() {
#define HIL_STOP_CONDITION_NAME(NAME, name, bit) {#NAME, bit},
  static const std::vector<StopConditionName> names = {HLI_STOP_CONDITIONS(HIL_STOP_CONDITION_NAME)};
#undef HIL_STOP_CONDITION_NAME
  return names;
}

int32_t find_stop_condition(const std::string& name) {
  std::string upper = name;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (upper.rfind("HLI_SC_", 0) == 0) upper.erase(0, 7);
  for (const StopConditionName& n : stop_condition_names())
    if (upper == n.name) return n.bit;
  return 0;
}

std::string stop_conditions_text(int32_t bits) {
  if (bits == 0) return "0";
  std::string out;
  for (const StopConditionName& n : stop_condition_names())
    if (bits & n.bit) {
      out += (out.empty() ? "" : "|") + std::string(n.name);
      bits &= ~n.bit;
    }
  if (bits != 0) {
    char rest[16];
    std::snprintf(rest, sizeof rest, "0x%X", static_cast<unsigned>(bits));
    out += (out.empty() ? "" : "|") + std::string(rest);
  }
  return out;
}

}  // namespace hil
