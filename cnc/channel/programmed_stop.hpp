#pragma once
// Programmed stop M00 and optional stop M01 (ISC-5): the channel stands in
// the stop state until the PLC's "continue motion"; M01 stops only while
// m01_stop_enable is set. An insert stop mark with M00 / M01 uses the same
// stop (insert_stop.hpp).
// Reads: continue_motion (rising edge of command_w while enable_w),
// m01_stop_enable (command_w while enable_w).
// Writes: continue_motion.state_r, m01_stop_enable.state_r.
#include <cstdint>

#include "hli.hpp"
#include "rising_edge.hpp"

namespace hil::cnc {

class ProgrammedStop {
 public:
  // Takes the PLC's units; true if continue motion left a stop this cycle.
  bool apply(const HliControl& control, HliState& hli);
  // The path stands at M00 (m = 0) or M01 (m = 1); true if the channel
  // stops (M01 only while enabled).
  bool begin(int m);
  bool stopped() const { return stopped_m_ >= 0; }
  void abort() { stopped_m_ = -1; }  // a reset; the PLC's levels and edge stay
  // HLI_SC_M00_OR_M01 with HLI_SC_M0_STOP or HLI_SC_M1_STOP while stopped.
  int32_t stop_conditions() const;

 private:
  int stopped_m_ = -1;
  bool m01_enabled_ = false;
  RisingEdge continue_;
};

}  // namespace hil::cnc
