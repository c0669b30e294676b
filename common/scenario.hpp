#pragma once
// A HIL scenario (RIG-5): machine configuration, NC program, PLC timeline and
// expectations. Files are YAML; see docs/SCENARIOS.md for the format.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "event.hpp"
#include "hli.hpp"
#include "fault_plan.hpp"
#include "machine_config.hpp"

namespace hil {

// A conjunction of predicates on the HLI state; a trigger fires the first
// cycle in which all of them hold.
struct Condition {
  std::optional<int64_t> cycle;               // cycle >= value
  std::optional<double> time_s;               // cycle * cycle time >= value
  std::optional<int64_t> block_nr_r;          // == value
  std::optional<int64_t> block_count_r;       // == value
  std::optional<double> dist_prog_start_mm;   // covered distance >= value
  std::optional<bool> path_standing;          // path_velocity == 0 (true) or > 0 (false)
  std::optional<ChannelState> channel_state;  // == value
  std::optional<bool> delete_distance_to_go_active_r;  // == value
  std::optional<int32_t> m_function_nr_r;     // this M function waits for acknowledgement
  // Other HLI state fields by name (hli_names.hpp), == value.
  std::map<std::string, int64_t> fields;
  // Per-axis BOOL arrays by name, per axis: {"lift_active": {"Z": true}}.
  std::map<std::string, std::map<std::string, bool>> axis_flags;

  bool holds(const HliState& state, double cycle_time_s) const;
  std::string describe() const;
};

// One write to a control unit field, e.g. "program_start.command_w": true
// or "override.command_w": 500 (true / false are 1 / 0). The loader checks
// the name and that the field's type holds the value (hli_names.hpp).
struct ControlWrite {
  std::string field;
  int64_t value = 0;
};

struct TimelineStep {
  Condition when;
  std::vector<ControlWrite> set;
};

// A bound on an axis' highest (axis_max_*) or lowest (axis_min_*)
// commanded position over an expectation's window.
struct ExtremeCheck {
  enum class Bound { equal, at_least, at_most };
  std::string key;  // "axis_max_mm", "axis_min_at_most_mm", ...
  std::string axis;
  bool highest = true;
  Bound bound = Bound::equal;
  double mm = 0;
};

// Checks on the HLI state at the moment `when` first holds. With `since`,
// the expectation has a window: from the first cycle `since` holds on
// (without: from the run's start), `when` is looked for from there; the
// extremes and the time are taken over that window.
struct Expectation {
  Condition when;
  std::optional<Condition> since;
  std::optional<ChannelState> channel_state;
  std::optional<int64_t> block_nr_r;
  std::optional<int64_t> block_count_r;
  std::optional<double> dist_prog_start_mm;
  std::optional<bool> delete_distance_to_go_active_r;
  std::map<std::string, double> axis_position_mm;
  std::map<std::string, int64_t> fields;  // other HLI state fields (hli_names.hpp)
  std::map<std::string, std::map<std::string, bool>> axis_flags;  // lift_active: {Z: true}
  std::vector<ExtremeCheck> extremes;
  // The time from the window's start to the cycle `when` first held.
  std::optional<double> time_s_at_least, time_s_at_most;
  // The largest |path_velocity| over the window, mm/s (LIFT-2, LIFT-8).
  std::optional<double> path_velocity_max_at_least_mm_s, path_velocity_max_at_most_mm_s;
  double tolerance_mm = 0.001;
};

// An event that must (or, with count 0, must not) appear during the run.
struct EventExpectation {
  std::optional<int32_t> id;  // if set, only events with this TF5200 number count
  Severity severity = Severity::error;
  std::string parameter;  // if set, only events about this parameter ID count
  int64_t nc_line = 0;  // if > 0, only events from this NC program line count
  int count_min = 1;    // at least this many
  bool absent = false;  // instead: none may appear
};

// An offline-check violation the scenario provokes on purpose (RIG-4): the
// run passes only if it is found, and no violation passes unless expected.
struct ViolationExpectation {
  std::string axis;
  std::string quantity;  // a part of the checker's quantity, e.g. "actual acceleration"
  bool matches(const std::string& violation_axis, const std::string& violation_quantity) const {
    return violation_axis == axis && violation_quantity.find(quantity) != std::string::npos;
  }
};

struct Scenario {
  std::string name;
  std::string description;
  std::vector<std::string> requirements;  // SPEC IDs the scenario exercises
  MachineConfig machine;
  std::string nc_program;
  double max_time_s = 60;      // the CNC aborts the run after this much simulated time
  double settle_time_s = 0.1;  // cycles run after program end, for drives and PLC
  std::vector<TimelineStep> timeline;
  // The PLC acknowledges each M function this many cycles after the CNC
  // outputs it; 0: only the timeline acknowledges (m_function_ack).
  int m_function_ack_cycles = 1;
  std::vector<Expectation> expectations;
  std::vector<EventExpectation> expected_events;
  std::vector<ViolationExpectation> expected_violations;
  bool allow_errors = false;   // unexpected error events fail the run unless true
  FaultPlan faults;            // RIG-8: what the rig does to the cycle channels
  // RIG-6: the CNC ticks on the wall clock and never waits for answers
  // (docs/REALTIME.md); false: lock-step.
  bool realtime = false;

  YAML::Node resolved;  // the whole scenario, machine and NC program inline
};

// Loads a scenario file; `machine:` and `nc_file:` may name files relative
// to it. Throws ConfigError naming the file and the key's path
// ("machine.axes[1].slep_max"); an unknown key is an error, with the
// closest known key (config_error.hpp).
Scenario load_scenario_file(const std::string& path);
// The same for a file's top mapping already read (`path` names the file and
// the folder its `machine:` and `nc_file:` are relative to).
Scenario load_scenario_node(YAML::Node root, const std::string& path);
// A scenario file's YAML as it stands (ConfigError if it cannot be read).
YAML::Node load_scenario_yaml(const std::string& path);
// Parses a scenario whose machine and NC program are inline (as in a manifest).
Scenario parse_scenario(const YAML::Node& root);
std::string to_yaml(const Scenario& scenario);
// What makes `text` no NC program, "" if nothing: "line 3: byte 0x00 (NUL)
// is not text: ...". A control character other than tab, CR and LF is
// binary, not text; bytes >= 0x80 pass (UTF-8 or Latin-1 comments).
std::string nc_text_problem(const std::string& text);

}  // namespace hil
