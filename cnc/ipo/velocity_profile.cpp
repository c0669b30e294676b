#include "velocity_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "trapez_change.hpp"

namespace hil::cnc {
namespace {

// A ramp the change plans: a sin² pulse for SIN2.
Phase ramp(double a_from, double a_to, const Limits& lim, SlopeType slope) {
  if (slope == SlopeType::sin2 && a_to != a_from) return sin2_ramp(a_from, a_to, lim.j);
  return linear_ramp(a_from, a_to, slope == SlopeType::step ? std::numeric_limits<double>::infinity() : lim.j);
}

// The start acceleration brought back towards 0 (see unwind_rate).
Phase unwind(double a_from, double a_to, const Limits& lim, SlopeType slope) {
  return linear_ramp(a_from, a_to, unwind_rate(lim, slope));
}

// The plateau a_p >= 0 of a rising change by dv from a start acceleration
// a0 without hold: the start ramp a0 -> a_p (unwinding while |a| shrinks)
// plus the closing ramp a_p -> 0 gain dv.
double plateau_without_hold(double a0, double dv, double rate, double unwind_rate) {
  if (a0 <= 0) return std::sqrt(std::max(0.0, rate * (dv + a0 * a0 / (2 * unwind_rate))));
  const double rising = std::sqrt(std::max(0.0, rate * dv + a0 * a0 / 2));
  if (rising >= a0 || !(unwind_rate > rate)) return rising;
  // (a0² - a_p²) / (2 unwind) + a_p² / (2 rate) = dv
  return std::sqrt(std::max(0.0, (dv - a0 * a0 / (2 * unwind_rate)) / (1 / (2 * rate) - 1 / (2 * unwind_rate))));
}

// Velocity gained by the start ramp a0 -> a_p (a_p >= 0).
double start_ramp_gain(double a0, double a_p, double rate, double unwind_rate) {
  if (a0 <= 0) return -a0 * a0 / (2 * unwind_rate) + a_p * a_p / (2 * rate);
  if (a_p >= a0) return (a_p * a_p - a0 * a0) / (2 * rate);
  return (a0 * a0 - a_p * a_p) / (2 * unwind_rate);
}

}  // namespace

double VelocityChange::duration() const {
  double t = 0;
  for (const Phase& ph : phases) t += ph.duration;
  return t;
}

MotionState VelocityChange::end(const MotionState& s) const {
  MotionState x = s;
  for (const Phase& ph : phases) x = advance(x, ph, ph.duration);
  return x;
}

void VelocityChange::append_to(PhaseList& out) const {
  for (const Phase& ph : phases) out.push_back(ph);
}

namespace {

// The phases of the change, one by one into `emit`: kept apart from where
// they go, so that the end state of a change (what the position planner's
// search evaluates) is computed by the same arithmetic without storing them.
template <typename Emit>
void plan_change(double v, double a, double v_target, const Limits& lim, SlopeType slope, Emit&& emit) {
  const double rate = ramp_rate(lim, slope), unwinding = unwind_rate(lim, slope);
  // Solve the rising case; a falling change is its mirror image.
  const double v_ramp_down = velocity_after_ramp_to_zero(v, a, lim, slope);
  // Ramping straight to a = 0 lands on v_target to round-off: any plateau
  // found beyond that would be the square root of noise.
  const double round_off = 16 * std::numeric_limits<double>::epsilon() *
                           (lim.v + std::abs(v) + std::abs(v_target) + std::abs(v_ramp_down - v));
  if (std::abs(v_target - v_ramp_down) <= round_off) {
    emit(unwind(a, 0.0, lim, slope));
    return;
  }
  const double sign = v_ramp_down < v_target ? 1.0 : -1.0;
  const double v0 = sign * v, a0 = sign * a, vt = sign * v_target;

  // Plateau a_p: reach it, hold it, ramp back to 0. From outside the limit
  // (a0 > lim.a) this comes back to it first.
  double a_p = lim.a;
  if (!std::isinf(rate)) a_p = std::min(lim.a, plateau_without_hold(a0, vt - v0, rate, unwinding));
  double dv = vt - v0;
  if (!std::isinf(rate)) dv -= start_ramp_gain(a0, a_p, rate, unwinding) + a_p * a_p / (2 * rate);
  const double t_hold = a_p > 0 ? std::max(0.0, dv / a_p) : 0.0;

  if (a0 < 0 && slope == SlopeType::sin2) {  // the wrong way: unwind, then a fresh pulse
    emit(unwind(a, 0.0, lim, slope));
    emit(ramp(0.0, sign * a_p, lim, slope));
  } else if (a_p < a0) {
    emit(unwind(a, sign * a_p, lim, slope));
  } else {
    emit(ramp(a, sign * a_p, lim, slope));
  }
  emit(hold(t_hold, sign * a_p));
  emit(ramp(sign * a_p, 0.0, lim, slope));
}

}  // namespace

VelocityChange velocity_change(double v, double a, double v_target, const Limits& lim, SlopeType slope) {
  VelocityChange change;
  if (slope == SlopeType::trapez && std::isfinite(lim.j)) {  // the same phases, without the slope types' cases
    const TrapezChange<double> trapez = plan_trapez_change(v, a, v_target, lim);
    if (trapez.just_unwind) {
      change.phases.push_back(linear_ramp(a, 0.0, lim.j));
      return change;
    }
    const double a_p = trapez.sign * trapez.a_p;
    change.phases.push_back(linear_ramp(a, a_p, lim.j));
    change.phases.push_back(hold(trapez.t_hold, a_p));
    change.phases.push_back(linear_ramp(a_p, 0.0, lim.j));
    return change;
  }
  return velocity_change_reference(v, a, v_target, lim, slope);
}

VelocityChange velocity_change_reference(double v, double a, double v_target, const Limits& lim, SlopeType slope) {
  VelocityChange change;
  plan_change(v, a, v_target, lim, slope, [&](const Phase& ph) { change.phases.push_back(ph); });
  return change;
}

MotionState velocity_change_end(const MotionState& s, double v_target, const Limits& lim, SlopeType slope) {
  if (slope == SlopeType::trapez && std::isfinite(lim.j)) {
    const StateOf<double> end = trapez_change_end(to_state_of(s), v_target, lim);
    return {end.p, end.v, end.a, end.j};
  }
  MotionState x = s;
  plan_change(s.v, s.a, v_target, lim, slope, [&](const Phase& ph) { x = advance(x, ph, ph.duration); });
  return x;
}

MotionProfile velocity_profile(const MotionState& start, double v_target, const Limits& lim, SlopeType slope) {
  const double vt = std::clamp(v_target, -lim.v, lim.v);
  PhaseList phases;
  velocity_change(start.v, start.a, vt, lim, slope).append_to(phases);
  MotionState s = start;
  s.j = 0;
  return MotionProfile(s, phases);
}

}  // namespace hil::cnc
