#pragma once
// A condition on the HLI state (RIG-5): what a trigger (`when:`, `since:`,
// `until:`) waits for, what `never:` / `always:` watch in every cycle of a
// window, and what an expectation checks with ranges at its moment. A
// conjunction: it holds in a cycle when all its predicates hold.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hli.hpp"
#include "value_range.hpp"

namespace hil {

// stop_conditions_r by bit names: exactly these bits, or (contains) these
// bits set and the others free.
struct StopConditionMatch {
  int32_t bits = 0;
  bool contains = false;
  bool matches(int32_t value) const { return contains ? (value & bits) == bits : value == bits; }
  std::string describe() const;
};

struct Condition {
  std::optional<ValueRange> cycle;               // the HLI state's cycle
  std::optional<ValueRange> time_s;              // cycle * cycle time, s
  std::optional<ValueRange> block_nr_r;
  std::optional<ValueRange> block_count_r;
  std::optional<ValueRange> dist_prog_start_mm;  // covered distance, mm
  std::optional<ValueRange> path_velocity_mm_s;  // path_velocity as the CNC publishes it
  std::optional<bool> path_standing;             // path_velocity == 0 (true) or > 0 (false)
  std::optional<ChannelState> channel_state;
  std::optional<bool> delete_distance_to_go_active_r;
  std::optional<int32_t> m_function_nr_r;  // this M function waits for acknowledgement
  std::optional<StopConditionMatch> stop_conditions_r;
  // Other HLI state fields by name (hli_names.hpp).
  std::map<std::string, ValueRange> fields;
  // Commanded positions by axis name, mm.
  std::map<std::string, ValueRange> axis_position_mm;
  // Per-axis BOOL arrays by name, per axis: {"lift_active": {"Z": true}}.
  std::map<std::string, std::map<std::string, bool>> axis_flags;

  bool empty() const;
  bool holds(const HliState& state, double cycle_time_s) const { return check(state, cycle_time_s, nullptr); }
  // As holds(); if it does not, and `broken` is given, appends each broken
  // predicate with the value seen: " path_velocity_mm_s 12.5 (expected path_velocity_mm_s<=10);".
  bool check(const HliState& state, double cycle_time_s, std::string* broken) const;
  // The values its predicates read in `state`: "axis_position_mm.X=100.0021".
  std::string seen(const HliState& state, double cycle_time_s) const;
  std::string describe() const;
  // Each axis it names (for the check against the machine), with its key.
  std::vector<std::pair<std::string, std::string>> axes() const;
};

// What a plain number (no range) means for a key where ranges are allowed:
// in a trigger the value has been reached (cycle, time_s,
// dist_prog_start_mm, path_velocity_mm_s: >=; block numbers and HLI
// fields: ==); in an expectation's check the value itself.
enum class PlainNumber { trigger, exactly };

// The keys a condition takes (with the HLI state fields by name).
const std::vector<std::string>& condition_keys();
// One key of a condition; false if `key` is no condition key. ConfigError
// on a bad value, naming `where`.
bool parse_condition_key(Condition& c, const std::string& key, const YAML::Node& value, const std::string& where,
                         PlainNumber plain, double tolerance_mm = 0);
// A trigger: a mapping of condition keys, or `program_end`.
Condition parse_condition(const YAML::Node& node, const std::string& where);

}  // namespace hil
