#include "path_interpolator.hpp"

#include <algorithm>
#include <cmath>

#include "motion_parts.hpp"
#include "position_profile.hpp"
#include "velocity_profile.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
PathInterpolator::PathInterpolator(const MachineConfig& machine, PathObserver& observer)
    : machine_(machine), observer_(observer), look_ahead_(machine) {
  out_.axes.resize(machine.axes.size());
}

std::vector<double> PathInterpolator::setpoint_positions() const {
  std::vector<double> positions(out_.axes.size());
  for (size_t i = 0; i < positions.size(); ++i) positions[i] = out_.axes[i].position;
  return positions;
}

void PathInterpolator::set_velocity_factor(double factor) {
  look_ahead_.set_velocity_factor(factor);
  factor_changed_ = true;
}

StopPoint PathInterpolator::leave_front(double t) {
  const LookAheadPiece& front = look_ahead_.front();
  StopPoint stop;
  stop.block = front.block_index;
  stop.front_length = front.segment.length();
  stop.s = std::clamp(path_state_at(t).p, 0.0, stop.front_length);
  stop.position = setpoint_positions();
  if (front.segment.is_contour_curve()) {
    stop.curve = front.segment.joint();
    stop.curve_s = front.segment.curve_position(stop.s);
    stop.curve_reversed = front.segment.reversed();
  } else if (const MotionPiece& piece = pushed_.front(); piece.along_chord) {
    // On the chord of a curve's tiny rest: on the curve, off the block's
    // motion. Taken as a point off the motion, the turn ran a line from
    // there to the block's end that counts less than the curve and the
    // block left (fuzz contour seed 12004916: 6.4e-5 mm, DPS-1).
    stop.curve = piece.curve->joint;
    stop.curve_s = piece.curve->at(stop.front_length > 0 ? stop.s / stop.front_length : 0.0);
    stop.curve_reversed = piece.curve->reversed;
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
  MotionPiece piece;
  piece.block = target;
  piece.motion = cut;
  piece.covered = segment.covered_distance();
  piece.slope = program_[target].slope;
  push(std::move(piece));
  return true;
}

void PathInterpolator::go_on_from_standstill(double t) {
  refill();
  if (!look_ahead_.empty()) begin_front({}, t);
  replan_ = factor_changed_ = false;
}

bool PathInterpolator::turn(double t, size_t stored_blocks) {
  if (look_ahead_.empty()) {
    // Standing where the stored contour begins. (Forward with nothing left
    // to move, the program is about to end: it cannot turn there.)
    if (!program_.backward()) return false;
    program_.turn(stored_blocks);
    // It stands in block k (at its start, or where a backward short cut
    // found nothing before it, DDTG-6): on along k from there.
    const size_t k = program_.cursors().last_finished;
    if (program_[k].has_motion)
      if (const auto rest = rest_of_motion(program_[k].motion, setpoint_positions(), false, machine_))
        push(rest_of_block(k, *rest));
    program_.go_on_after(k);
    refill();
    return true;
  }
  const StopPoint stop = leave_front(t);
  const size_t k = stop.block;
  // Where on a full circle k (its start is its end) the path stands: its
  // place in k's programmed distance says which end. (Told from where it
  // stood in the front piece, a backward rest of 2.4e-14 mm at k's start
  // was taken for k's end, and the turn skipped the circle: fuzz arcs seed
  // 42301617 on another machine, dist_prog_start 54 mm short at the end.)
  const bool at_end_of_k =
      stop.programmed_place > PathSegment(program_[k].motion, machine_).covered_distance() / 2;
  program_.turn(stored_blocks);
  const bool backward = program_.backward();
  // What is left of block k the new way: back to its start, or on to its end
  // (the front may be a part of block k, split at an insert stop mark). On a
  // contouring curve, back along it into the block it came from.
  size_t on = k;
  if (stop.curve) on = push_along_curve(stop, stop.curve_reversed);
  else if (const auto rest = rest_of_motion(program_[k].motion, stop.position, backward, machine_, at_end_of_k))
    push(rest_of_block(k, *rest));
  program_.go_on_after(on);
  program_.stands_in(on);  // where the path stands if nothing follows: at block k's start
  refill();
  return true;
}

void PathInterpolator::begin_front(const MotionState& state, double t0) {
  const size_t index = look_ahead_.front().block_index;
  run_blocks_without_motion(index);
  const bool first_time = program_.begin(index);
  // Once per motion, at its first piece (contoured blocks are several, KRN-6).
  if (look_ahead_.front().begins_block)
    observer_.reach_block(program_[index], index, first_time);  // its M functions go out before its motion (MVS_SVS)
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
    if (stop_.at()) {
      // Where the path stands if it brakes now, on the front block's scale.
      const double braked = velocity_change(state.v, state.a, 0, st.lim, st.slope).end(state).p;
      stop_.not_before(travelled_before_front_ + braked);
      // A stop on the stretch's end but for round-off is on it: interpolate()
      // holds the path there (on the same tolerance), so the plan must end
      // at rest there (fuzz seed 870: 6.7 mm/s to 0 in one cycle).
      const double to_stop = *stop_.at() - travelled_before_front_;
      if (to_stop <= length + tolerance::length_at(*stop_.at())) {
        length = std::min(length, to_stop);
        v_end = 0;
      }
    }
    BlockProfile planned = block_profile(state, length, v_end, st.lim, st.slope);
    plan_.profile = std::move(planned.profile);
    plan_.arrival = planned.arrival;
    // Too fast on the stretch's end, or on v_end only beyond it (fuzz seed
    // 12016401: a plan that brakes a to 0 reached v_end 1.57 mm past the
    // transition it had to keep, X's acceleration 24,512 for 2,000): the
    // transition cannot be kept, the stretch runs through it.
    if (keeps_end(plan_.arrival)) break;
    Stretch longer = look_ahead_.stretch(state.v, through);
    if (longer.length <= st.length) break;  // nothing to run through
    st = longer;
  }
  plan_.start_cycles = t0 / machine_.cycle_time_s();
}

void PathInterpolator::replan(double t) {
  const Plan before = plan_;
  plan(path_state_at(t), t);
  // An override change while the path brakes for a limiting transition can
  // leave no plan that keeps it (a curvature step's jerk share: fuzz seed
  // 2089732 reached the start of the stored contour at 4.8 mm/s, 2,700
  // mm/s^2); the plan made before keeps it: it stays, and the new factor
  // acts from the next transition. A stop must be planned for: that plan is
  // taken whatever its arrival.
  if (!replan_ && !keeps_end(plan_.arrival) && keeps_end(before.arrival)) plan_ = before;
}

std::vector<Motion> PathInterpolator::path_ahead() const {
  std::vector<Motion> ahead;
  bool front = true;
  for (const MotionPiece& pushed : pushed_) {
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
      if (to_start <= tolerance::length_mm) ahead.push_back(motion);
      else if (to_end > tolerance::length_mm) ahead.push_back(motion_from(motion, here));
      front = false;
      continue;
    }
    ahead.push_back(motion);
  }
  program_.motions_ahead(ahead, path_ahead_blocks);
  return ahead;
}

void PathInterpolator::stop_after(double t, double distance, bool rebuild) {
  if (!standing(t)) {
    stop_.ask_at_length(travelled_before_front_ + path_state_at(t).p + std::max(distance, 0.0));
    replan_ = true;
    return;
  }
  stop_.ask_covered(covered_before_front_ + (look_ahead_.empty() ? 0.0 : std::abs(out_.front_covered)), distance);
  if (!rebuild) return;
  if (!look_ahead_.empty()) restart_here(t);
  else if (!program_.blocks().empty()) refill();
  replan_ = true;
}

void PathInterpolator::release_stop() {
  stop_.release();
  replan_ = true;
}

bool PathInterpolator::at_stop(double t) const {
  if (!stop_.at() || !standing(t)) return false;
  const double p = travelled_before_front_ + (look_ahead_.empty() ? 0.0 : path_state_at(t).p);
  return std::abs(p - *stop_.at()) <= tolerance::length_at(p);
}

void PathInterpolator::finish_front() {
  const LookAheadPiece& front = look_ahead_.front();
  observer_.travelled(direction_sign() * front.segment.covered_distance());
  travelled_before_front_ += front.segment.length();
  covered_before_front_ += front.segment.covered_distance();
  front_done_ += front.segment.covered_distance();
  if (front.ends_block) {
    ++fill_budget_;  // its replacement
    observer_.finish_block(front.block_index);
    pushed_.pop_front();
    front_done_ = 0;
  }
  program_.finish(front.block_index);
  look_ahead_.pop_front();
  refill();
  forget_history();
}

// #DISTANCE PROG START and M30 act when the interpolator reaches them.
void PathInterpolator::run_blocks_without_motion(size_t up_to) {
  while (const std::optional<size_t> k = program_.next_to_run_before(up_to)) {
    observer_.reach_block(program_[*k], *k, true);
    program_.ran(up_to);
  }
}

void PathInterpolator::forget_history() {
  size_t keep = past_program_end;
  if (!pushed_.empty()) keep = std::min(keep, pushed_.front().block);
  if (!look_ahead_.empty()) keep = std::min(keep, look_ahead_.front().block_index);
  program_.forget_history(keep);
}

PathProgress PathInterpolator::interpolate(double t) {
  top_up();
  const PathProgress progress = move_to(t);
  fill_budget_ = look_ahead_fill_per_cycle;  // the next cycle's
  return progress;
}

PathProgress PathInterpolator::move_to(double t) {
  // Replanned when the look-ahead grew: the plan ended at rest on the last
  // block it had.
  if (!look_ahead_.empty() && (replan_ || factor_changed_ || grown_)) replan(t);
  replan_ = factor_changed_ = grown_ = false;
  MotionState path = path_state_at(t);
  bool reached_contour_start = false;
  // Pass every block the path has left by t; a plan that ends short of the
  // block end (feed hold, override 0) waits there.
  while (!look_ahead_.empty()) {
    const double length = look_ahead_.front().segment.length();
    const bool plan_ended = since_plan_start(t) >= plan_.profile.duration();
    if (path.p < length && !(plan_ended && path.p >= length - tolerance::length_at(length))) break;
    // A stop at the block end: the path stands on the end, in the block.
    if (plan_ended && stop_.at() && std::abs(travelled_before_front_ + length - *stop_.at()) <= tolerance::length_at(*stop_.at()))
      break;
    const AxisValues end_point = look_ahead_.front().segment.end();
    finish_front();
    if (look_ahead_.empty()) {
      // Leave the last block exactly on its programmed end point.
      for (size_t i = 0; i < out_.axes.size(); ++i) out_.axes[i] = {end_point[i], 0, 0};
      reached_contour_start = program_.backward();
      break;
    }
    // Go on from where the path left the block: at t, or where a plan that
    // ended on the block end (a limiting transition) ended. A plan that
    // stops there (a corner) and is passed a rounding before its end also
    // ends there: the next block starts at rest after it, instead of taking
    // the braking's last residual acceleration round the corner (KRN-3:
    // 40,004 mm/s^3 for a limit of 40,000).
    double t_from = t;
    const bool at_rest = std::abs(plan_.profile.end().v) <= tolerance::velocity_mm_s;
    const bool stops_on_end = at_rest && std::abs(plan_.profile.end().p - length) <= tolerance::length_at(length);
    if (plan_ended || stops_on_end) {
      t_from = plan_.start_cycles * machine_.cycle_time_s() + plan_.profile.duration();
      path = plan_.profile.end();
      if (at_rest) path.v = path.a = 0;
    }
    path.p -= length;
    begin_front(path, t_from);
    path = path_state_at(t);
  }
  if (look_ahead_.empty()) {
    out_.velocity = out_.acceleration = 0;
    out_.front_covered = 0;
    if (program_.backward())
      return reached_contour_start ? PathProgress::reached_contour_start : PathProgress::at_contour_start;
    if (const std::optional<size_t>& invalid = program_.invalid_block()) {
      run_blocks_without_motion(*invalid);
      return PathProgress::invalid_block;
    }
    // Every block decoded correctly has run.
    run_blocks_without_motion(past_program_end);
    return PathProgress::all_blocks_run;
  }
  if (since_plan_start(t) >= plan_.profile.duration()) path.v = path.a = 0;  // held short of the block end
  if (output(path)) return PathProgress::moving;
  // Never a number that is not finite to the drives: nothing moves any more.
  look_ahead_.clear();
  pushed_.clear();
  front_done_ = 0;
  program_.abandon();
  for (AxisSetpoint& setpoint : out_.axes) setpoint.velocity = setpoint.acceleration = 0;
  out_.velocity = out_.acceleration = 0;
  return PathProgress::setpoint_not_finite;
}

bool PathInterpolator::output(const MotionState& path) {
  const PathSegment& seg = look_ahead_.front().segment;
  const double s = std::clamp(path.p, 0.0, seg.length());
  const std::vector<double> p = seg.position(s), d1 = seg.tangent(s), d2 = seg.curvature(s);
  std::vector<AxisSetpoint> next(out_.axes.size());
  for (size_t i = 0; i < out_.axes.size(); ++i) {
    next[i] = {p[i], d1[i] * path.v, d1[i] * path.a + d2[i] * path.v * path.v};
    if (!std::isfinite(next[i].position) || !std::isfinite(next[i].velocity) || !std::isfinite(next[i].acceleration))
      return false;
  }
  out_.axes = std::move(next);
  out_.front_covered = direction_sign() * (seg.covered_distance() * s / seg.length());
  out_.velocity = path.v;
  out_.acceleration = path.a;
  return true;
}

}  // namespace hil::cnc
