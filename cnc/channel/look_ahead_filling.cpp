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
  if (direction_ == TravelDirection::backward) refill_backward();
  else refill_forward();
  const bool exhausted = direction_ == TravelDirection::backward
                             ? cursors_.next_backward <= cursors_.lowest_stored
                             : !blocks_.has(cursors_.next_to_look_ahead) || cursors_.next_to_look_ahead == invalid_block_;
  if (exhausted) place_stop_at_end();
}

PathInterpolator::PushedMotion PathInterpolator::whole_block(size_t k) const {
  const Block& block = blocks_[k];
  const double programmed = PathSegment(block.motion, machine_).covered_distance();
  if (direction_ == TravelDirection::backward)
    return {k, reversed(block.motion), programmed, programmed, block.slope, corner_out(k), std::nullopt, true};
  return {k, block.motion, 0.0, programmed, block.slope, corner_out(k), std::nullopt, true};
}

PathInterpolator::PushedMotion PathInterpolator::rest_of_block(size_t k, const Motion& rest) const {
  const double covered = PathSegment(rest, machine_).covered_distance();
  const double end = direction_ == TravelDirection::backward ? 0.0 : PathSegment(blocks_[k].motion, machine_).covered_distance();
  return {k, rest, end - direction_sign() * covered, covered, blocks_[k].slope, corner_out(k), std::nullopt, false};
}

Corner PathInterpolator::corner_out(size_t k) const {
  return direction_ == TravelDirection::backward ? corner_below(k) : corner_after(blocks_[k]);
}

void PathInterpolator::push(PushedMotion m, bool stop_before) {
  m.block_stop = stop_before;
  if (m.curve) {
    push_curve_part(m.block, *m.curve);
    return;
  }
  if (pushed_.empty()) pushed_covered_ = covered_before_front_;
  const PathSegment segment(m.motion, machine_);
  const double length = segment.length();
  if (stop_covered_ && std::isfinite(length)) {
    const double to_stop = *stop_covered_ - pushed_covered_;
    const double s = m.covered > 0 ? length * to_stop / m.covered : 0.0;
    // The part before the stop ends as programmed (a corner there is not
    // contoured): the path stands on the mark.
    const std::optional<Corner> ends_at_stop = m.out ? std::optional<Corner>(Corner{}) : std::nullopt;
    if (s <= tolerance::shortest_part_mm) {  // at its start
      look_ahead_.flush();
      place_stop(segment.position(0));
      stop_before = true;
    } else if (s < length - tolerance::shortest_part_mm) {
      // ISC-3: the block is split where the stop lies; the look-ahead brakes
      // to v = 0 at the split as before an M function, and the path enters
      // the second part from standstill.
      const std::vector<double> point = segment.position(s);
      const double covered_first = m.covered * s / length;
      PushedMotion first = m, second = m;
      first.whole_block = second.whole_block = false;
      first.motion = motion_until(m.motion, point);
      first.covered = covered_first;
      first.out = ends_at_stop;
      second.motion = motion_from(m.motion, point);
      second.origin = m.origin + direction_sign() * covered_first;
      second.block_stop = false;
      second.covered = m.covered - covered_first;
      hand_over(std::move(first), stop_before);
      place_stop(point);
      hand_over(std::move(second), true);
      return;
    } else if (s <= length + tolerance::shortest_part_mm) {  // at its end
      const AxisValues end = m.motion.end;
      m.out = ends_at_stop;
      hand_over(std::move(m), stop_before);
      place_stop(end);
      return;
    }
  }
  hand_over(std::move(m), stop_before);
}

void PathInterpolator::hand_over(PushedMotion m, bool stop_before) {
  pushed_covered_ += m.covered;
  if (m.out) {
    look_ahead_.push(m.block, m.motion, m.slope, stop_before, *m.out, m.covered);
  } else {
    PathSegment segment(m.motion, machine_);
    segment.set_covered_distance(m.covered);
    look_ahead_.push(m.block, std::move(segment), m.slope, stop_before);
  }
  pushed_.push_back(std::move(m));
}

// KRN-6: the path runs on along the curve it stands on, either way, with
// each half counting for its own block (DPS-1), and joins the programmed
// motion where the curve does, tangent and curvature continuous.
size_t PathInterpolator::push_along_curve(const StopPoint& stop, bool towards_end) {
  const ContourJoint& j = *stop.curve;
  const double x = stop.curve_s, split = j.split, length = j.curve->length();
  if (towards_end) {
    push_curve_part(j.before.block, {stop.curve, x, split, false});
    push_curve_part(j.after.block, {stop.curve, std::max(x, split), length, false});
  } else {
    push_curve_part(j.after.block, {stop.curve, split, x, true});
    push_curve_part(j.before.block, {stop.curve, 0, std::min(x, split), true});
  }
  const ContourJoint::Half& last = towards_end ? j.after : j.before;
  const std::vector<double> joint_point = j.curve->position(towards_end ? length : 0.0);
  const bool backward = direction_ == TravelDirection::backward;
  if (const auto rest = rest_of_motion(blocks_[last.block].motion, joint_point, backward, machine_))
    push(rest_of_block(last.block, *rest));
  return last.block;
}

void PathInterpolator::push_curve_part(size_t block, const CurvePart& part) {
  const ContourJoint& j = *part.joint;
  const double length = part.to - part.from;
  const Block& b = blocks_[block];
  // Where the path enters and leaves the part.
  const std::vector<double> first = j.curve->position(part.reversed ? part.to : part.from);
  const std::vector<double> last = j.curve->position(part.reversed ? part.from : part.to);
  Motion chord = b.motion;  // for path_ahead() (ISC-4), within PATH_DEV of the curve
  if (chord.type != MotionType::rapid) chord.type = MotionType::linear;
  chord.start = first;
  chord.end = last;
  const double covered = j.covered(part.from, part.to);
  if (!(length > tolerance::shortest_part_mm)) {
    // Too short to tell apart from the curve (10 nm): a straight line, so
    // that the path goes on from where it stands.
    if (length > tolerance::length_mm) {
      PushedMotion m{block, chord, 0.0, covered, b.slope, std::nullopt, std::nullopt, false};
      m.chord_of = part;
      push(std::move(m));
    }
    return;
  }
  if (pushed_.empty()) pushed_covered_ = covered_before_front_;
  const auto hand_over_part = [&](double from, double to, bool stop_before) {
    PathSegment piece(part.joint, from, to, part.reversed, machine_);
    Motion c = chord;
    c.start = piece.position(0);
    c.end = piece.end();
    pushed_covered_ += piece.covered_distance();
    pushed_.push_back({block, c, 0.0, piece.covered_distance(), b.slope, std::nullopt,
                       CurvePart{part.joint, from, to, part.reversed}, false});
    look_ahead_.push(block, std::move(piece), b.slope, stop_before);
  };
  const double to_stop = stop_covered_ ? *stop_covered_ - pushed_covered_ : covered;
  if (to_stop < covered - tolerance::shortest_part_mm) {
    if (to_stop <= tolerance::shortest_part_mm) {  // at its start
      look_ahead_.flush();
      place_stop(first);
      hand_over_part(part.from, part.to, true);
      return;
    }
    // ISC-3: split where the stop lies (a half covers in proportion).
    const double at = part.reversed ? part.to - length * to_stop / covered : part.from + length * to_stop / covered;
    hand_over_part(part.reversed ? at : part.from, part.reversed ? part.to : at, false);
    place_stop(j.curve->position(at));
    hand_over_part(part.reversed ? part.from : at, part.reversed ? at : part.to, true);
    return;
  }
  hand_over_part(part.from, part.to, false);
}

void PathInterpolator::place_stop(std::vector<double> position) {
  stop_at_ = travelled_before_front_ + look_ahead_.path_length();
  placed_stop_ = PlacedStop{std::move(position), pushed_covered_ - stop_covered_from_};
  stop_covered_.reset();
  replan_ = true;
}

void PathInterpolator::place_stop_at_end() {
  if (!stop_covered_) return;
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
  const std::vector<PushedMotion> parts(pushed_.begin(), pushed_.begin() + static_cast<std::ptrdiff_t>(keep));
  const PushedMotion& front = parts.front();
  const size_t k = front.block;
  const StopPoint stop = leave_front(t);
  const double left = front.covered - direction_sign() * (stop.programmed_place - front.origin);
  size_t next = 1, last = k;  // the first of parts still to push; the block pushed last
  std::vector<PushedMotion> again;  // pushed anew, in order
  // b goes on where a ends, in the same block: a split of it.
  const auto goes_on = [](const PushedMotion& a, const PushedMotion& b) {
    if (a.block != b.block || a.curve || b.curve || a.chord_of || b.chord_of || b.block_stop ||
        a.motion.type != b.motion.type)
      return false;
    for (size_t i = 0; i < a.motion.end.size(); ++i)
      if (std::abs(a.motion.end[i] - b.motion.start[i]) > tolerance::same_point_share * (1 + std::abs(b.motion.start[i])))
        return false;
    return true;
  };
  if (stop.curve) {
    // The rest of the curve and of the block at its end: what parts have of
    // them is pushed anew.
    last = push_along_curve(stop, !stop.curve_reversed);
    for (size_t i = 1; i < parts.size(); ++i)
      if (parts[i].block == last) next = i + 1;
  } else if (const auto rest = rest_of_motion(front.motion, stop.position, false, machine_, left < front.covered / 2)) {
    // What is left of the front, from where the path stands: also a rest
    // too short for its own geometry (a straight line: a 4.6 nm rest
    // dropped made the path jump, fuzz seed 228); on a full circle by what
    // it has covered.
    PushedMotion r = front;
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
    if (direction_ == TravelDirection::forward) cursors_.next_to_run = std::max(cursors_.next_to_run, k + 1);
    cursors_.last_finished = k;
  }
  for (size_t i = next; i < parts.size(); ++i) {
    // The mark a part was split at is no longer in force (one stop is, and
    // push() splits at it anew): the parts are one motion again. Kept
    // apart, every insert stop added a split for good; stops commanded
    // every few cycles grew the look-ahead to ~1,100 pieces (fuzz seed
    // 12010265 never ended).
    if (!again.empty() && goes_on(again.back(), parts[i])) {
      PushedMotion& joined = again.back();
      joined.motion.end = parts[i].motion.end;
      joined.covered += parts[i].covered;
      joined.out = parts[i].out;
    } else {
      again.push_back(parts[i]);
    }
    last = parts[i].block;
  }
  for (PushedMotion& m : again) {
    const bool stop_before = m.block_stop;
    push(std::move(m), stop_before);
  }
  if (direction_ == TravelDirection::backward) cursors_.next_backward = last;
  else cursors_.next_to_look_ahead = last + 1;
  refill();
}

void PathInterpolator::refill_forward() {
  size_t& next = cursors_.next_to_look_ahead;
  for (; !look_ahead_.full() && next != invalid_block_ && blocks_.has(next); ++next) {
    const Block& block = blocks_[next];
    if (!block.has_motion) continue;
    // M functions, a dwell or a channel initialisation on its line or since
    // the last motion block: the path stands still where it starts.
    bool stop_before = false;
    for (size_t i = next + 1; i-- > blocks_.first_kept();) {
      if (i < next && blocks_[i].has_motion) break;
      stop_before = stop_before || blocks_[i].stops_path();
    }
    if (next < cursors_.begun) stop_before = false;  // forward again after backward motion: ran already
    PathSegment segment(block.motion, machine_);
    if (!finite(segment)) {
      invalid_block_ = next;
      look_ahead_.flush();
      return;
    }
    push(whole_block(next), stop_before);
  }
  if (!blocks_.has(next)) look_ahead_.flush();
}

void PathInterpolator::refill_backward() {
  while (!look_ahead_.full() && cursors_.next_backward > cursors_.lowest_stored) {
    const size_t i = --cursors_.next_backward;
    if (!blocks_[i].has_motion) continue;
    push(whole_block(i));
  }
  if (cursors_.next_backward <= cursors_.lowest_stored) look_ahead_.flush();
}

// Backward (KRN-5, KRN-6): the path leaves block i into the motion block
// below it through the corner at that block's end, contoured as forward
// unless something between stops the path there.
Corner PathInterpolator::corner_below(size_t i) const {
  for (size_t k = i; k-- > cursors_.lowest_stored;) {
    if (blocks_[k + 1].stops_path()) return {};
    if (blocks_[k].has_motion) return corner_after(blocks_[k]);
  }
  return {};
}

}  // namespace hil::cnc
