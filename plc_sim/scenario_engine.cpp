#include "scenario_engine.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <utility>
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

// "at block_nr_r=40", "at program_end since channel_state=ACTIVE",
// "never axis_position_mm.X>=100.001 since block_nr_r=20 until channel_state=PROGRAM_END"
std::string what(const Expectation& e) {
  const std::string window =
      (e.since ? " since " + e.since->describe() : "") + (e.until ? " until " + e.until->describe() : "");
  switch (e.kind) {
    case Expectation::Kind::never: return "never " + e.watched.describe() + window;
    case Expectation::Kind::always: return "always " + e.watched.describe() + window;
    case Expectation::Kind::at: break;
  }
  return "at " + e.when.describe() + window;
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
  // The PLC's technology function handling (M, H, S, T; KRN-8):
  // acknowledge each with a one-cycle pulse.
  if (m_function_ack_cycles_ > 0) {
    const std::pair<ControlUnitBool*, bool> handshakes[] = {
        {&control_.m_function_ack, state.m_function_request_r},
        {&control_.h_function_ack, state.h_function_request_r},
        {&control_.s_function_ack, state.s_function_request_r},
        {&control_.t_function_ack, state.t_function_request_r}};
    for (size_t k = 0; k < std::size(handshakes); ++k) {
      ControlUnitBool& ack = *handshakes[k].first;
      const bool requested = handshakes[k].second;
      ack.enable_w = true;
      if (ack.command_w) {
        ack.command_w = false;
      } else if (requested && ++function_waited_[k] >= m_function_ack_cycles_) {
        ack.command_w = true;
        function_waited_[k] = 0;
      }
      if (!requested) function_waited_[k] = 0;
    }
  }
  for (size_t i = 0; i < timeline_.size(); ++i) {
    if (fired_[i] || !timeline_[i].when.holds(state, cycle_time_s_)) continue;
    fired_[i] = true;
    for (const ControlWrite& write : timeline_[i].set) write_hli_field(control_, write.field, write.value);
  }
  // A state lost on the way (RIG-8) is a cycle no never: / always: saw.
  const bool missed_cycles = state.cycle > last_cycle_ + 1;
  for (Pending& p : pending_) {
    if (p.reached) continue;
    const bool was_open = p.opened;
    if (!p.opened && p.expectation.since->holds(state, cycle_time_s_)) {
      p.opened = true;
      p.opened_cycle = state.cycle;
    }
    if (!p.opened) continue;
    if (p.expectation.kind != Expectation::Kind::at) {
      watch(p, state, was_open && missed_cycles);
      continue;
    }
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
    p.result.cycle = state.cycle;
  }
  last_cycle_ = state.cycle;
  return control_;
}

void ScenarioEngine::watch(Pending& p, const HliState& state, bool missed_cycles) {
  const Expectation& e = p.expectation;
  auto decide = [&](bool passed, const std::string& detail) {
    p.reached = true;
    p.result = {what(e), passed, detail, state.cycle};
  };
  // `until` ends the window before its cycle; looked for from the window's
  // second cycle on, so that a window holds one cycle at least.
  if (e.until && state.cycle > p.opened_cycle && e.until->holds(state, cycle_time_s_)) {
    decide(true, " held in cycles " + std::to_string(p.opened_cycle) + ".." + std::to_string(last_cycle_));
    return;
  }
  // A cycle not seen might have broken it: no PASS on a guess.
  if (missed_cycles) {
    decide(false, " cycles " + std::to_string(last_cycle_ + 1) + ".." + std::to_string(state.cycle - 1) +
                      " not seen by the PLC: not checked");
    return;
  }
  std::string broken;
  const bool holds = e.watched.check(state, cycle_time_s_, &broken);
  if (e.kind == Expectation::Kind::never && holds)
    decide(false, " broken in cycle " + std::to_string(state.cycle) + ": " + e.watched.seen(state, cycle_time_s_));
  else if (e.kind == Expectation::Kind::always && !holds)
    decide(false, " broken in cycle " + std::to_string(state.cycle) + ":" + broken);
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
  std::string broken;
  if (!e.checks.check(s, cycle_time_s_, &broken)) failures << broken;
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

std::vector<ExpectationResult> ScenarioEngine::finish(std::optional<int64_t> end_cycle) const {
  std::vector<ExpectationResult> results;
  const int64_t last = end_cycle.value_or(last_cycle_);
  for (const Pending& p : pending_) {
    const Expectation& e = p.expectation;
    if (p.reached) results.push_back(p.result);
    else if (!p.opened) results.push_back({what(e), false, " 'since' never held", std::nullopt});
    else if (e.kind == Expectation::Kind::at) results.push_back({what(e), false, " never reached", std::nullopt});
    // A window `until` should have closed stays open: the run did not go where the scenario says.
    else if (e.until) results.push_back({what(e), false, " 'until' never held", std::nullopt});
    else if (last_cycle_ < last)
      results.push_back({what(e), false,
                         " the PLC saw cycles up to " + std::to_string(last_cycle_) + " of " + std::to_string(last) +
                             ": not checked to the end",
                         std::nullopt});
    else
      results.push_back({what(e), true,
                         " held in cycles " + std::to_string(p.opened_cycle) + ".." + std::to_string(last_cycle_),
                         std::nullopt});
  }
  for (const EventExpectation& x : expected_events_) {
    int count = 0;
    for (const Event& e : seen_events_) count += x.matches(e) ? 1 : 0;
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
      for (const EventExpectation& x : expected_events_) expected = expected || (!x.absent && x.matches(e));
      if (!expected) results.push_back({"no unexpected error", false, " " + describe(e), std::nullopt});
    }
  }
  return results;
}

}  // namespace hil::plc
