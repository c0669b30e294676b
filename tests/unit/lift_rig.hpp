#pragma once
// A channel running a lift program cycle by cycle (LIFT-1 .. LIFT-8), with
// the PLC's answers, the lift axis' trace and the offline limit check fed
// from every cycle (lift_active: the lift's overload range, LIFT-2).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "channel.hpp"
#include "limit_check.hpp"
#include "test_machine.hpp"

namespace hil::test {

constexpr size_t X = 0, Z = 2;

struct LiftRig {
  explicit LiftRig(const std::string& program, MachineConfig machine)
      : machine_config(machine), channel(machine, program), checker(machine_config) {
    control.program_start.enable_w = true;
    control.m_function_ack.enable_w = true;
    control.feedhold.enable_w = true;
    control.override.enable_w = true;
    control.override.command_w = 1000;
    control.delete_distance_to_go.enable_w = true;
  }
  MachineConfig machine_config;
  cnc::Channel channel;
  logger::LimitChecker checker;
  HliControl control;
  int64_t k = 0;
  std::vector<double> z, x;
  std::vector<bool> lifting;
  double z_peak = -1e9, z_floor = 1e9;  // z_floor: while lifting

  const HliState& hli() const { return channel.hli(); }
  double axis(size_t i) const { return channel.setpoints()[i].position; }
  void step() {
    channel.step(k, control);
    checker.add_hli_state(hli());  // lift_active: the lift's overload range (LIFT-2)
    for (size_t i = 0; i < channel.setpoints().size(); ++i)
      checker.add_setpoint(static_cast<int>(i), k, channel.setpoints()[i].position);
    z.push_back(axis(Z));
    x.push_back(axis(X));
    lifting.push_back(hli().lift_active[Z]);
    z_peak = std::max(z_peak, axis(Z));
    if (hli().lift_active[Z]) z_floor = std::min(z_floor, axis(Z));
    ++k;
    control.program_start.command_w = false;
    control.m_function_ack.command_w = hli().m_function_request_r;  // acknowledge at once
    control.continue_motion.command_w = false;
    if (control.insert_cmd.semaphor_rw) control.insert_cmd.semaphor_rw = hli().insert_cmd.semaphor_rw;  // ISC-1
  }
  void start() {
    control.program_start.command_w = true;
    step();
  }
  bool done() const {
    return hli().channel_state == ChannelState::program_end || hli().channel_state == ChannelState::error;
  }
  void run_to_end(int64_t limit = 200000) {
    while (!done() && k < limit) step();
  }
  template <typename Condition>
  void run_until(Condition c, int64_t limit = 200000) {
    while (!c() && !done() && k < limit) step();
  }
  void require_within_limits() {
    const logger::CheckReport report = checker.finish();
    for (const logger::Violation& v : report.violations)
      UNSCOPED_INFO(v.axis << " " << v.quantity << " " << v.value << " > " << v.limit << " at " << v.time_s);
    REQUIRE(report.violations.empty());
  }
  double largest_z_acceleration() const {
    double a = 0;
    const double dt = machine_config.cycle_time_s();
    for (size_t i = 2; i < z.size(); ++i) a = std::max(a, std::abs(z[i] - 2 * z[i - 1] + z[i - 2]) / (dt * dt));
    return a;
  }
};

}  // namespace hil::test
