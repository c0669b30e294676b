#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hil::cnc::decoding {

// One item of a command's parameter list: a keyword (DEV, ABS) or
// KEY=value, the value text an expression still to evaluate.
struct CommandParameter {
  std::string key;
  std::optional<std::string> value;
};

// What follows a command such as #INSERT CMD or #CONTOUR MODE:
// an optional ON / OFF, then at most one [..] list.
struct CommandArguments {
  std::optional<bool> on;  // ON: true, OFF: false
  std::vector<CommandParameter> parameters;
  bool has_list = false;  // a [..] was written, even an empty one
};

// Reads `arguments` (upper case, single blanks). Items are separated by
// blanks or commas; blanks around '=' belong to it (DIST = 5 is DIST=5).
// Throws LineError naming `command` for anything after the list or a
// second list.
CommandArguments read_command_arguments(const std::string& command, const std::string& arguments);

// The items of a parameter list without its brackets (an axis command's
// LIFT_START DOWN POS=12 POS_LIMIT=100): separated by blanks; blanks
// around '=' belong to it; a blank inside [..] (a value's expression,
// POS=[P1 + 2]) separates nothing. Throws LineError naming `command` for
// a '=' without a name.
std::vector<CommandParameter> read_parameter_items(const std::string& command, const std::string& items);

}  // namespace hil::cnc::decoding
