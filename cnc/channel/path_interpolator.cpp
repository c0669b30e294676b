#include "path_interpolator.hpp"

#include <algorithm>
#include <cmath>

#include "motion_parts.hpp"
#include "position_profile.hpp"
#include "velocity_profile.hpp"

namespace hil::cnc {
namespace {

// A rest shorter than this is not moved (10 nm): a shorter arc could not be
// told from a full circle.
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
  stop.on_contour_curve = front.segment.is_contour_curve();
  stop.front_ends_block = front.ends_block && !stop.on_contour_curve;
  double partial = 0;
  if (stop.front_length > 0) {
    partial = front.segment.covered_distance() * stop.s / stop.front_length;
    observer_.travelled(direction_sign() * partial);
  }
  // Where the stop lies in block k's programmed distance (DPS-1, KRN-6: a
  // contoured block is several pieces, and a stop inside a curve is off the
  // programmed line, so the rest's own geometry would not say it).
  const double done = front_block_done_ + partial;
  const double origin = programmed_origin(stop.block);
  stop_programmed_ = direction_ == TravelDirection::forward ? origin + done : origin - done;
  front_block_done_ = 0;
  travelled_before_front_ += stop.s;
  look_ahead_.clear();
  return stop;
}

bool PathInterpolator::push_short_cut(size_t target, const Motion& cut) {
  PathSegment segment(cut, machine_);
  if (!(segment.length() > 0)) return false;
  look_ahead_.push(target, std::move(segment), blocks_[target].slope);
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
    if (blocks_[k].has_motion) {
      const Motion rest = motion_from(blocks_[k].motion, setpoint_positions());
      if (PathSegment(rest, machine_).length() > shortest_rest_mm)
        look_ahead_.push(k, rest, blocks_[k].slope, false, corner_after(blocks_[k]));
    }
    cursors_.next_to_look_ahead = k + 1;
    refill();
    return true;
  }
  const StopPoint stop = leave_front(t);
  const size_t k = stop.block;
  const double at = stop_programmed_;
  direction_ = direction_ == TravelDirection::forward ? TravelDirection::backward : TravelDirection::forward;
  const bool backward = direction_ == TravelDirection::backward;
  // What is left of block k the new way: back to its start, or on to its end.
  const PathSegment whole(blocks_[k].motion, machine_);
  const double programmed = whole.covered_distance();
  const double rest = std::clamp(backward ? at : programmed - at, 0.0, programmed);
  // From a point on a contouring curve (KRN-6), off the programmed motion:
  // first straight onto the motion where the stop lies in its programmed
  // distance, then along the motion (an arc from a point off its circle
  // would blend its radius, and its setpoints would turn where its tangent
  // does not). The path stands at the joint (a corner).
  std::vector<double> from = stop.position;
  std::optional<PathSegment> connector;
  if (stop.on_contour_curve && programmed > 0) {
    from = whole.position(std::clamp(whole.length() * at / programmed, 0.0, whole.length()));
    Motion line = blocks_[k].motion;
    if (line.type != MotionType::rapid) line.type = MotionType::linear;
    line.start = stop.position;
    line.end = from;
    connector.emplace(line, machine_);
  }
  const Motion motion = backward ? reversed(motion_until(blocks_[k].motion, from))
                                 : motion_from(blocks_[k].motion, from);
  if (backward) {
    size_t i = cursors_.begun, counted = 0;
    while (i > 0 && counted < stored_blocks)
      if (blocks_[--i].has_motion) ++counted;
    cursors_.lowest_stored = i;
    cursors_.next_backward = k;
  } else {
    cursors_.next_to_look_ahead = k + 1;
  }
  // A front piece that ends where block k ends (every block without
  // contouring): the way back over block k is what it had covered before
  // the front and on it, as it always was. Otherwise from the stop's place
  // in the programmed distance.
  const double back_over_k = stop.front_ends_block ? whole.length() - stop.front_length + stop.s
                             : programmed > 0      ? whole.length() * rest / programmed
                                                   : 0.0;
  double connector_covered = 0;
  if (connector && connector->length() > shortest_rest_mm) {
    connector_covered = std::min(connector->length(), rest);
    connector->set_covered_distance(connector_covered);
    look_ahead_.push(k, std::move(*connector), blocks_[k].slope, false, !(back_over_k > shortest_rest_mm));
  }
  if (back_over_k > shortest_rest_mm) {
    // Off a curve, the rest counts the programmed remainder (the block-end
    // value stays the programmed sum); on the motion, its own length, as it
    // always did (the stop's place in the plan and the setpoint it left
    // differ by up to a cycle's motion).
    std::optional<double> covered;
    if (stop.on_contour_curve) covered = rest - connector_covered;
    look_ahead_.push(k, motion, blocks_[k].slope, false, backward ? corner_below(k) : corner_after(blocks_[k]),
                     covered);
    rest_block_ = k;
    // Where its pieces begin in the block's programmed distance.
    rest_origin_ = stop.on_contour_curve ? at
                   : backward            ? PathSegment(motion, machine_).covered_distance()
                                         : programmed - PathSegment(motion, machine_).covered_distance();
  }
  cursors_.last_finished = k;  // where the path stands if nothing follows: at block k's start
  refill();
  return true;
}

void PathInterpolator::refill() {
  if (direction_ == TravelDirection::backward) refill_backward();
  else refill_forward();
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
    look_ahead_.push(next, block.motion, block.slope, stop_before, corner_after(block));
  }
  if (next >= blocks_.size()) look_ahead_.flush();
}

void PathInterpolator::refill_backward() {
  while (!look_ahead_.full() && cursors_.next_backward > cursors_.lowest_stored) {
    const size_t i = --cursors_.next_backward;
    if (!blocks_[i].has_motion) continue;
    look_ahead_.push(i, reversed(blocks_[i].motion), blocks_[i].slope, false, corner_below(i));
  }
  if (cursors_.next_backward <= cursors_.lowest_stored) look_ahead_.flush();
}

// Forward coordinate in block k's programmed distance where its pieces in
// the look-ahead begin: a rest pushed by turn() begins where the path
// turned, a whole block at its start (forward) or end (backward).
double PathInterpolator::programmed_origin(size_t k) const {
  if (rest_block_ == k) return rest_origin_;
  if (direction_ == TravelDirection::forward) return 0;
  return PathSegment(blocks_[k].motion, machine_).covered_distance();
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
  // Once per block, at its first piece (contoured blocks are several, KRN-6).
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
  const Stretch st = look_ahead_.stretch(state.v);
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
  plan_start_ = t0;
}

void PathInterpolator::stop_after(double t, double distance) {
  stop_at_ = travelled_before_front_ + (look_ahead_.empty() ? 0.0 : path_state_at(t).p) + std::max(distance, 0.0);
  replan_ = true;
}

void PathInterpolator::release_stop() {
  stop_at_.reset();
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
  front_block_done_ += front.segment.covered_distance();
  if (front.ends_block) {
    observer_.finish_block(front.block_index);
    front_block_done_ = 0;
    if (rest_block_ == front.block_index) rest_block_.reset();
  }
  travelled_before_front_ += front.segment.length();
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
    const bool plan_ended = t - plan_start_ >= plan_.duration();
    if (path.p < length && !(plan_ended && path.p >= length - 1e-9 * (1 + length))) break;
    const std::vector<double> end_point = look_ahead_.front().segment.end();
    finish_front();
    if (look_ahead_.empty()) {
      // Leave the last block exactly on its programmed end point.
      for (size_t i = 0; i < setpoints_.size(); ++i) setpoints_[i] = {end_point[i], 0, 0};
      reached_contour_start = direction_ == TravelDirection::backward;
      break;
    }
    // Go on from where the path left the block: at t, or where a plan that
    // ended on the block end (a limiting transition) ended.
    double t_from = t;
    if (plan_ended) {
      t_from = plan_start_ + plan_.duration();
      path = plan_.end();
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
  if (t - plan_start_ >= plan_.duration()) path.v = path.a = 0;  // held short of the block end
  if (output(path)) return PathProgress::moving;
  // Never a number that is not finite to the drives: nothing moves any more.
  look_ahead_.clear();
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
