#pragma once
// The JSON Schema (draft 2020-12) of scenario and machine files (issue 37,
// RIG-5), made from the loaders' key tables (file_keys.hpp): every mapping
// with the keys it may have and no other, the lists and the nesting. The
// loaders check values, ranges and what depends on the machine; the schema
// lets an editor (yaml-language-server) complete the keys and mark a typo.
// schemas/*.schema.json are its output (`hil schema`), checked in ctest.
#include <string>

namespace hil {

std::string scenario_schema();
std::string machine_schema();

}  // namespace hil
