#pragma once
// YAML syntax errors in plain words (issue 37, RIG-5): yaml-cpp says "end of
// map flow not found" on the line after an unclosed '{', "illegal map value"
// for a TAB, "end of map not found" for an indentation slip. This says what
// is wrong and where the problem starts, and shows that line.
#include <yaml-cpp/yaml.h>

#include <string>

namespace hil {

// "line 3: a TAB in the indentation (YAML indents with spaces only)\n
//    3 | <the line>" for the text yaml-cpp refused with `error`.
std::string explain_yaml_error(const std::string& text, const YAML::Exception& error);

}  // namespace hil
