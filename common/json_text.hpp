#pragma once
// A text as a JSON string literal, quotes and control characters escaped:
// the rig's JSON (suite results, the files' JSON Schema) is written, not parsed.
#include <string>

namespace hil {

std::string json_string(const std::string& text);

}  // namespace hil
