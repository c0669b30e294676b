#pragma once
// Distance from program start (DPS-1, DPS-2): the path length covered since
// program start or the last #DISTANCE PROG START CLEAR, counted while
// #DISTANCE PROG START ON (the default at program start), backward travel
// counting off (KRN-5). Writes the HLI's dist_prog_start (0.1 um); reads
// nothing from the PLC. Insert stop's DISTANCE mode and block search by
// distance read it.
#include "block.hpp"

namespace hil::cnc {

class DistanceFromProgramStart {
 public:
  // #DISTANCE PROG START ON / OFF / CLEAR, when the interpolator reaches it.
  void apply(DistanceProgStart command);
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
  bool counting_ = true;      // #DISTANCE PROG START ON
  double before_front_ = 0;   // mm counted before the front block
};

}  // namespace hil::cnc
