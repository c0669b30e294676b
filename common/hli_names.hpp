#pragma once
// The HLI's fields by their TF5200 names, for scenarios (RIG-5, KRN-4):
// "feedhold.command_w", "delete_distance_to_go_activation.state_r",
// "m_function_request_r". Every BOOL, DINT, UDINT and LINT field of the
// table (hli_table.hpp) has one, in the table's order; TRUE / FALSE are 1 / 0.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hli.hpp"

namespace hil {

// One named field of Record (HliControl or HliState).
template <typename Record>
struct HliField {
  std::string name;
  const char* type = "";  // BOOL, DINT, UDINT or LINT
  int64_t min = 0;        // the values the type holds
  int64_t max = 0;
  std::function<int64_t(const Record&)> read;
  std::function<void(Record&, int64_t)> write;  // the value within min .. max

  bool holds(int64_t value) const { return value >= min && value <= max; }
  // "a BOOL (true or false)", "a UDINT (0 .. 4294967295)"
  std::string type_text() const;
};

template <typename Record>
const std::vector<HliField<Record>>& hli_fields();
// The field called `name`, or nullptr.
template <typename Record>
const HliField<Record>* find_hli_field(const std::string& name);
// By name: none / false if there is no such field, or its type does not
// hold the value.
template <typename Record>
std::optional<int64_t> read_hli_field(const Record& record, const std::string& name);
template <typename Record>
bool write_hli_field(Record& record, const std::string& name, int64_t value);
// Every name, for messages: "program_start.command_w, ..., override.command_w (DINT), ...".
template <typename Record>
std::string hli_field_names();

// The per-axis BOOL arrays of HliState by name (lift_active,
// lift_suppressed, LIFT-7): every std::vector<bool> of the table. A
// scenario names the axis: `lift_active: {Z: true}`.
struct HliAxisFlag {
  std::string name;
  // The axis' value, none if the state has no such axis.
  std::function<std::optional<bool>(const HliState&, const std::string& axis)> read;
};
const std::vector<HliAxisFlag>& hli_axis_flags();
const HliAxisFlag* find_hli_axis_flag(const std::string& name);

}  // namespace hil
