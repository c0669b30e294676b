#pragma once
// A HIL scenario (RIG-5): machine configuration, NC program, PLC timeline and
// expectations. Files are YAML; see docs/SCENARIOS.md for the format.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "condition.hpp"
#include "event.hpp"
#include "hli.hpp"
#include "fault_plan.hpp"
#include "machine_config.hpp"

namespace hil {

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

// An expectation on the HLI state over a window: from the first cycle
// `since` holds on (without: from the run's start).
//  - at: `checks` must hold at the first cycle of the window `when` holds
//    in; the extremes and the time are taken over the window up to it.
//  - never / always: `watched` must hold in no / every cycle of the window,
//    which ends before the first cycle after its start `until` holds in
//    (without: at the run's end).
struct Expectation {
  enum class Kind { at, never, always };
  Kind kind = Kind::at;
  Condition when;
  std::optional<Condition> since;
  std::optional<Condition> until;
  Condition watched;
  Condition checks;  // plain numbers exact (positions and distance within tolerance_mm)
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
  bool matches(const Event& e) const {
    return (!id || e.id == *id) && e.severity == severity && (nc_line == 0 || e.nc_line == nc_line) &&
           (parameter.empty() || e.parameter == parameter);
  }
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
  // Where the program stands, for messages (issue 37): its NC file (line
  // 0), or the scenario file and the line of an inline nc_program's line 1;
  // "" when not known (a scenario read from a manifest).
  std::string nc_source;
  int64_t nc_source_line = 0;
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
// Sets where `scenario`'s inline nc_program begins in the scenario file
// `path` that `root` was read from (its marks intact: not a clone).
void locate_nc_program(Scenario& scenario, const YAML::Node& root, const std::string& path);
// "nc_program line 6 (scenario file line 12)", "part.nc line 6", "NC program line 6".
std::string nc_line_place(const Scenario& scenario, int64_t nc_line);
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
