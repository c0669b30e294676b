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
  if (stop.front_length > 0) {
    const double covered = front.segment.covered_distance() * stop.s / stop.front_length;
    observer_.travelled(direction_sign() * covered);
    covered_before_front_ += covered;
  }
  travelled_before_front_ += stop.s;
  look_ahead_.clear();
  motions_.clear();
  return stop;
}

bool PathInterpolator::push_short_cut(size_t target, const Motion& cut) {
  PathSegment segment(cut, machine_);
  if (!(segment.length() > 0)) return false;
  push(target, cut, blocks_[target].slope);
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
        push(k, *rest, blocks_[k].slope);
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
    cursors_.next_backward = k;
  } else {
    cursors_.next_to_look_ahead = k + 1;
  }
  // What is left of block k the new way: back to its start, or on to its end
  // (the front may be a part of block k, split at an insert stop mark).
  if (const auto rest = rest_of_motion(blocks_[k].motion, stop.position, backward, machine_, at_end_of_k))
    push(k, *rest, blocks_[k].slope);
  cursors_.last_finished = k;  // where the path stands if nothing follows: at block k's start
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

void PathInterpolator::push(size_t index, const Motion& motion, SlopeType slope, bool stop_before) {
  if (look_ahead_.empty()) {
    pushed_length_ = travelled_before_front_;
    pushed_covered_ = covered_before_front_;
  }
  PathSegment segment(motion, machine_);
  if (stop_covered_ && std::isfinite(segment.length())) {
    const double to_stop = *stop_covered_ - pushed_covered_, covered = segment.covered_distance();
    const double s = covered > 0 ? segment.length() * to_stop / covered : 0.0;
    if (s <= shortest_rest_mm) {  // at its start
      place_stop(segment.position(0));
      stop_before = true;
    } else if (s < segment.length() - shortest_rest_mm) {
      // ISC-3: the block is split where the stop lies; the look-ahead brakes
      // to v = 0 at the split as before an M function, and the path enters
      // the second part from standstill.
      const std::vector<double> point = segment.position(s);
      const Motion first = motion_until(motion, point), second = motion_from(motion, point);
      push_segment(index, first, PathSegment(first, machine_), slope, stop_before);
      place_stop(point);
      push_segment(index, second, PathSegment(second, machine_), slope, true);
      return;
    } else if (s <= segment.length() + shortest_rest_mm) {  // at its end
      push_segment(index, motion, std::move(segment), slope, stop_before);
      place_stop(motion.end);
      return;
    }
  }
  push_segment(index, motion, std::move(segment), slope, stop_before);
}

void PathInterpolator::push_segment(size_t index, const Motion& motion, PathSegment segment, SlopeType slope,
                                    bool stop_before) {
  pushed_length_ += segment.length();
  pushed_covered_ += segment.covered_distance();
  look_ahead_.push(index, std::move(segment), slope, stop_before);
  motions_.emplace_back(index, motion);
}

void PathInterpolator::place_stop(std::vector<double> position) {
  stop_at_ = pushed_length_;
  placed_stop_ = PlacedStop{std::move(position), pushed_covered_ - stop_covered_from_};
  stop_covered_.reset();
  replan_ = true;
}

void PathInterpolator::place_stop_at_end() {
  if (!stop_covered_) return;
  if (look_ahead_.empty()) {
    pushed_length_ = travelled_before_front_;
    pushed_covered_ = covered_before_front_;
    place_stop(setpoint_positions());
  } else {
    place_stop(motions_.back().second.end);
  }
}

void PathInterpolator::restart_here(double t) {
  const size_t k = look_ahead_.front().block_index;
  const SlopeType slope = look_ahead_.front().slope;
  // The front segment and the parts of the same block after it (a split).
  std::vector<Motion> parts;
  for (const auto& [index, motion] : motions_) {
    if (index != k) break;
    parts.push_back(motion);
  }
  const StopPoint stop = leave_front(t);
  // What is left of the front by length: an arc's rest from its end point
  // would be a full circle.
  if (stop.front_length - stop.s > shortest_rest_mm) {
    push(k, motion_from(parts.front(), stop.position), slope);
  } else if (parts.size() == 1) {
    // Nothing is left of block k: it is finished, as finish_front() would
    // have it (the cursors say where the path stands, KRN-5).
    observer_.finish_block(k);
    if (direction_ == TravelDirection::forward) cursors_.next_to_run = std::max(cursors_.next_to_run, k + 1);
    cursors_.last_finished = k;
  }
  for (size_t i = 1; i < parts.size(); ++i) push(k, parts[i], slope);
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
      return;
    }
    push(next, block.motion, block.slope, stop_before);
  }
}

void PathInterpolator::refill_backward() {
  while (!look_ahead_.full() && cursors_.next_backward > cursors_.lowest_stored) {
    const size_t i = --cursors_.next_backward;
    if (!blocks_[i].has_motion) continue;
    push(i, reversed(blocks_[i].motion), blocks_[i].slope);
  }
}

void PathInterpolator::begin_front(const MotionState& state, double t0) {
  const size_t index = look_ahead_.front().block_index;
  run_blocks_without_motion(index);
  const bool first_time = direction_ == TravelDirection::forward && index >= cursors_.begun;
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
      const double to_stop = *stop_at_ - travelled_before_front_;
      if (to_stop <= length) {
        length = to_stop;
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
  for (const auto& [index, motion] : motions_) {
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
  observer_.finish_block(front.block_index);
  travelled_before_front_ += front.segment.length();
  covered_before_front_ += front.segment.covered_distance();
  motions_.pop_front();
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
  motions_.clear();
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
