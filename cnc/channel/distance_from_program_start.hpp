#pragma once
// Distance from program start (DPS-1, DPS-2): the path length covered since
// program start or the last #DISTANCE PROG START CLEAR, counted while
// #DISTANCE PROG START ON (the default at program start), backward travel
// counting off (KRN-5). Writes the HLI's dist_prog_start (0.1 um); reads
// nothing from the PLC. Insert stop's DISTANCE mode and block search by
// distance read it.
#include <cstdint>
#include <deque>
#include <utility>

#include "block.hpp"

namespace hil::cnc {

class DistanceFromProgramStart {
 public:
  // #DISTANCE PROG START ON / OFF / CLEAR, when the interpolator reaches it,
  // in the program's order: after the synchronous actions of the blocks
  // before it (a #TIME dwell, an M function's acknowledgement): `after`
  // actions queued so far, of which `done` are done (fuzz seed 15009636:
  // a CLEAR after a dwell showed 0 through the dwell).
  void command(DistanceProgStart command, uint64_t after, uint64_t done);
  // So many synchronous actions are done: the commands that waited for them act.
  void actions_done(uint64_t done);
  // A block search's continuation (DPS-3): the distance there, and whether
  // #DISTANCE PROG START ON was in force.
  void preset(double distance_mm, bool counting) {
    before_front_ = distance_mm;
    counting_ = counting;
  }
  // The path left a block or part of it (signed by the direction).
  void count(double covered_distance) {
    if (counting_) before_front_ += covered_distance;
  }
  // mm, with `front_covered` of the block in the interpolator so far.
  double value_mm(double front_covered) const { return before_front_ + (counting_ ? front_covered : 0.0); }

 private:
  void apply(DistanceProgStart command);

  // Commands reached while synchronous actions before them still ran: the
  // count of actions each waits for, in program order.
  std::deque<std::pair<uint64_t, DistanceProgStart>> waiting_;
  bool counting_ = true;      // #DISTANCE PROG START ON
  double before_front_ = 0;   // mm counted before the front block
};

}  // namespace hil::cnc
