#include "g_functions.hpp"

#include <map>

namespace hil::cnc::decoding {

std::optional<std::string> refused_twincat_g_function(int g) {
  static const std::map<int, std::string> functions = {
      {5, "tangential tool radius compensation"},
      {8, "acceleration at block start"},
      {9, "deceleration at block end"},
      {10, "constant feed with tool radius compensation"},
      {11, "adapted feed with tool radius compensation"},
      {12, "corner deceleration off"},
      {13, "corner deceleration on"},
      {20, "mirroring off (TwinCAT G20..G23 mirror; inch/metric is G70/G71)"},
      {21, "mirroring (TwinCAT G20..G23 mirror; metric input is G71)"},
      {22, "mirroring (TwinCAT G20..G23 mirror)"},
      {23, "mirroring (TwinCAT G20..G23 mirror)"},
      {25, "linear transitions of tool radius compensation"},
      {26, "circular transitions of tool radius compensation"},
      {33, "thread cutting"},
      {41, "tool radius compensation (left)"},
      {42, "tool radius compensation (right)"},
      {51, "diameter programming on"},
      {52, "diameter programming off"},
      {63, "tapping without compensating chuck"},
      {66, "cycle synchronisation at block end"},
      {68, "contour rotation on"},
      {69, "contour rotation off"},
      {93, "feed as machining time"},
      {95, "feed per spindle revolution (the rig simulates no spindle)"},
      {96, "constant cutting speed (the rig simulates no spindle)"},
      {97, "spindle speed in rpm after G96"},
      {98, "negative software limit switch from the program"},
      {99, "positive software limit switch from the program"},
      {101, "measurement run (G100 is built)"},
      {102, "measurement run (G100 is built)"},
      {106, "measurement run (G100 is built)"},
      {107, "measurement run (G100 is built)"},
      {108, "measurement run (G100 is built)"},
      {115, "look-ahead mode"},
      {116, "look-ahead mode"},
      {117, "look-ahead mode"},
      {130, "acceleration weighting"},
      {131, "acceleration weighting"},
      {132, "ramp time weighting"},
      {133, "ramp time weighting"},
      {134, "ramp time weighting"},
      {135, "feedforward control"},
      {136, "feedforward control"},
      {137, "feedforward control"},
      {138, "tool radius compensation selection"},
      {139, "tool radius compensation deselection"},
      {140, "contour masking"},
      {141, "contour masking"},
      {150, "spline interpolation"},
      {151, "spline interpolation"},
      {159, "extended zero offsets (G54..G59 are built)"},
      {160, "zero offset per axis"},
      {163, "radius programming"},
      {166, "override 100 %"},
      {193, "time-related feed interpolation"},
      {194, "feed as a share of the axes' limits"},
      {196, "highest spindle speed with G96"},
      {230, "acceleration weighting"},
      {231, "acceleration weighting"},
      {236, "tool radius compensation selection"},
      {237, "tool radius compensation selection"},
      {238, "tool radius compensation deselection"},
      {239, "tool radius compensation deselection"},
      {293, "path-related feed interpolation"},
      {303, "arc in space"},
      {333, "acceleration weighting"},
      {334, "acceleration weighting"},
      {351, "mirroring with axis information"},
      {900, "feed adaptation"},
      {901, "feed adaptation"},
  };
  if (const auto f = functions.find(g); f != functions.end()) return f->second;
  // G80..G89, G800..G839: implicit subroutine calls, configured per machine.
  if ((g >= 80 && g <= 89) || (g >= 800 && g <= 839)) return "an implicit subroutine call (no subroutines are configured)";
  return std::nullopt;
}

std::string refused_g_function_message(int g) {
  const std::string name = "G" + std::string(g < 10 ? "0" : "") + std::to_string(g);
  if (const std::optional<std::string> function = refused_twincat_g_function(g))
    return name + " " + *function + " is not supported by this rig";
  return name + " is not a G function of the TwinCAT CNC (TF5200)";
}

}  // namespace hil::cnc::decoding
