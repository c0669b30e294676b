#include "hli.hpp"

#include <algorithm>
#include <cctype>

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

}  // namespace hil
