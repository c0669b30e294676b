#include "limit_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hil::logger {
namespace {

// `cycle` - `back`, wrapping: a log's cycles may be any int64 (a crafted
// one's INT64_MIN), where signed arithmetic would overflow.
int64_t cycle_before(int64_t cycle, int64_t back) {
  return static_cast<int64_t>(static_cast<uint64_t>(cycle) - static_cast<uint64_t>(back));
}

}  // namespace

LimitChecker::LimitChecker(const MachineConfig& machine)
    : machine_(machine), setpoints_(machine.axes.size()), lift_active_(machine.axes.size()),
      summary_(machine.axes.size()) {
  for (size_t i = 0; i < machine.axes.size(); ++i) {
    const AxisConfig& a = machine.axes[i];
    AxisSummary& s = summary_[i];
    s.axis = a.name;
    s.v_max = a.v_max;
    s.a_max = a.a_max;
    s.j_max = a.j_max;
    s.a_err_limit = a.accel_error_limit();
    s.v_err_limit = a.velocity_error_limit();
    s.slep_max = a.slep_max;
  }
}

void LimitChecker::add_lift_active(int axis, int64_t cycle) {
  if (lift_active_[axis].insert(cycle).second) ++summary_[axis].lift_cycles;
}

// Only Lifting's acceleration rule asks for the path velocity.
void LimitChecker::add_path_velocity(int64_t cycle, double path_velocity) {
  if (machine_.lift_method == LiftMethod::path_based) path_velocity_[cycle] = path_velocity;
}

void LimitChecker::add_hli_state(const HliState& state) {
  add_path_velocity(state.cycle, state.path_velocity);
  for (size_t i = 0; i < state.axis_name.size() && i < state.lift_active.size(); ++i) {
    if (!state.lift_active[i]) continue;
    const int axis = machine_.axis_index(state.axis_name[i]);
    if (axis >= 0) add_lift_active(axis, state.cycle);
  }
}

void LimitChecker::check(std::vector<Violation>& out, double& max_seen, double value, double limit,
                         int64_t cycle, const std::string& axis, const char* quantity, double noise) const {
  const double magnitude = std::abs(value);
  if (!std::isfinite(value)) {  // a number that is not finite breaks every limit
    record(out, value, limit, cycle, axis, quantity);
    return;
  }
  max_seen = std::max(max_seen, magnitude);
  if (limit > 0 && magnitude > limit * (1 + limit_tolerance) + noise) record(out, value, limit, cycle, axis, quantity);
}

void LimitChecker::check_software_limits(std::vector<Violation>& out, const AxisConfig& a, double position,
                                         double tolerance, int64_t cycle, const char* quantity_pos,
                                         const char* quantity_neg) const {
  if (!a.software_limits) return;
  if (position > a.swe_pos + tolerance) record(out, position, a.swe_pos + tolerance, cycle, a.name, quantity_pos);
  if (position < a.swe_neg - tolerance) record(out, position, a.swe_neg - tolerance, cycle, a.name, quantity_neg);
}

void LimitChecker::record(std::vector<Violation>& out, double value, double limit, int64_t cycle,
                          const std::string& axis, const char* quantity) const {
  const double t = cycle * machine_.cycle_time_s();
  // Quantities of one axis interleave in `out`: the episode to extend, if
  // any, is among the last few entries.
  for (size_t back = 0; back < std::min<size_t>(out.size(), 6); ++back) {
    Violation& v = out[out.size() - 1 - back];
    if (v.axis != axis || v.quantity != quantity) continue;
    if (std::round(v.end_time_s / machine_.cycle_time_s()) + 1 != static_cast<double>(cycle)) break;
    v.end_time_s = t;
    ++v.cycles;
    if (std::abs(value) > std::abs(v.value)) {
      v.value = value;
      v.worst_time_s = t;
    }
    return;
  }
  out.push_back({t, t, 1, axis, quantity, value, t, limit});
}

void LimitChecker::add_setpoint(int axis, int64_t cycle, double position) {
  setpoints_[axis].cycle.push_back(cycle);
  setpoints_[axis].position.push_back(position);
  ++summary_[axis].setpoints;
}

void LimitChecker::add_actual(int axis, int64_t cycle, double position, double velocity, double acceleration,
                              double following_error) {
  AxisSummary& s = summary_[axis];
  ++s.states;
  if (!std::isfinite(position)) record(actual_violations_, position, 0, cycle, s.axis, "actual position (not finite)");
  check(actual_violations_, s.act_v, velocity, s.v_err_limit, cycle, s.axis,
        "actual velocity (P-AXIS-00440 limit)", 0);
  const AxisConfig& a = machine_.axes[axis];
  check_software_limits(actual_violations_, a, position, a.swe_toleranz, cycle,
                        "actual position (P-AXIS-00178 swe_pos + P-AXIS-00179)",
                        "actual position (P-AXIS-00177 swe_neg - P-AXIS-00179)");
  check(actual_violations_, s.act_a, acceleration, s.a_err_limit, cycle, s.axis,
        "actual acceleration (P-AXIS-00442 limit)", 0);
  check(actual_violations_, s.following_error, following_error, s.slep_max, cycle, s.axis,
        "following error", 0);
}

CheckReport LimitChecker::finish() const {
  CheckReport report;
  report.violations = actual_violations_;
  const double dt = machine_.cycle_time_s();
  // Cycles whose path velocity differs from the cycle before's (or that
  // cycle is unknown: then no constant velocity is shown).
  std::unordered_set<int64_t> feed_changes;
  for (const auto& [cycle, v] : path_velocity_) {
    const auto before = path_velocity_.find(cycle_before(cycle, 1));
    if (before == path_velocity_.end() || !(std::abs(v - before->second) <= 1e-9 * (1 + std::abs(v))))
      feed_changes.insert(cycle);
  }
  for (size_t i = 0; i < setpoints_.size(); ++i) {
    const Trace& t = setpoints_[i];
    AxisSummary& s = summary_[i];
    // The n-th difference of positions rounded to `ulp` can be off by
    // 2^n ulp / dt^n: allow for that noise, no more.
    double scale = 1.0;
    for (double p : t.position)
      if (std::isfinite(p)) scale = std::max(scale, std::abs(p));
    const double ulp = scale * std::numeric_limits<double>::epsilon();
    const double noise[] = {0, 2 * ulp / dt, 4 * ulp / (dt * dt), 8 * ulp / (dt * dt * dt)};
    // Differences only across consecutive cycles; a gap restarts them.
    double v1 = 0, a1 = 0;
    int run = 0;  // consecutive samples so far
    // A difference belongs to the lift if a cycle it spans showed
    // lift_active: the k-th difference at cycle c mixes the motion of
    // cycles c-k .. c (`spans`; asked the same of the path velocity's changes).
    auto spans = [](const std::unordered_set<int64_t>& cycles, int64_t cycle, int back) {
      if (cycles.empty()) return false;
      for (int b = 0; b <= back; ++b)
        if (cycles.count(cycle_before(cycle, b))) return true;
      return false;
    };
    const std::unordered_set<int64_t>& lift = lift_active_[i];
    // Lifting's acceleration goes beyond a_max only through the path's own
    // (z'' = z_qq v^2 + z_q a_path): one cycle more, for the HLI's velocity
    // of a cycle and the setpoint's.
    auto overload_allowed = [&](int64_t cycle) {
      return machine_.lift_method == LiftMethod::time_based || spans(feed_changes, cycle, 3);
    };
    const AxisConfig& axis = machine_.axes[i];
    for (size_t k = 0; k < t.position.size(); ++k) {
      if (!std::isfinite(t.position[k])) {
        record(report.violations, t.position[k], 0, t.cycle[k], s.axis, "commanded position (not finite)");
        run = 0;
        continue;
      }
      if (run == 0 || k == 0 || cycle_before(t.cycle[k], 1) != t.cycle[k - 1] || t.cycle[k - 1] == INT64_MAX) {
        run = 1;
        continue;
      }
      ++run;
      check_software_limits(report.violations, machine_.axes[i], t.position[k], 0, t.cycle[k],
                            "commanded position (P-AXIS-00178 swe_pos)", "commanded position (P-AXIS-00177 swe_neg)");
      const double v = (t.position[k] - t.position[k - 1]) / dt;
      check(report.violations, s.cmd_v, v, s.v_max, t.cycle[k], s.axis, "commanded velocity", noise[1]);
      if (run >= 3) {
        const double a = (v - v1) / dt;
        if (!spans(lift, t.cycle[k], 2))
          check(report.violations, s.cmd_a, a, s.a_max, t.cycle[k], s.axis, "commanded acceleration", noise[2]);
        else if (overload_allowed(t.cycle[k]))
          check(report.violations, s.cmd_a_lift, a, axis.accel_error_limit(), t.cycle[k], s.axis,
                "commanded acceleration (lift overload range, P-AXIS-00442)", noise[2]);
        else
          check(report.violations, s.cmd_a_lift, a, s.a_max, t.cycle[k], s.axis,
                "commanded acceleration (Lifting at constant path velocity, a_max)", noise[2]);
        if (run >= 4) {
          const double j = (a - a1) / dt;
          if (spans(lift, t.cycle[k], 3))
            check(report.violations, s.cmd_j_lift, j, s.j_max, t.cycle[k], s.axis, "commanded jerk (lift, j_max)",
                  noise[3]);
          else
            check(report.violations, s.cmd_j, j, s.j_max, t.cycle[k], s.axis, "commanded jerk", noise[3]);
        }
        a1 = a;
      }
      v1 = v;
    }
  }
  std::stable_sort(report.violations.begin(), report.violations.end(),
                   [](const Violation& a, const Violation& b) { return a.time_s < b.time_s; });
  report.axes = summary_;
  return report;
}

}  // namespace hil::logger
