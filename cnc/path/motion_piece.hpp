#pragma once
// What the interpolator hands the look-ahead, as one value (KRN-3, KRN-5,
// KRN-6, ISC-3, DDTG-2): a whole block, a part of one split at a stop
// mark, the rest of a block or of a contouring curve after a turn or a
// restart, a short cut. It knows the block it came from, its geometry (a
// programmed motion's part, or a span of a contouring curve), what it adds
// to the distance from program start over its path length (DPS-1: in
// proportion), and how the path leaves it.
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "block.hpp"
#include "contour_curve.hpp"
#include "machine_config.hpp"
#include "path_segment.hpp"
#include "slope.hpp"

namespace hil::cnc {

// How the path is to leave a block into the next motion block.
struct Corner {
  BlockTransition transition = BlockTransition::standard;
  ContourMode mode;
  HscMode hsc;  // the block is smoothed by the HSC spline (KRN-9) where on
};

// How the path leaves `block` into the next motion block. The lift
// function's preparation has already turned the transitions it suppresses
// into standard ones (prepare_lift_ranges, LIFT-3).
inline Corner corner_after(const Block& block) { return {block.transition, block.contour, block.hsc}; }

// [from, to] of a contouring curve, run from `to` to `from` if reversed.
struct CurveSpan {
  std::shared_ptr<const ContourJoint> joint;
  double from = 0, to = 0;
  bool reversed = false;

  double length() const { return to - from; }
  // The curve position `share` of the way along the span, the way it runs.
  double at(double share) const { return reversed ? to - length() * share : from + length() * share; }
};

struct MotionPiece {
  size_t block = 0;
  Motion motion;       // in the travel direction; of a curve span its chord (path_ahead, ISC-4)
  double origin = 0;   // where it begins in the block's programmed distance (StopPoint::programmed_place)
  double covered = 0;  // what it adds to dist_prog_start (DPS-1)
  SlopeType slope = SlopeType::trapez;
  std::optional<Corner> out;  // how the path leaves it; none: taken as it is (DDTG-2, a curve span)
  std::optional<CurveSpan> curve;  // on a contouring curve (after a turn or a restart on it)
  // A curve span too short to tell apart from its chord (10 nm), moved
  // along that chord: a stop on it stands on the curve (leave_front).
  bool along_chord = false;
  bool whole_block = false;  // as refill() pushes it: refill() can push it again
  // The path stands before it for its block's sake (M functions, a dwell,
  // a lift positioning since the last motion block): restart_here() pushes
  // it again so (fuzz lift seed 2359: an M16 passed at 18 mm/s).
  bool block_stop = false;

  // The whole of `block` (at `index` of the program) as programmed, leaving
  // it as the block says (corner_after); `segment`: the block's own, made
  // by the caller (the interpolator checks it is finite first).
  static MotionPiece of_block(const Block& block, size_t index, const PathSegment& segment);
  // The span of a curve as a piece of `block`; none if it has no length
  // (1 nm).
  static std::optional<MotionPiece> on_curve(const Block& block, size_t index, const CurveSpan& span,
                                             const MachineConfig& machine);

  // Its geometry over path length, covering `covered`.
  PathSegment segment(const MachineConfig& machine) const;
  // The path length of `segment` (this piece's) at which it has covered `covered_part`.
  double length_at(double covered_part, const PathSegment& segment) const {
    return covered > 0 ? segment.length() * covered_part / covered : 0.0;
  }
  // ISC-3: the piece up to path length `s` of `segment` (this piece's) and
  // the piece after it. The first ends there as programmed (a corner is
  // not contoured), so that the path can stand there; the second is no
  // block stop (the stop at s is the caller's). `direction_sign`: of the
  // travel direction, for where the second begins in its block.
  std::pair<MotionPiece, MotionPiece> split_at(double s, const PathSegment& segment,
                                               double direction_sign) const;
  // `next` goes on where this one ends, in the same block: a split of the
  // same motion.
  bool continued_by(const MotionPiece& next) const;
};

}  // namespace hil::cnc
