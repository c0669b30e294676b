#pragma once
// One drive on the bus (RIG-1, RIG-3): integrates one cycle per setpoint,
// in order, and answers with the actual state and its monitoring; bridges
// the cycles of setpoints lost on the way (RIG-8).
#include <hil/axis_setpoint_t.hpp>

#include <cstdint>
#include <string>

#include "drive_model.hpp"
#include "drive_monitor.hpp"
#include "inbox.hpp"
#include "machine_config.hpp"

namespace hil::axis {

class AxisSimNode {
 public:
  AxisSimNode(const AxisConfig& axis, double cycle_time_s, lcm_support::Inbox& inbox);

  const std::string& name() const { return source_; }
  int64_t last_cycle() const { return last_cycle_; }

 private:
  void on_setpoint(const hil::axis_setpoint_t& m);
  void bridge_gap(int64_t cycle);
  void step(const hil::axis_setpoint_t& m, bool answer);

  AxisConfig axis_;
  lcm_support::Bus& bus_;
  int64_t run_id_;
  double cycle_time_s_;
  int64_t cycle_us_;
  DriveModel drive_;
  DriveMonitor monitor_;
  std::string source_;
  int64_t last_cycle_ = -1;
  hil::axis_setpoint_t last_setpoint_{};
};

}  // namespace hil::axis
