#pragma once
// Why the path holds (velocity factor 0), as one set: each function of the
// channel contributes its reason, and the set yields both the velocity
// factor for the look-ahead and the HLI_SC_* bits of stop_conditions_r
// (TF5200_insert_stop_cmd.txt, table of stop conditions).
#include <bitset>
#include <cstdint>

namespace hil::cnc {

enum class HoldReason : uint8_t {
  feedhold,           // feed hold in force (HLI_SC_FEEDHOLD)
  short_cut_pending,  // delete distance to go: stopping for the short cut (DDTG-1)
  channel_error,      // error stop (HLI_SC_CHANNEL_ERROR)
  m_function_ack,     // an M function waits for the PLC's acknowledgement, MVS_SVS (HLI_SC_PLC_ACKNOWLEDGE, HLI_SC_WAIT_TECHNO_ACK)
  dwell,              // #TIME (HLI_SC_DELAY_TIME)
  direction_change,   // backward motion requested the other way (KRN-5)
  insert_command,     // an insert stop command stops the path briefly (ISC-6)
  programmed_stop,    // M00 / M01 stop state, also of an insert stop mark (ISC-5; bits from ProgrammedStop)
  lift_positioning,   // the lift axis positions while the path waits (LIFT-2; HLI_SC_WAIT_FOR_AXES)
  count
};

class PathHold {
 public:
  void set(HoldReason reason, bool holds) { reasons_.set(static_cast<size_t>(reason), holds); }
  bool holds(HoldReason reason) const { return reasons_.test(static_cast<size_t>(reason)); }
  bool holds() const { return reasons_.any(); }
  // The override (0.1 %) scales the programmed velocities unless a reason holds the path.
  double velocity_factor(int32_t override_value) const;
  // The HLI_SC_* bits of the reasons that have one.
  int32_t stop_conditions() const;

 private:
  std::bitset<static_cast<size_t>(HoldReason::count)> reasons_;
};

}  // namespace hil::cnc
