#include "velocity_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hil::cnc {
namespace {

Phase ramp(double a_from, double a_to, const Limits& lim, SlopeType slope) {
  if (slope == SlopeType::sin2 && a_to != a_from) return sin2_ramp(a_from, a_to, lim.j);
  return linear_ramp(a_from, a_to, slope == SlopeType::step ? std::numeric_limits<double>::infinity() : lim.j);
}

}  // namespace

double VelocityChange::duration() const {
  double t = 0;
  for (int i = 0; i < count; ++i) t += phases[i].duration;
  return t;
}

MotionState VelocityChange::end(const MotionState& s) const {
  MotionState x = s;
  for (int i = 0; i < count; ++i) x = advance(x, phases[i], phases[i].duration);
  return x;
}

void VelocityChange::append_to(std::vector<Phase>& out) const {
  for (int i = 0; i < count; ++i) out.push_back(phases[i]);
}

VelocityChange velocity_change(double v, double a, double v_target, const Limits& lim, SlopeType slope) {
  const double rate = ramp_rate(lim, slope);
  // Solve the rising case; a falling change is its mirror image.
  const double v_ramp_down = velocity_after_ramp_to_zero(v, a, lim, slope);
  VelocityChange change;
  // Ramping straight to a = 0 lands on v_target to round-off: any plateau
  // found beyond that would be the square root of noise.
  const double round_off = 16 * std::numeric_limits<double>::epsilon() *
                           (lim.v + std::abs(v) + std::abs(v_target) + std::abs(v_ramp_down - v));
  if (std::abs(v_target - v_ramp_down) <= round_off) {
    change.phases[change.count++] = ramp(a, 0.0, lim, slope);
    return change;
  }
  const double sign = v_ramp_down < v_target ? 1.0 : -1.0;
  const double v0 = sign * v, a0 = sign * a, vt = sign * v_target;

  // Plateau a_p: rise to it, hold, ramp to 0. Without a hold,
  // (2 a_p² - a0²) / (2 rate) = vt - v0.
  double a_p = lim.a;
  if (!std::isinf(rate)) {
    const double free = std::sqrt(std::max(0.0, rate * (vt - v0) + a0 * a0 / 2));
    if (free < lim.a) a_p = free;
  }
  if (a0 > lim.a) a_p = lim.a;  // outside the limit: come back to it first
  double dv = vt - v0;
  if (!std::isinf(rate)) dv -= ((a0 + a_p) * std::abs(a_p - a0) + a_p * a_p) / (2 * rate);
  const double t_hold = a_p > 0 ? std::max(0.0, dv / a_p) : 0.0;

  // A SIN2 ramp through a = 0 is two pulses, so the velocity never moves
  // further the wrong way than a direct ramp to 0 would take it.
  double a_from = a;
  if (slope == SlopeType::sin2 && a0 < 0 && a_p > 0) {
    change.phases[change.count++] = ramp(a, 0.0, lim, slope);
    a_from = 0;
  }
  change.phases[change.count++] = ramp(a_from, sign * a_p, lim, slope);
  change.phases[change.count++] = hold(t_hold, sign * a_p);
  change.phases[change.count++] = ramp(sign * a_p, 0.0, lim, slope);
  return change;
}

MotionProfile velocity_profile(const MotionState& start, double v_target, const Limits& lim, SlopeType slope) {
  const double vt = std::clamp(v_target, -lim.v, lim.v);
  std::vector<Phase> phases;
  velocity_change(start.v, start.a, vt, lim, slope).append_to(phases);
  MotionState s = start;
  s.j = 0;
  return MotionProfile(s, phases);
}

}  // namespace hil::cnc
