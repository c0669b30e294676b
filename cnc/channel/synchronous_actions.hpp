#pragma once
// Synchronous actions of a block (MVS_SVS): its M functions, output to the
// PLC one after the other and each acknowledged by it, and its #TIME dwell,
// all before the block's motion; the path holds until none is left.
// Reads: m_function_ack (a rising edge of command_w while enable_w).
// Writes: m_function_request_r, m_function_nr_r, m_function_add_nr_r.
#include <deque>

#include "block.hpp"
#include "hli.hpp"
#include "rising_edge.hpp"

namespace hil::cnc {

class SynchronousActions {
 public:
  // The block's M functions and dwell, in order; true if it has any.
  bool queue(const Block& block);
  // An M function with its additional value (an insert stop mark, ISC-5).
  void queue_m_function(int nr, int32_t add_nr) { actions_.push_back({nr, 0, add_nr}); }
  // Outputs the next M function, takes the PLC's acknowledgement, counts
  // down a dwell (t: s after program start); true when the last one is done.
  bool run(const ControlUnitBool& ack, double t, HliState& hli);
  bool waiting() const { return !actions_.empty(); }
  bool waiting_for_acknowledgement() const { return waiting() && actions_.front().m_function >= 0; }
  bool in_dwell() const { return waiting() && actions_.front().m_function < 0; }
  // A reset: nothing left to output or wait for; the acknowledgement's edge stays.
  void abort() {
    actions_.clear();
    dwell_end_ = -1;
  }

 private:
  // An M function's acknowledgement (m_function >= 0) or a dwell (dwell_s > 0).
  struct Action {
    int m_function = -1;
    double dwell_s = 0;
    int32_t add_nr = 0;
  };
  std::deque<Action> actions_;
  double dwell_end_ = -1;  // s after program start, while the front action is a dwell
  RisingEdge acknowledgement_;
};

}  // namespace hil::cnc
