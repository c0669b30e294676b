#include "motion_piece.hpp"

#include <cmath>

#include "motion_parts.hpp"
#include "tolerances.hpp"

namespace hil::cnc {

MotionPiece MotionPiece::of_block(const Block& block, size_t index, const PathSegment& segment) {
  MotionPiece piece;
  piece.block = index;
  piece.motion = block.motion;
  piece.covered = segment.covered_distance();
  piece.slope = block.slope;
  piece.out = corner_after(block);
  piece.whole_block = true;
  return piece;
}

std::optional<MotionPiece> MotionPiece::on_curve(const Block& block, size_t index, const CurveSpan& span,
                                                 const MachineConfig& machine) {
  if (!(span.length() > 0)) return std::nullopt;
  const PathSegment on(span.joint, span.from, span.to, span.reversed, machine);
  // A span the path stands on however short is moved, as its chord (fuzz
  // AH: a turn 0.58e-9 mm into an HSC span, dropped below the 1e-9 mm this
  // was, jumped to the span's start).
  if (same_point(on.position(0), on.end())) return std::nullopt;
  MotionPiece piece;
  piece.block = index;
  piece.slope = block.slope;
  piece.curve = span;
  piece.motion = block.motion;  // the chord: within PATH_DEV of the curve
  if (piece.motion.type != MotionType::rapid) piece.motion.type = MotionType::linear;
  piece.motion.start = on.position(0);
  piece.motion.end = on.end();
  piece.covered = on.covered_distance();
  // Too short to tell apart from the curve (10 nm): a straight line, so
  // that the path goes on from where it stands.
  piece.along_chord = !(span.length() > tolerance::shortest_part_mm);
  return piece;
}

PathSegment MotionPiece::segment(const MachineConfig& machine) const {
  PathSegment s = curve && !along_chord ? PathSegment(curve->joint, curve->from, curve->to, curve->reversed, machine)
                                        : PathSegment(motion, machine);
  s.set_covered_distance(covered);
  return s;
}

std::pair<MotionPiece, MotionPiece> MotionPiece::split_at(double s, const PathSegment& segment,
                                                          double direction_sign) const {
  const double share = s / segment.length();
  const std::vector<double> point = segment.position(s);
  MotionPiece first = *this, second = *this;
  first.whole_block = second.whole_block = false;
  second.block_stop = false;
  first.covered = covered * s / segment.length();
  second.covered = covered - first.covered;
  second.origin = origin + direction_sign * first.covered;
  if (out) first.out = Corner{};
  first.motion = motion_until(motion, point);
  second.motion = motion_from(motion, point);
  if (curve && !along_chord) {
    const double at = curve->at(share);
    (curve->reversed ? first.curve->from : first.curve->to) = at;
    (curve->reversed ? second.curve->to : second.curve->from) = at;
    // The halves cover what the curve's halves say of them (ContourJoint::covered).
    first.covered = curve->joint->covered(first.curve->from, first.curve->to);
    second.covered = curve->joint->covered(second.curve->from, second.curve->to);
  }
  return {std::move(first), std::move(second)};
}

bool MotionPiece::continued_by(const MotionPiece& next) const {
  if (block != next.block || curve || next.curve || next.block_stop || motion.type != next.motion.type) return false;
  for (size_t i = 0; i < motion.end.size(); ++i)
    if (std::abs(motion.end[i] - next.motion.start[i]) > tolerance::same_point_share * (1 + std::abs(next.motion.start[i])))
      return false;
  return true;
}

}  // namespace hil::cnc
