#include "lift.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lift_limits.hpp"
#include "position_profile.hpp"
#include "velocity_profile.hpp"
#include "tolerances.hpp"

namespace hil::cnc {

void Lift::begin_program() {
  ranges_.clear();
  covered_ = 0;
  last_reached_ = 0;
  blocks_run_ = false;
  active_ = path_left_ = positioning_ = landed_ = missed_landing_ = false;
  starts_next_cycle_ = waits_for_landing_ = false;
  pending_.clear();
  advanced_.reset();
  cap_ = 0;
  updated_at_.reset();
}

void Lift::reach_block(size_t index, int32_t override_value) {
  // Reaching a block after the range, or its last block when that one has
  // no motion (LIFT_END, #FLUSH alone on a line), the path has run the range.
  last_reached_ = index;
  if (active_ && range().passed_by(index)) path_left_ = true;
  const auto starting = std::find_if(ranges_.begin(), ranges_.end(), [&](const LiftRange& r) { return r.start == index; });
  if (starting == ranges_.end()) return;
  const size_t r = static_cast<size_t>(starting - ranges_.begin());
  if (active_) {  // begins once the current range has ended (update), from here
    pending_.push_back({r, covered_});
    return;
  }
  start(r, override_value, covered_);
  starts_next_cycle_ = true;
}

void Lift::start(size_t range_index, int32_t override_value, double covered_at_start) {
  current_ = range_index;
  active_ = true;
  positioning_ = landed_ = waits_for_landing_ = false;
  covered_at_start_ = covered_at_start;
  path_left_ = range().passed_by(last_reached_);  // one that began while another ended may be run already
  const LiftRange& g = range();
  state_ = MotionState{g.z0, 0, 0, 0};
  advanced_.reset();
  covered_last_cycle_.reset();
  cap_ = 0;
  if (g.positioning) {
    position_to(g.command.pos);
  } else if (machine_.lift_method == LiftMethod::time_based) {
    const AxisConfig& axis = machine_.axes[static_cast<size_t>(g.command.axis)];
    const double dt = machine_.cycle_time_s();
    advanced_.emplace(g.z0, g.command.pos, g.peak, advanced_lifting_limits(axis, dt), dt);
    cap_ = override_value;  // LIFT-8: what runs now is accepted
  }
}

void Lift::position_to(double target) {
  const AxisConfig& axis = machine_.axes[static_cast<size_t>(range().command.axis)];
  const Limits lim = machine_.lift_method == LiftMethod::time_based
                         ? advanced_lifting_limits(axis, machine_.cycle_time_s())
                         : Limits{axis.v_max, axis.a_max, axis.j_max};
  positioning_ = true;
  waits_for_landing_ = false;  // the positioning holds the path as long as it needs
  hold_position_ = target;
  positioning_profile_ = position_profile(state_, target, lim, SlopeType::trapez);
  since_positioning_ = 0;
  advanced_.reset();
}

void Lift::land_at_once() {
  if (!positioning_ && !landed_) position_to(range().command.pos);
}

void Lift::land_now(PathInterpolator& path) {
  if (!active_) return;
  land_at_once();
  // The ranges waiting after it land as well (the short cut runs through
  // them): the lift axis ends on the last one's POS.
  double landing = hold_position_;
  for (Pending& next : pending_) {
    next.land = true;
    landing = ranges_[next.range].command.pos;
  }
  path.place_axis(static_cast<size_t>(range().command.axis), landing);
}

void Lift::stop_now() {
  if (!active_ || landed_ || (!advanced_ && !positioning_)) return;  // Lifting stops with the path
  const AxisConfig& axis = machine_.axes[static_cast<size_t>(range().command.axis)];
  const Limits lim = advanced_lifting_limits(axis, machine_.cycle_time_s());
  position_to(velocity_change(state_.v, state_.a, 0, lim, SlopeType::trapez).end(state_).p);
}

void Lift::finish() {
  const double pos = range().command.pos;
  // Lifting lands with the path by construction; Advanced Lifting before it.
  if (advanced_ && !advanced_->landed() &&
      (std::abs(state_.p - pos) > tolerance::length_mm || std::abs(state_.v) > tolerance::velocity_mm_s))
    missed_landing_ = true;
  if (blocks_run_) {
    parked_axis_ = static_cast<size_t>(range().command.axis);
    parked_ = AxisSetpoint{pos, 0, 0};
  }
  active_ = positioning_ = landed_ = waits_for_landing_ = false;
  advanced_.reset();
  cap_ = 0;
}

bool Lift::update(const PathInterpolator& path, double t, int32_t override_value,
                  std::vector<AxisSetpoint>& setpoints) {
  const bool again = updated_at_ == t;
  updated_at_ = t;
  if (again && active_) {
    setpoints[static_cast<size_t>(range().command.axis)] = AxisSetpoint{state_.p, state_.v, state_.a};
    return false;
  }
  if (!active_) {
    apply_parked(setpoints);
    return false;
  }
  bool changed = false;
  if (path_left_ && !positioning_) {
    // The path has run the range: from this cycle on the lift axis is the
    // path's again (on POS: the blocks after a range start there).
    finish();
    start_pending(override_value);
    if (!active_) {
      apply_parked(setpoints);
      return true;
    }
    changed = true;
  }
  const LiftRange& g = range();
  const double dt = machine_.cycle_time_s();
  if (std::exchange(starts_next_cycle_, false) && (positioning_ || advanced_)) {
    // The path's motion of the lift axis came to rest within this cycle:
    // the lift axis stays on its start state until the cycle's end.
  } else if (positioning_) {
    since_positioning_ += dt;
    state_ = positioning_profile_.at(since_positioning_);
    if (since_positioning_ >= positioning_profile_.duration()) {
      state_ = MotionState{hold_position_, 0, 0, 0};
      positioning_ = false;
      landed_ = true;
      changed = true;
    }
  } else if (landed_) {
    state_ = MotionState{hold_position_, 0, 0, 0};
  } else if (advanced_) {
    // The least time the path can take to the range's end: the rest of it
    // at the highest velocity programmed from the front block on, at the
    // override the lift accepts (LIFT-8).
    const double covered = since_start_covered(path);
    const double rest = std::max(g.length - covered, 0.0);
    const size_t front = path.empty() ? g.end : path.front_index();
    const double v_programmed = g.v_ahead[std::min(front < g.start ? 0 : front - g.start, g.v_ahead.size() - 1)];
    const int32_t effective = std::min(override_value, cap_);
    const bool was_lowering = advanced_->lowering();
    const bool held = holds_path();
    // The path is faster than that while it brakes down to a lower override
    // (or a cap): until it is down, it reaches the end sooner (fuzz lift
    // seed 13005122: the override fell from 101.4 % to 1.1 %, Z landed a
    // cycle after the path had left the range). Its last cycle's mean
    // velocity bounds it from above while it brakes.
    const double v_now = covered_last_cycle_ ? std::max(covered - *covered_last_cycle_, 0.0) / dt : 0.0;
    covered_last_cycle_ = covered;
    const double v = std::max(v_programmed * effective / 1000.0, v_now);
    state_ = advanced_->step(v > 0 ? rest / v : std::numeric_limits<double>::infinity());
    if (advanced_->landed()) {
      landed_ = true;
      waits_for_landing_ = false;
      hold_position_ = g.command.pos;
    } else if (!advanced_->lowering()) {
      // Rising: a higher override only as far as the lift axis could still
      // land in time from where it is; lowering: none higher than at its start.
      const double room = 1000.0 * (rest - v * dt) / (v_programmed * (advanced_->landing_s() + 2 * dt));
      const double highest = machine_.override_max_percent * 10.0;
      const double accepted = std::min(std::isfinite(room) ? room : highest, highest);
      if (effective == 0 && override_value > 0 && accepted < 1) {
        // It rose while the path stood, and now not even 0.1 % lets it land
        // in time on what is left: it lands first, the path waits for it
        // (HLI_SC_WAIT_FOR_AXES); before, both waited for each other.
        advanced_->land_now();
        waits_for_landing_ = true;
      }
      cap_ = std::max(effective, static_cast<int32_t>(accepted));
    } else if (!was_lowering) {
      cap_ = effective;
    }
    changed = override_cap(override_value) != effective || holds_path() != held;
  } else {  // Lifting: over the path parameter q, at tau = q / v_plan
    const double q = std::clamp(since_start_covered(path), 0.0, g.length);
    const MotionState z = g.profile.at(q / g.v_plan);
    const double rate = path.path_velocity() / g.v_plan;
    state_ = MotionState{z.p, z.v * rate, z.a * rate * rate + z.v * path.path_acceleration() / g.v_plan, 0};
  }
  const size_t axis = static_cast<size_t>(g.command.axis);
  setpoints[axis] = AxisSetpoint{state_.p, state_.v, state_.a};
  return changed;
}

// The next range waiting; one a short cut runs through lands at once.
void Lift::start_pending(int32_t override_value) {
  if (pending_.empty()) return;
  const Pending next = pending_.front();
  pending_.pop_front();
  start(next.range, override_value, next.covered_at_start);
  if (next.land) land_at_once();
}

// Parked until the path takes the lift axis over from there (a next program).
void Lift::apply_parked(std::vector<AxisSetpoint>& setpoints) {
  if (parked_ && std::abs(setpoints[parked_axis_].position - parked_->position) <= tolerance::length_mm) parked_.reset();
  if (parked_) setpoints[parked_axis_] = *parked_;
}

bool Lift::holds_path() const {
  if (active_ && (positioning_ || waits_for_landing_)) return true;
  return std::any_of(pending_.begin(), pending_.end(), [&](const Pending& p) { return ranges_[p.range].positioning; });
}

int32_t Lift::override_cap(int32_t override_value) const {
  return active_ && advanced_ && !landed_ ? std::min(override_value, cap_) : override_value;
}

bool Lift::forbids_backward(size_t front_block) const {
  return std::any_of(ranges_.begin(), ranges_.end(), [&](const LiftRange& r) { return r.start <= front_block; });
}

bool Lift::active(size_t axis) const {
  if (!active_ || static_cast<size_t>(range().command.axis) != axis) return false;
  // A suppressed lift is active only where Advanced Lifting still moves the
  // axis to a POS programmed elsewhere (LIFT-7, the text's special case).
  return !range().suppressed || (machine_.lift_method == LiftMethod::time_based && range().command.pos != range().z0);
}

bool Lift::suppressed(size_t axis) const {
  return active_ && static_cast<size_t>(range().command.axis) == axis && range().suppressed;
}

}  // namespace hil::cnc
