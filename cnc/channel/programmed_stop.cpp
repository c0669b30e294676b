#include "programmed_stop.hpp"

namespace hil::cnc {

bool ProgrammedStop::apply(const HliControl& control, HliState& hli) {
  m01_enabled_ = control.m01_stop_enable.command_w && control.m01_stop_enable.enable_w;
  hli.m01_stop_enable.state_r = m01_enabled_;
  hli.m01_stop_enable.request_r = m01_enabled_;
  const bool edge = continue_(control.continue_motion.command_w) && control.continue_motion.enable_w;
  hli.continue_motion.request_r = control.continue_motion.command_w && control.continue_motion.enable_w;
  hli.continue_motion.state_r = edge && stopped();
  if (!edge || !stopped()) return false;
  stopped_m_ = -1;
  return true;
}

bool ProgrammedStop::begin(int m) {
  if (m == 1 && !m01_enabled_) return false;
  stopped_m_ = m;
  return true;
}

int32_t ProgrammedStop::stop_conditions() const {
  if (!stopped()) return 0;
  return stop_condition::m00_or_m01 | (stopped_m_ == 0 ? stop_condition::m0_stop : stop_condition::m1_stop);
}

}  // namespace hil::cnc
