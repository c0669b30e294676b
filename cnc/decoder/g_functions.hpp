#pragma once
// The G functions of the TwinCAT CNC (TF5200 programming manual, "Overview
// of G functions", P-CHAN-00022's groups) that this rig does not build, and
// why: a real program gets "G41 tool radius compensation is not supported
// by this rig" instead of a plain "unknown" (KRN-8). docs/DIALECT.md lists
// every G function with what the rig does with it.
#include <optional>
#include <string>

namespace hil::cnc::decoding {

// What TwinCAT does with G<g> if it is one of its G functions the rig
// refuses ("tool radius compensation"); none if the rig decodes it or if
// TwinCAT has no G<g>.
std::optional<std::string> refused_twincat_g_function(int g);

// The LineError message for G<g>, which the decoder does not decode.
std::string refused_g_function_message(int g);

}  // namespace hil::cnc::decoding
