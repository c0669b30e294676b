#pragma once
// TRAPEZ's velocity change (velocity_change with SlopeType::trapez) reduced
// to where it ends, in closed form and generic in the number type: the
// same arithmetic, step for step, as building its phases and advancing
// through them, so that with double it is the same to the last bit (tested),
// and with Dual (values to round-off) it also gives the derivative along
// the drive the position planner's switch search steps with (issue 36
// item 3). Forced inline: there only the end position is used, and the
// rest of the arithmetic drops out.
#include <cmath>
#include <limits>

#include "dual.hpp"
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

template <typename T>
struct StateOf {
  T p{}, v{}, a{};
  double j = 0;
};

namespace trapez_detail {

template <typename T>
T abs_of(const T& x) {
  return value_of(x) < 0 ? T{} - x : x;
}
template <typename T>
T at_least_zero(const T& x) {
  return value_of(x) > 0 ? x : T{};
}

// advance() through a linear ramp from s.a to a_to at jerk j (a jump where
// it takes no time).
template <typename T>
[[gnu::always_inline]] inline void ramp(StateOf<T>& s, const T& a_to, double j) {
  const T duration = abs_of(a_to - s.a) / j;
  if (!(value_of(duration) > 0)) {
    s.a = a_to;
    s.j = 0;
    return;
  }
  const double jerk = std::copysign(j, value_of(a_to - s.a));
  s.p = s.p + duration * (s.v + duration * (s.a / 2 + duration * jerk / 6));
  s.v = s.v + duration * (s.a + duration * jerk / 2);
  s.a = a_to;
  s.j = jerk;
}

// advance() through a hold of acceleration a for `duration`.
template <typename T>
[[gnu::always_inline]] inline void hold(StateOf<T>& s, const T& duration, const T& a) {
  if (!(value_of(duration) > 0)) {
    s.a = a;
    s.j = 0;
    return;
  }
  s.p = s.p + duration * (s.v + duration * (s.a / 2 + duration * 0.0 / 6));
  s.v = s.v + duration * (s.a + duration * 0.0 / 2);
  s.a = a;
  s.j = 0;
}

}  // namespace trapez_detail

// The change from (v, a) to (v_target, 0): ramp a to sign * a_p, hold it
// t_hold, ramp back to 0; or, where ramping a straight to 0 lands on
// v_target to round-off, that ramp alone (just_unwind).
template <typename T>
struct TrapezChange {
  bool just_unwind = false;
  double sign = 1;
  T a_p{}, t_hold{};

  // From the start acceleration a (VelocityChange::duration to round-off).
  T duration(const T& a, double j) const {
    using trapez_detail::abs_of;
    if (just_unwind) return abs_of(a) / j;
    return abs_of(sign * a_p - a) / j + t_hold + a_p / j;
  }
};

template <typename T>
[[gnu::always_inline]] inline TrapezChange<T> plan_trapez_change(const T& v, const T& a, double v_target,
                                                                  const Limits& lim) {
  using namespace trapez_detail;
  using std::sqrt;
  const double j = lim.j;
  TrapezChange<T> change;
  const T v_ramp_down = v + a * abs_of(a) / (2 * j);
  const double round_off = 16 * std::numeric_limits<double>::epsilon() *
                           (lim.v + std::abs(value_of(v)) + std::abs(v_target) + std::abs(value_of(v_ramp_down - v)));
  if (std::abs(v_target - value_of(v_ramp_down)) <= round_off) {
    change.just_unwind = true;
    return change;
  }
  change.sign = value_of(v_ramp_down) < v_target ? 1.0 : -1.0;
  const T v0 = change.sign * v, a0 = change.sign * a;
  const T dv = change.sign * v_target - v0;
  // The plateau without hold (the start ramp and the closing one gain dv),
  // at most lim.a; from beyond lim.a the start ramp unwinds to it.
  T a_p = value_of(a0) <= 0 ? sqrt(at_least_zero(j * (dv + a0 * a0 / (2 * j))))
                            : sqrt(at_least_zero(j * dv + a0 * a0 / 2));
  if (!(value_of(a_p) < lim.a)) a_p = T{} + lim.a;
  const T start_gain = value_of(a0) <= 0 ? -a0 * a0 / (2 * j) + a_p * a_p / (2 * j)
                       : value_of(a_p) >= value_of(a0) ? (a_p * a_p - a0 * a0) / (2 * j)
                                                       : (a0 * a0 - a_p * a_p) / (2 * j);
  const T rest = dv - (start_gain + a_p * a_p / (2 * j));
  change.a_p = a_p;
  change.t_hold = value_of(a_p) > 0 ? at_least_zero(rest / a_p) : T{};
  return change;
}

// Where `change`, planned from s.v and s.a, ends.
template <typename T>
[[gnu::always_inline]] inline StateOf<T> trapez_change_end(StateOf<T> s, const TrapezChange<T>& change, double j) {
  if (change.just_unwind) {
    trapez_detail::ramp(s, T{}, j);
    return s;
  }
  trapez_detail::ramp(s, change.sign * change.a_p, j);
  trapez_detail::hold(s, change.t_hold, change.sign * change.a_p);
  trapez_detail::ramp(s, T{}, j);
  return s;
}

// velocity_change_end(s, v_target, lim, SlopeType::trapez).
template <typename T>
[[gnu::always_inline]] inline StateOf<T> trapez_change_end(const StateOf<T>& s, double v_target, const Limits& lim) {
  return trapez_change_end(s, plan_trapez_change(s.v, s.a, v_target, lim), lim.j);
}

inline StateOf<double> to_state_of(const MotionState& s) { return {s.p, s.v, s.a, s.j}; }

}  // namespace hil::cnc
