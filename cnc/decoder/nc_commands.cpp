#include "nc_commands.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

#include "command_parameters.hpp"
#include "lift_commands.hpp"
#include "value_ranges.hpp"

namespace hil::cnc::decoding {
namespace {

// A handler gets what follows its keyword, upper case with single blanks
// and no leading blank: "[TYPE=SIN2]" for #SLOPE [TYPE=SIN2].
using CommandHandler = void (*)(const std::string& arguments, DecoderState& state, Block& block);
// An axis command's handler also gets the machine axis it is programmed on.
using AxisCommandHandler = void (*)(int axis, const std::string& arguments, DecoderState& state, Block& block);

template <typename Handler>
struct Keyword {
  std::string_view keyword;  // upper case, single blanks: how upper_words writes the command
  Handler decode;
};
using NcCommand = Keyword<CommandHandler>;
using AxisCommand = Keyword<AxisCommandHandler>;

// A letter after a keyword makes another word (#CSX is not #CS); a digit
// may follow directly (#TIME5 is #TIME 5, as it always was).
bool continues_keyword(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }

// The row whose keyword `text` starts with, ending there; the longest, so
// that #FLUSH WAIT is not #FLUSH.
template <typename Table>
const auto* find_command(const Table& table, const std::string& text) {
  using Row = std::remove_reference_t<decltype(*std::begin(table))>;
  Row* found = nullptr;
  for (Row& row : table) {
    const std::string_view keyword = row.keyword;
    const bool starts_with = text.compare(0, keyword.size(), keyword) == 0;  // so text is no shorter
    if (starts_with && (text.size() == keyword.size() || !continues_keyword(text[keyword.size()])) &&
        (!found || keyword.size() > found->keyword.size()))
      found = &row;
  }
  return found;
}

std::string arguments_after(const std::string& text, std::string_view keyword) {
  std::string arguments = text.substr(keyword.size());
  if (!arguments.empty() && arguments[0] == ' ') arguments.erase(0, 1);
  return arguments;
}

// Blanks are not significant inside brackets: [ END = 8 ] is [END=8].
std::string without_blanks(std::string arguments) {
  arguments.erase(std::remove(arguments.begin(), arguments.end(), ' '), arguments.end());
  return arguments;
}

// <value> of arguments that are exactly [<key>=<value>] (without blanks).
std::optional<std::string> key_value(const std::string& arguments, const std::string& key) {
  const std::string prefix = "[" + key + "=";
  if (arguments.rfind(prefix, 0) != 0 || arguments.back() != ']') return std::nullopt;
  return arguments.substr(prefix.size(), arguments.size() - prefix.size() - 1);
}

// #DISTANCE PROG START ON|OFF (modal) or CLEAR (DPS-2).
void decode_distance_prog_start(const std::string& arguments, DecoderState&, Block& block) {
  if (arguments == "ON") block.distance_prog_start = DistanceProgStart::on;
  else if (arguments == "OFF") block.distance_prog_start = DistanceProgStart::off;
  else if (arguments == "CLEAR") block.distance_prog_start = DistanceProgStart::clear;
  else throw LineError{"#DISTANCE PROG START needs ON, OFF or CLEAR"};
}

// #SLOPE [TYPE=..]: modal, the profile of the motion blocks after it (KRN-3).
void decode_slope(const std::string& arguments, DecoderState& state, Block&) {
  const std::optional<std::string> name = key_value(without_blanks(arguments), "TYPE");
  if (!name) throw LineError{"#SLOPE needs [TYPE=STEP|TRAPEZ|SIN2]"};
  if (*name == "HSC" && state.machine.lift_method == LiftMethod::time_based)  // LIFT-6
    throw LineError{"#SLOPE type HSC is not supported with Advanced Lifting (P-CHAN-00345 enable_time_based_lift = 1; "
                    "STEP, TRAPEZ, SIN2 are)",
                    120711};
  const std::optional<SlopeType> type = parse_slope_type(*name);
  if (!type) throw LineError{"#SLOPE type '" + *name + "' is not one of STEP, TRAPEZ, SIN2"};
  state.modal.slope = *type;
}

// END as a number or an IEC literal '16#0105' (also 2# and 8#); default 1 (DDTG-5).
uint32_t end_marker(const std::string& arguments) {
  if (arguments.empty() || arguments == "[]") return 1;
  const std::optional<std::string> bracketed = key_value(arguments, "END");
  if (!bracketed) throw LineError{"#DEL DIST2GO takes [END=<32-bit mask>], e.g. [END='16#0105']"};
  std::string value = *bracketed;
  if (value.size() >= 2 && value.front() == '\'' && value.back() == '\'') value = value.substr(1, value.size() - 2);
  int base = 10;
  if (const size_t hash = value.find('#'); hash != std::string::npos) {
    const std::string prefix = value.substr(0, hash);
    base = prefix == "2" ? 2 : prefix == "8" ? 8 : prefix == "16" ? 16 : 0;
    value = value.substr(hash + 1);
    if (base == 0) throw LineError{"#DEL DIST2GO END: base must be 2#, 8# or 16#"};
  }
  // Digits only: strtoull would also take a sign, blanks or 0x.
  const bool digits = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
  });
  char* end = nullptr;
  const unsigned long long mask = digits ? std::strtoull(value.c_str(), &end, base) : 0;
  if (!digits || *end != '\0' || mask > 0xFFFFFFFFull)
    throw LineError{"#DEL DIST2GO END '" + value + "' is not a 32-bit mask"};
  return static_cast<uint32_t>(mask);
}

// #DEL DIST2GO, #DEL DIST2GO [], #DEL DIST2GO [END=<32-bit>]: a short-cut target.
void decode_del_dist2go(const std::string& arguments, DecoderState&, Block& block) {
  block.ddtg_end_marker = end_marker(without_blanks(arguments));
}

// #TIME <s>: dwell; an expression, so P parameters can set it.
void decode_time(const std::string& arguments, DecoderState& state, Block& block) {
  try {
    const double seconds = state.evaluate(arguments);
    if (seconds > 0 && seconds <= max_dwell_s) {
      block.dwell_s = seconds;
      return;
    }
  } catch (const std::invalid_argument&) {
  }
  throw LineError{"#TIME needs a dwell time > 0 and <= " + std::to_string(static_cast<int64_t>(max_dwell_s)) + " s"};
}

// What stands in the [..] groups of `text`, which holds nothing else but
// blanks between them (#CS ONX [1] is no #CS ON); brackets inside a group
// belong to its expressions.
std::vector<std::string> bracket_groups(const std::string& text) {
  std::vector<std::string> groups;
  int depth = 0;
  for (size_t i = 0, open = 0; i < text.size(); ++i) {
    if (text[i] == '[' && depth++ == 0) open = i;
    else if (text[i] == ']' && depth > 0 && --depth == 0) groups.push_back(text.substr(open + 1, i - open - 1));
    else if (depth == 0 && text[i] != ' ')
      throw LineError{"#CS ON: '" + text.substr(i, 1) + "' outside [v1,v2,v3,φ1,φ2,φ3]"};
  }
  if (depth != 0) throw LineError{"#CS ON: '[' is not closed"};
  return groups;
}

// #CS ON [v1,v2,v3,φ1,φ2,φ3], #CS ON [<id>] [..], #CS OFF; one CS at a time.
void decode_coordinate_system(const std::string& arguments, DecoderState& state, Block& block) {
  if (state.lift)  // LIFT-6: the rotation may not change in a lift range
    throw LineError{"#CS " + arguments.substr(0, arguments.find_first_of(" [")) + " inside the lift range of " +
                        state.machine.axes[static_cast<size_t>(state.lift->start.axis)].name +
                        " (LIFT_START in line " + std::to_string(state.lift->nc_line) + ") is not permitted",
                    120606};
  block.short_cut_restriction = ShortCutRestriction::not_skippable;  // DDTG-8
  if (arguments == "OFF") {
    if (!state.cs) throw LineError{"#CS OFF without an active #CS"};
    state.cs.reset();
    return;
  }
  if (arguments.rfind("ON", 0) != 0) throw LineError{"#CS takes ON [v1,v2,v3,φ1,φ2,φ3] or OFF"};
  const std::vector<std::string> groups = bracket_groups(arguments.substr(2));
  if (groups.empty() || groups.size() > 2)
    throw LineError{"#CS ON needs [v1,v2,v3,φ1,φ2,φ3], optionally after [<CS-ID>] (stored CS are not supported yet)"};
  if (state.cs)
    throw LineError{"#CS ON while a #CS is active: deselect it with #CS OFF first (nesting is not supported yet)"};
  for (const char* axis : {"X", "Y", "Z"})
    if (state.machine.axis_index(axis) < 0) throw LineError{"#CS needs the main axes X, Y and Z"};
  state.cs = CoordinateSystem::parse(groups.back(), state.parameters);
}

// #CHANNEL INIT [CMDPOS]: the command positions the interpolator would
// report are the ones decoded (this rig has no manual mode offsets); the
// path stands still there (Block::stops_path).
void decode_channel_init(const std::string& arguments, DecoderState&, Block& block) {
  if (without_blanks(arguments) != "[CMDPOS]")
    throw LineError{"#CHANNEL INIT takes [CMDPOS] (ACTPOS and single axes are not supported yet)"};
  block.short_cut_restriction = ShortCutRestriction::channel_initialisation;
}

// #CONTOUR MODE [ON|OFF] [<type> <key>=<value> ..] (KRN-6): the parameters
// of polynomial contouring; ON and OFF are G261 and G260. Types DEV
// (PATH_DEV) and DIST (DIST); the manual's other types and parameters are
// refused by name.
void decode_contour_mode(const std::string& arguments, DecoderState& state, Block&) {
  const CommandArguments args = read_command_arguments("#CONTOUR MODE", arguments);
  if (args.on == false) {
    if (args.has_list) throw LineError{"#CONTOUR MODE OFF takes no parameters"};
    if (state.modal.transition == BlockTransition::contour) state.modal.transition = BlockTransition::standard;
    return;
  }
  if (!args.on && !args.has_list) throw LineError{"#CONTOUR MODE needs ON, OFF or [DEV PATH_DEV=..] / [DIST DIST=..]"};
  ContourMode mode = state.modal.contour;
  bool dev_value = false, dist_value = false;
  for (const CommandParameter& item : args.parameters) {
    const std::string& key = item.key;
    if (!item.value) {
      if (key == "DEV") mode.type = ContourMode::Type::dev;
      else if (key == "DIST") mode.type = ContourMode::Type::dist;
      else if (key == "PTP" || key == "DIST_SOFT" || key == "DIST_MASTER" || key == "DEV_MASTER")
        throw LineError{"#CONTOUR MODE type " + key + " is not supported (DEV and DIST are)"};
      else throw LineError{"#CONTOUR MODE: unknown type '" + key + "'"};
      continue;
    }
    if (key == "PATH_DEV" || key == "DIST") {
      double value = 0;
      try {
        value = state.evaluate(*item.value);
      } catch (const std::invalid_argument& e) {
        throw LineError{"#CONTOUR MODE " + key + ": " + e.what()};
      }
      if (!(value > 0 && value <= max_length_mm))
        throw LineError{"#CONTOUR MODE " + key + " must be > 0 and <= " + std::to_string(max_length_mm) + " mm"};
      (key == "PATH_DEV" ? mode.path_dev : mode.dist) = value;
      (key == "PATH_DEV" ? dev_value : dist_value) = true;
    } else if (key == "TRACK_DEV" || key == "RELEASE_DIST" || key == "AX_DEV" || key == "AX_DIST" ||
               key == "MAX_ANGLE" || key == "PTP_ANGLE_MIN" || key == "WEIGHT" || key == "SLOPE" ||
               key == "TANGENTIAL" || key == "PTP_MAX_DEV" || key == "TRACK_DIST") {
      throw LineError{"#CONTOUR MODE parameter " + key + " is not supported (PATH_DEV with DEV, DIST with DIST)"};
    } else {
      throw LineError{"#CONTOUR MODE: unknown parameter '" + key + "'"};
    }
  }
  if (mode.type == ContourMode::Type::dev && dist_value) throw LineError{"#CONTOUR MODE DEV takes PATH_DEV, not DIST"};
  if (mode.type == ContourMode::Type::dist && dev_value) throw LineError{"#CONTOUR MODE DIST takes DIST, not PATH_DEV"};
  if (mode.type == ContourMode::Type::dist && !(mode.dist > 0)) throw LineError{"#CONTOUR MODE DIST needs DIST=.."};
  state.modal.contour = mode;
  if (args.on) state.modal.transition = BlockTransition::contour;
}

// #HSC [ON|OFF] [BSPLINE PATH_DEV=.. TRACK_DEV=.. MERGE=.. AUTO_OFF_PATH=..
// AUTO_OFF_TRACK=.. AUTO_OFF_G00=.. AUTO_OFF_G60=.. MAX_PATH_LENGTH=..
// MAX_ANGLE=..] (KRN-9, programming manual "Trim a contour"): BSPLINE first;
// parameters are modal and may be set without ON; OFF takes none.
void decode_hsc(const std::string& arguments, DecoderState& state, Block&) {
  const CommandArguments args = read_command_arguments("#HSC", arguments);
  if (args.on == false) {
    if (args.has_list) throw LineError{"#HSC OFF takes no parameters"};
    state.modal.hsc.on = false;
    return;
  }
  if (!args.on && !args.has_list) throw LineError{"#HSC needs ON, OFF or [BSPLINE ..]"};
  HscMode mode = state.modal.hsc;
  if (args.has_list) {
    if (args.parameters.empty() || args.parameters[0].key != "BSPLINE" || args.parameters[0].value)
      throw LineError{"#HSC: BSPLINE must be the first keyword of the list (the only HSC type of TF5200)"};
    for (size_t i = 1; i < args.parameters.size(); ++i) {
      const CommandParameter& item = args.parameters[i];
      const std::string& key = item.key;
      if (!item.value) throw LineError{"#HSC: '" + key + "' needs a value (" + key + "=..)"};
      double value = 0;
      try {
        value = state.evaluate(*item.value);
      } catch (const std::invalid_argument& e) {
        throw LineError{"#HSC " + key + ": " + e.what()};
      }
      auto length = [&](double& field, const char* unit) {
        if (!(value >= 0 && value <= max_length_mm))
          throw LineError{"#HSC " + key + " must be >= 0 and <= " + std::to_string(max_length_mm) + " " + unit};
        field = value;
      };
      auto flag = [&](bool& field) {
        if (value != 0 && value != 1) throw LineError{"#HSC " + key + " must be 0 or 1"};
        field = value == 1;
      };
      if (key == "PATH_DEV") length(mode.path_dev, "mm");
      else if (key == "TRACK_DEV") length(mode.track_dev, "degrees");
      else if (key == "MAX_PATH_LENGTH") length(mode.max_path_length, "mm");
      else if (key == "MAX_ANGLE") {
        if (!(value >= 0 && value <= 180)) throw LineError{"#HSC MAX_ANGLE must be >= 0 and <= 180 degrees"};
        mode.max_angle = value;
      } else if (key == "MERGE") flag(mode.merge);
      else if (key == "AUTO_OFF_PATH") flag(mode.auto_off_path);
      else if (key == "AUTO_OFF_TRACK") flag(mode.auto_off_track);
      else if (key == "AUTO_OFF_G00") flag(mode.auto_off_g00);
      else if (key == "AUTO_OFF_G60") flag(mode.auto_off_g60);
      else throw LineError{"#HSC: unknown parameter '" + key + "'"};
    }
  }
  if (args.on) mode.on = true;
  state.modal.hsc = mode;
}

// A whole number of an #INSERT CMD parameter within [min, max].
int64_t insert_whole(const std::string& key, const std::string& text, const DecoderState& state, int64_t min,
                     int64_t max) {
  double v = 0;
  try {
    v = state.evaluate(text);
  } catch (const std::invalid_argument&) {
    throw LineError{"#INSERT CMD " + key + "='" + text + "' is not a number"};
  }
  if (!(v >= static_cast<double>(min) && v <= static_cast<double>(max)) || v != std::floor(v))
    throw LineError{"#INSERT CMD " + key + "=" + text + ": a whole number " + std::to_string(min) + " .. " +
                    std::to_string(max)};
  return static_cast<int64_t>(v);
}

// #INSERT CMD [ON|OFF] [AXNR=.. MNR=.. ADDR=.. DIST=.. ABS|REL|REL_ONCE]
// (ISC-8); the defaults are #INSERT CMD [MNR=0 DIST=0 REL AXNR=0].
void decode_insert_cmd(const std::string& arguments, DecoderState& state, Block& block) {
  const CommandArguments args = read_command_arguments("#INSERT CMD", arguments);
  InsertCmdLine line;
  line.off = args.on == false;
  if (args.has_list) {
    if (line.off) throw LineError{"#INSERT CMD OFF takes no parameters"};
    InsertCommand c;
    int modes = 0;
    for (const CommandParameter& item : args.parameters) {
      const std::string& key = item.key;
      if (!item.value) {
        if (key == "ABS") c.rel_abs_mode = 1;
        else if (key == "REL") c.rel_abs_mode = 0;
        else if (key == "REL_ONCE") c.rel_abs_mode = 2;
        else throw LineError{"#INSERT CMD: unknown parameter '" + key + "'"};
        if (++modes > 1) throw LineError{"#INSERT CMD: ABS, REL and REL_ONCE exclude each other", 22130};
        continue;
      }
      const std::string& value = *item.value;
      if (key == "AXNR" || key == "AX") {
        c.axis_nr =
            static_cast<int>(insert_whole(key, value, state, 0, static_cast<int64_t>(state.machine.axes.size())));
      } else if (key == "MNR") {
        c.m_function_nr = static_cast<int>(insert_whole(key, value, state, 0, 65535));
      } else if (key == "ADDR") {
        c.add_nr = static_cast<int32_t>(insert_whole(key, value, state, INT32_MIN, INT32_MAX));
      } else if (key == "DIST") {
        double d = 0;
        try {
          d = state.evaluate(value);
        } catch (const std::invalid_argument&) {
          throw LineError{"#INSERT CMD DIST='" + value + "' is not a number"};
        }
        if (!(std::abs(d) <= max_length_mm * 1e4)) throw LineError{"#INSERT CMD DIST=" + value + " is out of range"};
        c.dist_or_pos = d;
      } else {
        throw LineError{"#INSERT CMD: unknown parameter '" + key + "'"};
      }
    }
    line.command = c;
  } else if (!args.on) {
    line.command = InsertCommand{};  // the defaults: DIST=0 REL clears the mark
  }
  block.insert_cmd = line;
}

// #FLUSH WAIT waits for an external signal as well: block search by
// distance cannot simulate it (DPS-3).
void decode_flush_wait(const std::string& arguments, DecoderState& state, Block& block) {
  decode_flush(arguments, state, block);
  block.not_searchable = "#FLUSH WAIT";
}

void decode_rotation(const std::string&, DecoderState& state, Block&) { refuse_rotation("#ROTATION", state); }
void decode_trafo(const std::string&, DecoderState& state, Block&) { refuse_rotation("#TRAFO", state); }

// A new command is a handler above and one row here (KRN-1).
constexpr NcCommand nc_commands[] = {
    {"#DISTANCE PROG START", decode_distance_prog_start},
    {"#SLOPE", decode_slope},
    {"#DEL DIST2GO", decode_del_dist2go},
    {"#TIME", decode_time},
    {"#CS", decode_coordinate_system},
    {"#CHANNEL INIT", decode_channel_init},
    {"#INSERT CMD", decode_insert_cmd},
    {"#CONTOUR MODE", decode_contour_mode},
    {"#HSC", decode_hsc},
    {"#FLUSH", decode_flush},
    {"#FLUSH WAIT", decode_flush_wait},
    {"#ROTATION", decode_rotation},
    {"#TRAFO", decode_trafo},
};

// The lift function (LIFT-1, lift_commands.hpp).
constexpr AxisCommand axis_commands[] = {
    {"LIFT_START", decode_lift_start},
    {"LIFT_END", decode_lift_end},
    {"LIFT", decode_lift},
};

}  // namespace

void decode_nc_command(const std::string& command, DecoderState& state, Block& block) {
  const NcCommand* found = find_command(nc_commands, command);
  if (!found) throw LineError{"command '" + command.substr(0, command.find_first_of(" [")) + "' is not supported yet"};
  found->decode(arguments_after(command, found->keyword), state, block);
}

void decode_axis_command(const Word& word, int axis, DecoderState& state, Block& block) {
  const AxisCommand* found = find_command(axis_commands, word.command);
  if (!found) {
    std::istringstream items(word.command);
    for (std::string item; items >> item;)
      if (find_command(axis_commands, item))  // LIFT-1: Z[POS_LIMIT=30 LIFT_START]
        throw LineError{std::string(1, word.letter) + "[" + item + "]: " + item + " must be the first keyword"};
    throw LineError{std::string("axis command '") + word.letter + "[" + command_keyword(word.command) +
                    "]' is not supported yet"};
  }
  found->decode(axis, arguments_after(word.command, found->keyword), state, block);
}

}  // namespace hil::cnc::decoding
