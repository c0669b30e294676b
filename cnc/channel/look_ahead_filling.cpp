// PathInterpolator, what enters the look-ahead (KRN-3, KRN-5, KRN-6,
// ISC-3): the blocks the way the path travels, a split where a stop mark
// lies, the rest of a block or of a contouring curve after a turn or a
// restart, the stop at the end of what there is.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "motion_parts.hpp"
#include "path_interpolator.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

// Numbers the planner can work with: a finite length and finite limits.
bool finite(const PathSegment& segment) {
  const Limits& lim = segment.limits();
  return std::isfinite(segment.length()) && std::isfinite(lim.v) && std::isfinite(lim.a) && !std::isnan(lim.j) &&
         std::isfinite(segment.covered_distance());
}

}  // namespace

void PathInterpolator::refill() {
  if (program_.backward()) refill_backward();
  else refill_forward();
  if (program_.exhausted()) place_stop_at_end();
}

MotionPiece PathInterpolator::whole_block(size_t k, const PathSegment& segment) const {
  MotionPiece piece = MotionPiece::of_block(program_[k], k, segment);
  if (program_.backward()) {
    piece.motion = reversed(piece.motion);
    piece.origin = piece.covered;
  }
  piece.out = program_.corner_out(k);
  if (program_.backward()) piece.out->hsc.on = false;  // KRN-9: backward along the programmed blocks
  return piece;
}

MotionPiece PathInterpolator::rest_of_block(size_t k, const Motion& rest) const {
  MotionPiece piece;
  piece.block = k;
  piece.motion = rest;
  piece.covered = PathSegment(rest, machine_).covered_distance();
  const double end = program_.backward() ? 0.0 : PathSegment(program_[k].motion, machine_).covered_distance();
  piece.origin = end - direction_sign() * piece.covered;
  piece.slope = program_[k].slope;
  piece.out = program_.corner_out(k);
  return piece;
}

void PathInterpolator::push(MotionPiece m, bool stop_before) {
  m.block_stop = stop_before;
  if (pushed_.empty()) pushed_covered_ = covered_before_front_;
  if (!stop_.unplaced()) {  // no stop to place: the geometry is hand_over()'s
    hand_over(std::move(m), stop_before);
    return;
  }
  const PathSegment segment = m.segment(machine_);
  const double length = segment.length();
  if (std::isfinite(length)) {
    const double s = m.length_at(*stop_.unplaced() - pushed_covered_, segment);
    if (s <= tolerance::shortest_part_mm) {  // at its start
      look_ahead_.flush();
      place_stop(segment.position(0));
      stop_before = true;
    } else if (s < length - tolerance::shortest_part_mm) {
      // ISC-3: the block is split where the stop lies; the look-ahead brakes
      // to v = 0 at the split as before an M function, and the path enters
      // the second part from standstill.
      auto [first, second] = m.split_at(s, segment, direction_sign());
      const AxisValues point = first.motion.end;
      hand_over(std::move(first), stop_before);
      place_stop(point);
      hand_over(std::move(second), true);
      return;
    } else if (s <= length + tolerance::shortest_part_mm) {  // at its end
      // It ends as programmed (a corner there is not contoured): the path
      // stands on the mark.
      if (m.out) m.out = Corner{};
      const AxisValues end = m.motion.end;
      hand_over(std::move(m), stop_before);
      place_stop(end);
      return;
    }
  }
  hand_over(std::move(m), stop_before);
}

void PathInterpolator::hand_over(MotionPiece m, bool stop_before) {
  pushed_covered_ += m.covered;
  look_ahead_.push(m, stop_before);
  pushed_.push_back(std::move(m));
}

// KRN-6: the path runs on along the curve it stands on, either way, with
// each half counting for its own block (DPS-1), and joins the programmed
// motion where the curve does, tangent and curvature continuous.
size_t PathInterpolator::push_along_curve(const StopPoint& stop, bool towards_end) {
  const ContourJoint& j = *stop.curve;
  const double x = stop.curve_s, length = j.curve->length();
  const size_t n = j.parts.size();
  for (size_t step = 0; step < n; ++step) {
    const size_t i = towards_end ? step : n - 1 - step;
    const double from = j.begin(i), to = j.parts[i].end;
    if (towards_end && to > x) push_curve_span(j.parts[i].block, {stop.curve, std::max(x, from), to, false});
    if (!towards_end && from < x) push_curve_span(j.parts[i].block, {stop.curve, from, std::min(x, to), true});
  }
  const ContourJoint::Part& last = towards_end ? j.parts.back() : j.parts.front();
  const std::vector<double> joint_point = j.curve->position(towards_end ? length : 0.0);
  if (const auto rest = rest_of_motion(program_[last.block].motion, joint_point, program_.backward(), machine_))
    push(rest_of_block(last.block, *rest));
  return last.block;
}

void PathInterpolator::push_curve_span(size_t block, const CurveSpan& span) {
  if (std::optional<MotionPiece> piece = MotionPiece::on_curve(program_[block], block, span, machine_))
    push(std::move(*piece));
}

void PathInterpolator::place_stop(std::vector<double> position) {
  stop_.place(travelled_before_front_ + look_ahead_.path_length(), std::move(position), pushed_covered_);
  replan_ = true;
}

void PathInterpolator::place_stop_at_end() {
  if (!stop_.unplaced()) return;
  if (pushed_.empty()) {
    pushed_covered_ = covered_before_front_;
    place_stop(setpoint_positions());
  } else {
    place_stop(pushed_.back().motion.end);
  }
}

void PathInterpolator::restart_here(double t) {
  // The front motion and what follows it that refill() would not push the
  // same again: parts of blocks (split at a stop mark, a curve and a block's
  // rest after a turn on it: seed 1084 jumped 25 nm when those were left
  // out) and the whole blocks between them.
  size_t keep = 1;
  for (size_t i = 1; i < pushed_.size(); ++i)
    if (!pushed_[i].whole_block) keep = i + 1;
  const std::vector<MotionPiece> parts(pushed_.begin(), pushed_.begin() + static_cast<std::ptrdiff_t>(keep));
  const MotionPiece& front = parts.front();
  const size_t k = front.block;
  const StopPoint stop = leave_front(t);
  const double left = front.covered - direction_sign() * (stop.programmed_place - front.origin);
  size_t next = 1, last = k;  // the first of parts still to push; the block pushed last
  std::vector<MotionPiece> again;  // pushed anew, in order
  if (stop.curve) {
    // The rest of the curve and of the block at its end: what parts have of
    // them is pushed anew.
    last = push_along_curve(stop, !stop.curve_reversed);
    for (size_t i = 1; i < parts.size(); ++i)
      if (parts[i].block == last) next = i + 1;
    if (pushed_.empty()) {
      // Standing on the curve's end, where block `last` ends too (an HSC
      // span ends on its block's programmed end, KRN-9): it is finished, or
      // the cursors still named the block before it (fuzz hsc seed
      // 31002326: turned there, the path ran from the start of N40 straight
      // to the end of N50, 1.5e-3 mm of dist_prog_start short).
      observer_.finish_block(last);
      program_.finish(last);
    }
  } else if (const auto rest = rest_of_motion(front.motion, stop.position, false, machine_, left < front.covered / 2)) {
    // What is left of the front, from where the path stands: also a rest
    // too short for its own geometry (a straight line: a 4.6 nm rest
    // dropped made the path jump, fuzz seed 228); on a full circle by what
    // it has covered.
    MotionPiece r = front;
    r.motion = *rest;
    r.origin = stop.programmed_place;
    r.covered = std::max(left, 0.0);
    r.whole_block = false;
    r.block_stop = false;
    again.push_back(std::move(r));
  } else if (parts.size() == 1 || parts[1].block != k) {
    // Nothing is left of block k: it is finished, as finish_front() would
    // have it (the cursors say where the path stands, KRN-5).
    observer_.finish_block(k);
    program_.finish(k);
  }
  for (size_t i = next; i < parts.size(); ++i) {
    // The mark a part was split at is no longer in force (one stop is, and
    // push() splits at it anew): the parts are one motion again. Kept
    // apart, every insert stop added a split for good; stops commanded
    // every few cycles grew the look-ahead to ~1,100 pieces (fuzz seed
    // 12010265 never ended).
    if (!again.empty() && again.back().continued_by(parts[i])) {
      MotionPiece& joined = again.back();
      joined.motion.end = parts[i].motion.end;
      joined.covered += parts[i].covered;
      joined.out = parts[i].out;
    } else {
      again.push_back(parts[i]);
    }
    last = parts[i].block;
  }
  for (MotionPiece& m : again) {
    const bool stop_before = m.block_stop;
    push(std::move(m), stop_before);
  }
  program_.go_on_after(last);
  refill();
}

// Within the cycle's budget, and always while the piece the path runs on
// has none after it (a contoured block waits for the next one, a spline for
// its fit window): alone, it is planned at the jerk share a curvature step
// after it would give it (LookAhead::push_piece), and the next piece gives
// it its own back (fuzz AD, hsc seeds 32 and 40000192, and AJ: halved only
// once the next piece came, the share took away jerk a braking used).
bool PathInterpolator::may_fill() const {
  return !look_ahead_.full() && (fill_budget_ > 0 || look_ahead_.size() < 2);
}

void PathInterpolator::filled_one() {
  if (fill_budget_ > 0) --fill_budget_;
}

void PathInterpolator::top_up() {
  if (look_ahead_.empty() || !may_fill()) return;
  const size_t budget = fill_budget_;
  refill();
  grown_ = fill_budget_ != budget;
}

void PathInterpolator::refill_forward() {
  while (may_fill()) {
    const std::optional<size_t> next = program_.next_motion_block();
    if (!next) break;
    const PathSegment segment(program_[*next].motion, machine_);
    if (!finite(segment)) {
      program_.set_invalid(*next);
      look_ahead_.flush();
      return;
    }
    push(whole_block(*next, segment), program_.stops_before(*next));
    program_.go_on_after(*next);
    filled_one();
  }
  if (program_.at_read_end()) look_ahead_.flush();
}

void PathInterpolator::refill_backward() {
  while (may_fill()) {
    const std::optional<size_t> next = program_.next_motion_block();
    if (!next) break;
    program_.go_on_after(*next);
    push(whole_block(*next, PathSegment(program_[*next].motion, machine_)));
    filled_one();
  }
  if (program_.exhausted()) look_ahead_.flush();
}

}  // namespace hil::cnc
