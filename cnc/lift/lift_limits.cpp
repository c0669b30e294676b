#include "lift_limits.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "drive_response.hpp"

namespace hil::cnc {

Limits advanced_lifting_limits(const AxisConfig& axis, double cycle_time_s) {
  const axis::DriveParameters drive = axis::drive_parameters(axis, cycle_time_s);
  const double limit = axis.accel_error_limit();
  using Key = std::array<double, 11>;
  const Key key{drive.kv,          drive.velocity_lag_s,   drive.cycle_time_s,   double(drive.velocity_loop_order),
                drive.velocity_damping, drive.feedforward,  drive.acceleration_limit, drive.coulomb_friction,
                drive.viscous_friction, limit,              axis.j_max};
  thread_local std::vector<std::pair<Key, double>> known;
  auto it = std::find_if(known.begin(), known.end(), [&](const auto& k) { return k.first == key; });
  if (it == known.end()) {
    known.emplace_back(key, axis::largest_followed_acceleration(drive, limit, axis.j_max));
    it = known.end() - 1;
  }
  return {axis.v_max, it->second, axis.j_max};
}

void prepare_advanced_lifting_limits(const MachineConfig& machine) {
  if (machine.lift_method != LiftMethod::time_based) return;
  for (const AxisConfig& axis : machine.axes) advanced_lifting_limits(axis, machine.cycle_time_s());
}

Limits lifting_limits(const AxisConfig& axis, double factor) {
  return {axis.v_max, std::min(axis.a_max, factor * axis.a_max / 2), lifting_profile_jerk_share * axis.j_max};
}

}  // namespace hil::cnc
