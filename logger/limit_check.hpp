#pragma once
// Offline check of one run against every axis' limits (RIG-4). Commanded
// velocity, acceleration and jerk are taken from differences of the
// commanded positions: the k-th difference of a sampled motion is a
// weighted mean of its k-th derivative, so it never exceeds the true
// maximum, and the check does not trust what the CNC says of itself.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "hli.hpp"
#include "machine_config.hpp"

namespace hil::logger {

// One episode: consecutive cycles in which one quantity of one axis is
// beyond its limit, so a long overload is one line, not hundreds.
struct Violation {
  double time_s = 0;       // first cycle of the episode
  double end_time_s = 0;   // last cycle of the episode
  int64_t cycles = 0;
  std::string axis;
  std::string quantity;    // e.g. "commanded acceleration"
  double value = 0;        // the worst (largest |value|) of the episode
  double worst_time_s = 0;
  double limit = 0;
};

struct AxisSummary {
  std::string axis;
  double cmd_v = 0, cmd_a = 0, cmd_j = 0;  // max |.| of the commanded motion (a, j: outside the lift's range)
  double act_v = 0, act_a = 0;             // max |.| of the actual motion
  double following_error = 0;              // max |.|
  double v_max = 0, a_max = 0, j_max = 0, a_err_limit = 0, v_err_limit = 0, slep_max = 0;
  int64_t setpoints = 0, states = 0;       // samples seen
  // The lift (LIFT-2, LIFT-3): max |commanded a| and |j| of the
  // differences that span a cycle with lift_active (a within the overload
  // range a_err_limit where the text allows it, j within j_max always),
  // and how many cycles the HLI showed lift_active.
  double cmd_a_lift = 0, cmd_j_lift = 0;
  int64_t lift_cycles = 0;
};

struct CheckReport {
  std::vector<AxisSummary> axes;
  std::vector<Violation> violations;
  bool passed() const { return violations.empty(); }
};

class LimitChecker {
 public:
  explicit LimitChecker(const MachineConfig& machine);

  // Samples of one axis in cycle order.
  void add_setpoint(int axis, int64_t cycle, double position);
  void add_actual(int axis, int64_t cycle, double position, double velocity, double acceleration,
                  double following_error);
  // The HLI state of a cycle (LIFT-7), in cycle order: where an axis shows
  // lift_active, its commanded acceleration may reach P-AXIS-00442's limit
  // (the overload range) where TF5200_lift_function.txt allows it —
  // Advanced Lifting throughout (P-AXIS-00442 "is used to plan lift
  // acceleration"), Lifting only while the path velocity changes ("if the
  // path feed rate is changed during the lifting motion"; at constant path
  // velocity a_max). Velocity and jerk stay within v_max and j_max ("the Z
  // axis moves with jerk limiting"). Axes by name.
  void add_lift_active(int axis, int64_t cycle);
  void add_path_velocity(int64_t cycle, double path_velocity);
  void add_hli_state(const HliState& state);
  CheckReport finish() const;

 private:
  struct Trace {
    std::vector<int64_t> cycle;
    std::vector<double> position;
  };
  void check(std::vector<Violation>& out, double& max_seen, double value, double limit, int64_t cycle,
             const std::string& axis, const char* quantity, double noise) const;
  // P-AXIS-00177 / 00178, widened by `tolerance`.
  void check_software_limits(std::vector<Violation>& out, const AxisConfig& axis, double position, double tolerance,
                             int64_t cycle, const char* quantity_pos, const char* quantity_neg) const;
  // Starts or extends the episode of `quantity` of `axis`.
  void record(std::vector<Violation>& out, double value, double limit, int64_t cycle, const std::string& axis,
              const char* quantity) const;

  MachineConfig machine_;
  std::vector<Trace> setpoints_;
  std::vector<std::unordered_set<int64_t>> lift_active_;  // per axis: the cycles with lift_active
  std::unordered_map<int64_t, double> path_velocity_;  // per cycle, mm/s (Lifting only)
  mutable std::vector<AxisSummary> summary_;
  std::vector<Violation> actual_violations_;
};

// Relative slack for round-off in the limit comparisons.
constexpr double limit_tolerance = 1e-6;

}  // namespace hil::logger
