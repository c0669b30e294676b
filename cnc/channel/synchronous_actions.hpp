#pragma once
// Synchronous actions of a block (MVS_SVS): its technology functions (M, H,
// S, T; KRN-8), output to the PLC one after the other in the block's order
// and each acknowledged by it, its D (the tool offset, shown at once), and
// its #TIME / G04 dwell, all before the block's motion; the path holds
// until none is left.
// Reads: m_function_ack, h_function_ack, s_function_ack, t_function_ack (a
// rising edge of command_w while enable_w).
// Writes: <m|h|s|t>_function_request_r and their numbers / values,
// m_function_add_nr_r, tool_offset_nr_r.
#include <cstdint>
#include <deque>

#include "block.hpp"
#include "hli.hpp"
#include "rising_edge.hpp"

namespace hil::cnc {

class SynchronousActions {
 public:
  // The block's technology functions and dwell, in order; true if it has any.
  bool queue(const Block& block);
  // An M function with its additional value (an insert stop mark, ISC-5).
  void queue_m_function(int nr, int32_t add_nr) { actions_.push_back({'M', nr, 0, 0, add_nr}); }
  // Outputs the next function, takes the PLC's acknowledgement, counts
  // down a dwell (t: s after program start); true when the last one is done.
  bool run(const HliControl& control, double t, HliState& hli);
  bool waiting() const { return !actions_.empty(); }
  bool waiting_for_acknowledgement() const { return waiting() && actions_.front().address != dwell; }
  bool in_dwell() const { return waiting() && actions_.front().address == dwell; }
  // How many actions are done since the channel was made (a reset counts
  // those it drops), and how many were queued: what comes after the n-th
  // in program order waits until done() reaches n (DPS-2).
  uint64_t done() const { return done_; }
  uint64_t queued() const { return done_ + actions_.size(); }
  // A reset: nothing left to output or wait for; the acknowledgements' edges stay.
  void abort() {
    done_ += actions_.size();
    actions_.clear();
    dwell_end_ = -1;
  }

 private:
  static constexpr char dwell = 0;
  // A technology function (address M H S T D) or a dwell (address 0).
  struct Action {
    char address = dwell;
    int nr = 0;
    double value = 0;    // S: rpm
    double dwell_s = 0;
    int32_t add_nr = 0;
  };
  // Shows the function `action` on the HLI, requesting its acknowledgement.
  static void output(const Action& action, HliState& hli);
  static bool& request(char address, HliState& hli);
  std::deque<Action> actions_;
  uint64_t done_ = 0;
  double dwell_end_ = -1;  // s after program start, while the front action is a dwell
  RisingEdge m_ack_, h_ack_, s_ack_, t_ack_;
};

}  // namespace hil::cnc
