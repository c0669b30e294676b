#include "path_hold.hpp"

#include "hli.hpp"

namespace hil::cnc {

double PathHold::velocity_factor(int32_t override_value) const {
  return holds() ? 0.0 : override_value / static_cast<double>(override_full);
}

int32_t PathHold::stop_conditions() const {
  int32_t bits = 0;
  if (holds(HoldReason::feedhold)) bits |= stop_condition::feedhold;
  if (holds(HoldReason::channel_error)) bits |= stop_condition::channel_error;
  if (holds(HoldReason::m_function_ack)) bits |= stop_condition::plc_acknowledge | stop_condition::wait_techno_ack;
  if (holds(HoldReason::dwell)) bits |= stop_condition::delay_time;
  if (holds(HoldReason::lift_positioning)) bits |= stop_condition::wait_for_axes;
  return bits;
}

}  // namespace hil::cnc
