#include "path_interpolator.hpp"

#include <algorithm>
#include <cmath>

#include "motion_parts.hpp"
#include "position_profile.hpp"
#include "velocity_profile.hpp"

namespace hil::cnc {
namespace {

// A part shorter than this is not split off or moved (10 nm): a shorter arc
// could not be told from a full circle.
constexpr double shortest_rest_mm = 1e-5;

// Numbers the planner can work with: a finite length and finite limits.
bool finite(const PathSegment& segment) {
  const Limits& lim = segment.limits();
  return std::isfinite(segment.length()) && std::isfinite(lim.v) && std::isfinite(lim.a) && !std::isnan(lim.j) &&
         std::isfinite(segment.covered_distance());
}

}  // namespace

PathInterpolator::PathInterpolator(const MachineConfig& machine, PathObserver& observer)
    : machine_(machine), observer_(observer), look_ahead_(machine), setpoints_(machine.axes.size()) {}

std::vector<double> PathInterpolator::setpoint_positions() const {
  std::vector<double> positions(setpoints_.size());
  for (size_t i = 0; i < positions.size(); ++i) positions[i] = setpoints_[i].position;
  return positions;
}

void PathInterpolator::set_velocity_factor(double factor) {
  look_ahead_.set_velocity_factor(factor);
  replan_ = true;
}

StopPoint PathInterpolator::leave_front(double t) {
  const LookAheadBlock& front = look_ahead_.front();
  StopPoint stop;
  stop.block = front.block_index;
  stop.front_length = front.segment.length();
  stop.s = std::clamp(path_state_at(t).p, 0.0, stop.front_length);
  stop.position = setpoint_positions();
  if (front.segment.is_contour_curve()) {
    stop.curve = front.segment.joint();
    stop.curve_s = front.segment.curve_position(stop.s);
    stop.curve_reversed = front.segment.reversed();
  }
  double covered = 0;
  if (stop.front_length > 0) {
    covered = front.segment.covered_distance() * stop.s / stop.front_length;
    observer_.travelled(direction_sign() * covered);
    covered_before_front_ += covered;
  }
  stop.programmed_place = pushed_.front().origin + direction_sign() * (front_done_ + covered);
  front_done_ = 0;
  travelled_before_front_ += stop.s;
  look_ahead_.clear();
  pushed_.clear();
  return stop;
}

bool PathInterpolator::push_short_cut(size_t target, const Motion& cut) {
  PathSegment segment(cut, machine_);
  if (!(segment.length() > 0)) return false;
  // Not smoothed, nor the transition after it (DDTG-2).
  push({target, cut, 0.0, segment.covered_distance(), blocks_[target].slope, std::nullopt});
  return true;
}

void PathInterpolator::go_on_from_standstill(double t) {
  refill();
  if (!look_ahead_.empty()) begin_front({}, t);
  replan_ = false;
}

bool PathInterpolator::turn(double t, size_t stored_blocks) {
  if (look_ahead_.empty()) {
    // Standing where the stored contour begins. (Forward with nothing left
    // to move, the program is about to end: it cannot turn there.)
    if (direction_ == TravelDirection::forward) return false;
    direction_ = TravelDirection::forward;
    // It stands in block k (at its start, or where a backward short cut
    // found nothing before it, DDTG-6): on along k from there.
    const size_t k = cursors_.last_finished;
    if (blocks_[k].has_motion)
      if (const auto rest = rest_of_motion(blocks_[k].motion, setpoint_positions(), false, machine_))
        push(rest_of_block(k, *rest));
    cursors_.next_to_look_ahead = k + 1;
    refill();
    return true;
  }
  const StopPoint stop = leave_front(t);
  const size_t k = stop.block;
  // Where on a full circle k (its start is its end) the path stands: a
  // part of block k runs from a lower place on it to a higher one forward,
  // the other way backward, whether it ends where k ends or at a split.
  const bool at_part_start = stop.s < stop.front_length / 2;
  const bool at_end_of_k = (direction_ == TravelDirection::forward) != at_part_start;
  direction_ = direction_ == TravelDirection::forward ? TravelDirection::backward : TravelDirection::forward;
  const bool backward = direction_ == TravelDirection::backward;
  if (backward) {
    size_t i = cursors_.begun, counted = 0;
    while (i > 0 && counted < stored_blocks)
      if (blocks_[--i].has_motion) ++counted;
    cursors_.lowest_stored = i;
  }
  // What is left of block k the new way: back to its start, or on to its end
  // (the front may be a part of block k, split at an insert stop mark). On a
  // contouring curve, back along it into the block it came from.
  size_t on = k;
  if (stop.curve) on = push_along_curve(stop, stop.curve_reversed);
  else if (const auto rest = rest_of_motion(blocks_[k].motion, stop.position, backward, machine_, at_end_of_k))
    push(rest_of_block(k, *rest));
  if (backward) cursors_.next_backward = on;
  else cursors_.next_to_look_ahead = on + 1;
  cursors_.last_finished = on;  // where the path stands if nothing follows: at block k's start
  refill();
  return true;
}

void PathInterpolator::refill() {
  if (direction_ == TravelDirection::backward) refill_backward();
  else refill_forward();
  const bool exhausted = direction_ == TravelDirection::backward
                             ? cursors_.next_backward <= cursors_.lowest_stored
                             : cursors_.next_to_look_ahead >= blocks_.size() || cursors_.next_to_look_ahead == invalid_block_;
  if (exhausted) place_stop_at_end();
}

PathInterpolator::PushedMotion PathInterpolator::whole_block(size_t k) const {
  const Block& block = blocks_[k];
  const double programmed = PathSegment(block.motion, machine_).covered_distance();
  if (direction_ == TravelDirection::backward)
    return {k, reversed(block.motion), programmed, programmed, block.slope, corner_out(k)};
  return {k, block.motion, 0.0, programmed, block.slope, corner_out(k)};
}

PathInterpolator::PushedMotion PathInterpolator::rest_of_block(size_t k, const Motion& rest) const {
  const double covered = PathSegment(rest, machine_).covered_distance();
  const double end = direction_ == TravelDirection::backward ? 0.0 : PathSegment(blocks_[k].motion, machine_).covered_distance();
  return {k, rest, end - direction_sign() * covered, covered, blocks_[k].slope, corner_out(k)};
}

Corner PathInterpolator::corner_out(size_t k) const {
  return direction_ == TravelDirection::backward ? corner_below(k) : corner_after(blocks_[k]);
}

void PathInterpolator::push(PushedMotion m, bool stop_before) {
  if (pushed_.empty()) pushed_covered_ = covered_before_front_;
  const PathSegment segment(m.motion, machine_);
  const double length = segment.length();
  if (stop_covered_ && std::isfinite(length)) {
    const double to_stop = *stop_covered_ - pushed_covered_;
    const double s = m.covered > 0 ? length * to_stop / m.covered : 0.0;
    // The part before the stop ends as programmed (a corner there is not
    // contoured): the path stands on the mark.
    const std::optional<Corner> ends_at_stop = m.out ? std::optional<Corner>(Corner{}) : std::nullopt;
    if (s <= shortest_rest_mm) {  // at its start
      look_ahead_.flush();
      place_stop(segment.position(0));
      stop_before = true;
    } else if (s < length - shortest_rest_mm) {
      // ISC-3: the block is split where the stop lies; the look-ahead brakes
      // to v = 0 at the split as before an M function, and the path enters
      // the second part from standstill.
      const std::vector<double> point = segment.position(s);
      const double covered_first = m.covered * s / length;
      PushedMotion first = m, second = m;
      first.motion = motion_until(m.motion, point);
      first.covered = covered_first;
      first.out = ends_at_stop;
      second.motion = motion_from(m.motion, point);
      second.origin = m.origin + direction_sign() * covered_first;
      second.covered = m.covered - covered_first;
      hand_over(std::move(first), stop_before);
      place_stop(point);
      hand_over(std::move(second), true);
      return;
    } else if (s <= length + shortest_rest_mm) {  // at its end
      const std::vector<double> end = m.motion.end;
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
  if (pushed_.empty()) pushed_covered_ = covered_before_front_;
  // [from, to] of the curve, run towards its end or its start.
  const auto hand_over_part = [&](const ContourJoint::Half& half, double from, double to, bool stop_before) {
    PathSegment piece(stop.curve, from, to, !towards_end, machine_);
    const Block& block = blocks_[half.block];
    // For path_ahead() (ISC-4), within PATH_DEV of the curve.
    Motion chord = block.motion;
    if (chord.type != MotionType::rapid) chord.type = MotionType::linear;
    chord.start = piece.position(0);
    chord.end = piece.end();
    pushed_covered_ += piece.covered_distance();
    pushed_.push_back({half.block, chord, 0.0, piece.covered_distance(), block.slope, std::nullopt});
    look_ahead_.push(half.block, std::move(piece), block.slope, stop_before);
  };
  const auto part = [&](const ContourJoint::Half& half, double from, double to) {
    if (!(to - from > shortest_rest_mm)) {
      // Too short to tell apart from the curve (10 nm): a straight line, so
      // that the path goes on from where it stands.
      if (!(to - from > 1e-9)) return;
      Motion line = blocks_[half.block].motion;
      if (line.type != MotionType::rapid) line.type = MotionType::linear;
      line.start = j.curve->position(towards_end ? from : to);
      line.end = j.curve->position(towards_end ? to : from);
      push({half.block, line, 0.0, j.covered(from, to), blocks_[half.block].slope, std::nullopt});
      return;
    }
    const double covered = j.covered(from, to);
    const double to_stop = stop_covered_ ? *stop_covered_ - pushed_covered_ : covered;
    if (to_stop < covered - shortest_rest_mm) {
      if (to_stop <= shortest_rest_mm) {  // at its start
        look_ahead_.flush();
        place_stop(j.curve->position(towards_end ? from : to));
        hand_over_part(half, from, to, true);
        return;
      }
      // ISC-3: split where the stop lies (each half covers in proportion).
      const double at = towards_end ? from + (to - from) * to_stop / covered : to - (to - from) * to_stop / covered;
      hand_over_part(half, towards_end ? from : at, towards_end ? at : to, false);
      place_stop(j.curve->position(at));
      hand_over_part(half, towards_end ? at : from, towards_end ? to : at, true);
      return;
    }
    hand_over_part(half, from, to, false);
  };
  const double x = stop.curve_s, split = j.split, length = j.curve->length();
  if (towards_end) {
    part(j.before, x, split);
    part(j.after, std::max(x, split), length);
  } else {
    part(j.after, split, x);
    part(j.before, 0, std::min(x, split));
  }
  const ContourJoint::Half& last = towards_end ? j.after : j.before;
  const std::vector<double> joint_point = j.curve->position(towards_end ? length : 0.0);
  const bool backward = direction_ == TravelDirection::backward;
  if (const auto rest = rest_of_motion(blocks_[last.block].motion, joint_point, backward, machine_))
    push(rest_of_block(last.block, *rest));
  return last.block;
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
  const size_t k = look_ahead_.front().block_index;
  // The front motion and the parts of the same block after it (a split).
  std::vector<PushedMotion> parts;
  for (const PushedMotion& m : pushed_) {
    if (m.block != k) break;
    parts.push_back(m);
  }
  const StopPoint stop = leave_front(t);
  const PushedMotion& front = parts.front();
  const double left = front.covered - direction_sign() * (stop.programmed_place - front.origin);
  if (stop.curve) {
    const size_t on = push_along_curve(stop, !stop.curve_reversed);  // with the rest of its block
    if (direction_ == TravelDirection::backward) cursors_.next_backward = on;
    else cursors_.next_to_look_ahead = on + 1;
    refill();
    return;
  }
  // What is left of the front, from where the path stands: also a rest too
  // short for its own geometry (a straight line: a 4.6 nm rest dropped made
  // the path jump, fuzz seed 228); on a full circle by what it has covered.
  if (const auto rest = rest_of_motion(front.motion, stop.position, false, machine_, left < front.covered / 2)) {
    PushedMotion r = front;
    r.motion = *rest;
    r.origin = stop.programmed_place;
    r.covered = std::max(left, 0.0);
    push(std::move(r));
  } else if (parts.size() == 1) {
    // Nothing is left of block k: it is finished, as finish_front() would
    // have it (the cursors say where the path stands, KRN-5).
    observer_.finish_block(k);
    if (direction_ == TravelDirection::forward) cursors_.next_to_run = std::max(cursors_.next_to_run, k + 1);
    cursors_.last_finished = k;
  }
  for (size_t i = 1; i < parts.size(); ++i) push(parts[i]);
  if (direction_ == TravelDirection::backward) cursors_.next_backward = k;
  else cursors_.next_to_look_ahead = k + 1;
  refill();
}

void PathInterpolator::refill_forward() {
  size_t& next = cursors_.next_to_look_ahead;
  for (; !look_ahead_.full() && next < blocks_.size() && next != invalid_block_; ++next) {
    const Block& block = blocks_[next];
    if (!block.has_motion) continue;
    // M functions, a dwell or a channel initialisation on its line or since
    // the last motion block: the path stands still where it starts.
    bool stop_before = false;
    for (size_t i = next + 1; i-- > 0;) {
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
  if (next >= blocks_.size()) look_ahead_.flush();
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

void PathInterpolator::begin_front(const MotionState& state, double t0) {
  const size_t index = look_ahead_.front().block_index;
  run_blocks_without_motion(index);
  const bool first_time = direction_ == TravelDirection::forward && index >= cursors_.begun;
  // Once per motion, at its first piece (contoured blocks are several, KRN-6).
  if (look_ahead_.front().begins_block)
    observer_.reach_block(blocks_[index], first_time);  // its M functions go out before its motion (MVS_SVS)
  if (first_time) cursors_.begun = index + 1;
  plan(state, t0);
}

// Replanning from a state on the plan continues it (the planner is
// time-optimal, so its tail is too); it is done at every block transition,
// where the look-ahead has seen one block more, and when the velocity
// factor changes.
void PathInterpolator::plan(const MotionState& state, double t0) {
  // A transition that turned limiting while the path brakes through it (an
  // override change) may demand what the braking path cannot meet; then
  // the plan runs through it to the next limiting one, as it did before.
  Stretch st = look_ahead_.stretch(state.v);
  for (size_t through = 1;; ++through) {
    double length = st.length, v_end = st.v_end;
    if (stop_at_) {
      // Where the path stands if it brakes now, on the front block's scale.
      const double braked = velocity_change(state.v, state.a, 0, st.lim, st.slope).end(state).p;
      stop_at_ = std::max(*stop_at_, travelled_before_front_ + braked);
      // A stop on the stretch's end but for round-off is on it: interpolate()
      // holds the path there (on the same tolerance), so the plan must end
      // at rest there (fuzz seed 870: 6.7 mm/s to 0 in one cycle).
      const double to_stop = *stop_at_ - travelled_before_front_;
      if (to_stop <= length + 1e-9 * (1 + *stop_at_)) {
        length = std::min(length, to_stop);
        v_end = 0;
      }
    }
    plan_ = block_profile(state, length, v_end, st.lim, st.slope);
    if (plan_.end().v <= v_end + 1e-9 * (1 + v_end)) break;
    Stretch longer = look_ahead_.stretch(state.v, through);
    if (longer.length <= st.length) break;  // nothing to run through
    st = longer;
  }
  plan_start_cycles_ = t0 / machine_.cycle_time_s();
}

std::vector<Motion> PathInterpolator::path_ahead() const {
  std::vector<Motion> ahead;
  bool front = true;
  for (const PushedMotion& pushed : pushed_) {
    const Motion& motion = pushed.motion;
    if (front) {
      // The rest of the front: nothing at its end point (an arc's rest from
      // there would be a full circle), all of it at its start.
      const std::vector<double> here = setpoint_positions();
      double to_end = 0, to_start = 0;
      for (size_t i = 0; i < here.size(); ++i) {
        to_end = std::max(to_end, std::abs(here[i] - motion.end[i]));
        to_start = std::max(to_start, std::abs(here[i] - motion.start[i]));
      }
      if (to_start <= 1e-9) ahead.push_back(motion);
      else if (to_end > 1e-9) ahead.push_back(motion_from(motion, here));
      front = false;
      continue;
    }
    ahead.push_back(motion);
  }
  if (direction_ == TravelDirection::backward) {
    for (size_t i = cursors_.next_backward; i-- > cursors_.lowest_stored;)
      if (blocks_[i].has_motion) ahead.push_back(reversed(blocks_[i].motion));
  } else {
    for (size_t i = cursors_.next_to_look_ahead; i < blocks_.size() && i != invalid_block_; ++i)
      if (blocks_[i].has_motion) ahead.push_back(blocks_[i].motion);
  }
  return ahead;
}

void PathInterpolator::stop_after(double t, double distance, bool rebuild) {
  placed_stop_.reset();
  if (!standing(t)) {
    stop_at_ = travelled_before_front_ + path_state_at(t).p + std::max(distance, 0.0);
    replan_ = true;
    return;
  }
  stop_at_.reset();
  stop_covered_from_ = covered_before_front_ + std::abs(front_covered_);
  if (look_ahead_.empty()) stop_covered_from_ = covered_before_front_;
  stop_covered_ = stop_covered_from_ + std::max(distance, 0.0);
  if (!rebuild) return;
  if (!look_ahead_.empty()) restart_here(t);
  else if (!blocks_.empty()) refill();
  replan_ = true;
}

void PathInterpolator::release_stop() {
  stop_at_.reset();
  stop_covered_.reset();
  placed_stop_.reset();
  replan_ = true;
}

bool PathInterpolator::at_stop(double t) const {
  if (!stop_at_ || !standing(t)) return false;
  const double p = travelled_before_front_ + (look_ahead_.empty() ? 0.0 : path_state_at(t).p);
  return std::abs(p - *stop_at_) <= 1e-9 * (1 + std::abs(p));
}

void PathInterpolator::finish_front() {
  const LookAheadBlock& front = look_ahead_.front();
  observer_.travelled(direction_sign() * front.segment.covered_distance());
  travelled_before_front_ += front.segment.length();
  covered_before_front_ += front.segment.covered_distance();
  front_done_ += front.segment.covered_distance();
  if (front.ends_block) {
    observer_.finish_block(front.block_index);
    pushed_.pop_front();
    front_done_ = 0;
  }
  if (direction_ == TravelDirection::forward)
    cursors_.next_to_run = std::max(cursors_.next_to_run, front.block_index + 1);
  cursors_.last_finished = front.block_index;
  look_ahead_.pop_front();
  refill();
}

// #DISTANCE PROG START and M30 act when the interpolator reaches them.
void PathInterpolator::run_blocks_without_motion(size_t up_to) {
  for (; cursors_.next_to_run < up_to; ++cursors_.next_to_run) observer_.reach_block(blocks_[cursors_.next_to_run], true);
}

PathProgress PathInterpolator::interpolate(double t) {
  if (!look_ahead_.empty() && replan_) plan(path_state_at(t), t);
  replan_ = false;
  MotionState path = path_state_at(t);
  bool reached_contour_start = false;
  // Pass every block the path has left by t; a plan that ends short of the
  // block end (feed hold, override 0) waits there.
  while (!look_ahead_.empty()) {
    const double length = look_ahead_.front().segment.length();
    const bool plan_ended = since_plan_start(t) >= plan_.duration();
    if (path.p < length && !(plan_ended && path.p >= length - 1e-9 * (1 + length))) break;
    // A stop at the block end: the path stands on the end, in the block.
    if (plan_ended && stop_at_ && std::abs(travelled_before_front_ + length - *stop_at_) <= 1e-9 * (1 + *stop_at_))
      break;
    const std::vector<double> end_point = look_ahead_.front().segment.end();
    finish_front();
    if (look_ahead_.empty()) {
      // Leave the last block exactly on its programmed end point.
      for (size_t i = 0; i < setpoints_.size(); ++i) setpoints_[i] = {end_point[i], 0, 0};
      reached_contour_start = direction_ == TravelDirection::backward;
      break;
    }
    // Go on from where the path left the block: at t, or where a plan that
    // ended on the block end (a limiting transition) ended. A plan that
    // stops there (a corner) and is passed a rounding before its end also
    // ends there: the next block starts at rest after it, instead of taking
    // the braking's last residual acceleration round the corner (KRN-3:
    // 40,004 mm/s^3 for a limit of 40,000).
    double t_from = t;
    const bool at_rest = std::abs(plan_.end().v) <= 1e-9;  // mm/s: 0 but for round-off
    const bool stops_on_end = at_rest && std::abs(plan_.end().p - length) <= 1e-9 * (1 + length);
    if (plan_ended || stops_on_end) {
      t_from = plan_start_cycles_ * machine_.cycle_time_s() + plan_.duration();
      path = plan_.end();
      if (at_rest) path.v = path.a = 0;
    }
    path.p -= length;
    begin_front(path, t_from);
    path = path_state_at(t);
  }
  if (look_ahead_.empty()) {
    path_velocity_ = 0;
    front_covered_ = 0;
    if (direction_ == TravelDirection::backward)
      return reached_contour_start ? PathProgress::reached_contour_start : PathProgress::at_contour_start;
    if (invalid_block_) {
      run_blocks_without_motion(*invalid_block_);
      return PathProgress::invalid_block;
    }
    // Every block decoded correctly has run.
    run_blocks_without_motion(blocks_.size());
    return PathProgress::all_blocks_run;
  }
  if (since_plan_start(t) >= plan_.duration()) path.v = path.a = 0;  // held short of the block end
  if (output(path)) return PathProgress::moving;
  // Never a number that is not finite to the drives: nothing moves any more.
  look_ahead_.clear();
  pushed_.clear();
  front_done_ = 0;
  cursors_.next_to_look_ahead = cursors_.next_to_run = cursors_.next_backward = blocks_.size();
  cursors_.lowest_stored = blocks_.size();
  for (AxisSetpoint& setpoint : setpoints_) setpoint.velocity = setpoint.acceleration = 0;
  path_velocity_ = 0;
  return PathProgress::setpoint_not_finite;
}

bool PathInterpolator::output(const MotionState& path) {
  const PathSegment& seg = look_ahead_.front().segment;
  const double s = std::clamp(path.p, 0.0, seg.length());
  const std::vector<double> p = seg.position(s), d1 = seg.tangent(s), d2 = seg.curvature(s);
  std::vector<AxisSetpoint> next(setpoints_.size());
  for (size_t i = 0; i < setpoints_.size(); ++i) {
    next[i] = {p[i], d1[i] * path.v, d1[i] * path.a + d2[i] * path.v * path.v};
    if (!std::isfinite(next[i].position) || !std::isfinite(next[i].velocity) || !std::isfinite(next[i].acceleration))
      return false;
  }
  setpoints_ = std::move(next);
  front_covered_ = direction_sign() * (seg.covered_distance() * s / seg.length());
  path_velocity_ = path.v;
  return true;
}

}  // namespace hil::cnc
