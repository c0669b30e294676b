#include "scenario_engine.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "hli_names.hpp"

namespace hil::plc {
namespace {

// "highest Z 29.5 mm"
std::string axis_extreme_text(const ExtremeCheck& x, double mm) {
  std::ostringstream out;
  out << (x.highest ? "highest " : "lowest ") << x.axis << " " << mm << " mm";
  return out.str();
}

// "at block_nr_r=40", "at program_end since channel_state=ACTIVE"
std::string what(const Expectation& e) {
  return "at " + e.when.describe() + (e.since ? " since " + e.since->describe() : "");
}

std::string mm_text(double mm) {
  std::ostringstream out;
  out << mm << " mm";
  return out.str();
}

}  // namespace

ScenarioEngine::ScenarioEngine(const Scenario& scenario)
    : timeline_(scenario.timeline), fired_(scenario.timeline.size(), false),
      expected_events_(scenario.expected_events), allow_errors_(scenario.allow_errors),
      m_function_ack_cycles_(scenario.m_function_ack_cycles),
      cycle_time_s_(scenario.machine.cycle_time_s()) {
  for (const Expectation& e : scenario.expectations) {
    Pending p;
    p.expectation = e;
    p.opened = !e.since;  // the window begins with the run
    pending_.push_back(std::move(p));
  }
}

const HliControl& ScenarioEngine::cycle(const HliState& state) {
  control_.cycle = state.cycle;
  // semaphor_rw is one variable the PLC raises and the CNC clears (ISC-1):
  // the PLC's copy follows the CNC's once it has answered.
  control_.insert_cmd.semaphor_rw = state.insert_cmd.semaphor_rw;
  // The PLC's M function handling: acknowledge with a one-cycle pulse.
  if (m_function_ack_cycles_ > 0) {
    ControlUnitBool& ack = control_.m_function_ack;
    ack.enable_w = true;
    if (ack.command_w) {
      ack.command_w = false;
    } else if (state.m_function_request_r && ++m_function_waited_ >= m_function_ack_cycles_) {
      ack.command_w = true;
      m_function_waited_ = 0;
    }
    if (!state.m_function_request_r) m_function_waited_ = 0;
  }
  for (size_t i = 0; i < timeline_.size(); ++i) {
    if (fired_[i] || !timeline_[i].when.holds(state, cycle_time_s_)) continue;
    fired_[i] = true;
    for (const ControlWrite& write : timeline_[i].set) write_hli_field(control_, write.field, write.value);
  }
  for (Pending& p : pending_) {
    if (p.reached) continue;
    if (!p.opened && p.expectation.since->holds(state, cycle_time_s_)) {
      p.opened = true;
      p.opened_cycle = state.cycle;
    }
    if (!p.opened) continue;
    p.path_velocity_max = std::max(p.path_velocity_max, std::abs(state.path_velocity));
    for (const ExtremeCheck& x : p.expectation.extremes) {
      for (size_t i = 0; i < state.axis_name.size() && i < state.axis_position_r.size(); ++i) {
        if (state.axis_name[i] != x.axis) continue;
        const double mm = static_cast<double>(state.axis_position_r[i]) / hli_units_per_mm;
        Extremes& seen = p.extremes[x.axis];
        seen.highest = seen.seen ? std::max(seen.highest, mm) : mm;
        seen.lowest = seen.seen ? std::min(seen.lowest, mm) : mm;
        seen.seen = true;
      }
    }
    if (!p.expectation.when.holds(state, cycle_time_s_)) continue;
    p.reached = true;
    p.result = evaluate(p, state);
  }
  return control_;
}

void ScenarioEngine::observe(const Event& event) { seen_events_.push_back(event); }

ExpectationResult ScenarioEngine::evaluate(const Pending& p, const HliState& s) const {
  const Expectation& e = p.expectation;
  ExpectationResult r;
  r.what = what(e);
  std::ostringstream failures;
  auto check = [&](bool ok, const std::string& text) {
    if (!ok) failures << ' ' << text << ';';
  };
  if (e.channel_state)
    check(s.channel_state == *e.channel_state, std::string("channel_state ") + to_string(s.channel_state) +
                                                   " != " + to_string(*e.channel_state));
  if (e.block_nr_r)
    check(s.block_nr_r == *e.block_nr_r,
          "block_nr_r " + std::to_string(s.block_nr_r) + " != " + std::to_string(*e.block_nr_r));
  if (e.block_count_r)
    check(s.block_count_r == *e.block_count_r,
          "block_count_r " + std::to_string(s.block_count_r) + " != " + std::to_string(*e.block_count_r));
  if (e.dist_prog_start_mm) {
    const double mm = s.dist_prog_start / hli_units_per_mm;
    check(std::abs(mm - *e.dist_prog_start_mm) <= e.tolerance_mm,
          "dist_prog_start " + std::to_string(mm) + " mm != " + std::to_string(*e.dist_prog_start_mm));
  }
  if (e.delete_distance_to_go_active_r)
    check(s.delete_distance_to_go_active_r == *e.delete_distance_to_go_active_r,
          std::string("delete_distance_to_go_active_r ") + (s.delete_distance_to_go_active_r ? "true" : "false"));
  for (const auto& [name, expected] : e.fields) {
    const int64_t value = read_hli_field(s, name).value_or(0);
    check(value == expected, name + " " + std::to_string(value) + " != " + std::to_string(expected));
  }
  for (const auto& [axis, expected] : e.axis_position_mm) {
    for (size_t i = 0; i < s.axis_name.size(); ++i) {
      if (s.axis_name[i] != axis) continue;
      const double mm = static_cast<double>(s.axis_position_r[i]) / hli_units_per_mm;
      check(std::abs(mm - expected) <= e.tolerance_mm,
            axis + " at " + std::to_string(mm) + " mm != " + std::to_string(expected));
    }
  }
  for (const auto& [name, axes] : e.axis_flags) {
    const HliAxisFlag* flag = find_hli_axis_flag(name);
    for (const auto& [axis, expected] : axes) {
      const std::optional<bool> read = flag ? flag->read(s, axis) : std::nullopt;
      const bool known = read.has_value(), value = read.value_or(false);
      check(known && value == expected, name + " of " + axis + " " + (known ? (value ? "true" : "false") : "missing"));
    }
  }
  for (const ExtremeCheck& x : e.extremes) {
    const auto seen = p.extremes.find(x.axis);
    if (seen == p.extremes.end()) {
      check(false, x.key + " " + x.axis + ": no position of the axis in the window");
      continue;
    }
    const double mm = x.highest ? seen->second.highest : seen->second.lowest;
    const bool ok = x.bound == ExtremeCheck::Bound::equal      ? std::abs(mm - x.mm) <= e.tolerance_mm
                    : x.bound == ExtremeCheck::Bound::at_least ? mm >= x.mm - e.tolerance_mm
                                                               : mm <= x.mm + e.tolerance_mm;
    const char* relation = x.bound == ExtremeCheck::Bound::equal      ? " != "
                           : x.bound == ExtremeCheck::Bound::at_least ? " < "
                                                                      : " > ";
    check(ok, axis_extreme_text(x, mm) + relation + mm_text(x.mm));
  }
  const double window_s = static_cast<double>(s.cycle - p.opened_cycle) * cycle_time_s_;
  auto time_text = [&](const char* relation, double bound) {
    std::ostringstream out;
    out << "time " << window_s << " s" << relation << bound << " s";
    return out.str();
  };
  if (e.time_s_at_least) check(window_s + 1e-9 >= *e.time_s_at_least, time_text(" < ", *e.time_s_at_least));
  if (e.time_s_at_most) check(window_s <= *e.time_s_at_most + 1e-9, time_text(" > ", *e.time_s_at_most));
  auto velocity_text = [&](const char* relation, double bound) {
    std::ostringstream out;
    out << "path_velocity up to " << p.path_velocity_max << " mm/s" << relation << bound << " mm/s";
    return out.str();
  };
  // 1e-9 relative: round-off, not a tolerance.
  if (e.path_velocity_max_at_least_mm_s)
    check(p.path_velocity_max >= *e.path_velocity_max_at_least_mm_s * (1 - 1e-9),
          velocity_text(" < ", *e.path_velocity_max_at_least_mm_s));
  if (e.path_velocity_max_at_most_mm_s)
    check(p.path_velocity_max <= *e.path_velocity_max_at_most_mm_s * (1 + 1e-9),
          velocity_text(" > ", *e.path_velocity_max_at_most_mm_s));
  r.detail = failures.str();
  r.passed = r.detail.empty();
  if (r.passed) r.detail = " all checks hold";
  return r;
}

std::vector<ExpectationResult> ScenarioEngine::finish() const {
  std::vector<ExpectationResult> results;
  for (const Pending& p : pending_) {
    if (p.reached) results.push_back(p.result);
    else if (!p.opened) results.push_back({what(p.expectation), false, " 'since' never held"});
    else results.push_back({what(p.expectation), false, " never reached"});
  }
  auto matches = [](const EventExpectation& x, const Event& e) {
    return (!x.id || e.id == *x.id) && e.severity == x.severity && (x.nc_line == 0 || e.nc_line == x.nc_line) &&
           (x.parameter.empty() || e.parameter == x.parameter);
  };
  for (const EventExpectation& x : expected_events_) {
    int count = 0;
    for (const Event& e : seen_events_) count += matches(x, e) ? 1 : 0;
    ExpectationResult r;
    r.what = std::string(x.absent ? "no " : "") + to_string(x.severity) + (x.id ? " " + std::to_string(*x.id) : "") +
             (x.parameter.empty() ? "" : " (" + x.parameter + ")") +
             (x.nc_line > 0 ? " on line " + std::to_string(x.nc_line) : "");
    r.passed = x.absent ? count == 0 : count >= x.count_min;
    r.detail = " seen " + std::to_string(count) + " time(s)";
    results.push_back(r);
  }
  if (!allow_errors_) {
    for (const Event& e : seen_events_) {
      if (e.severity != Severity::error) continue;
      bool expected = false;
      for (const EventExpectation& x : expected_events_) expected = expected || (!x.absent && matches(x, e));
      if (!expected) results.push_back({"no unexpected error", false, " " + describe(e)});
    }
  }
  return results;
}

}  // namespace hil::plc
