#include "position_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bisect.hpp"
#include "dual.hpp"
#include "trapez_change.hpp"
#include "rest_to_rest.hpp"
#include "velocity_profile.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

// On or before `target`, no faster than v_end but for round-off.
bool arrives_within(const MotionState& end, double target, double v_end) {
  return end.v <= v_end + tolerance::velocity_mm_s * (1 + v_end) && end.p <= target + tolerance::length_at(target);
}

class Planner {
 public:
  // v_end: the velocity to arrive with (a = 0); 0 for a target at rest.
  Planner(const MotionState& start, double target, double v_end, const Limits& lim, SlopeType slope,
          SwitchSearch search = SwitchSearch::fast)
      : start_{start.p, start.v, start.a, 0}, target_(target), v_end_(v_end), lim_(lim), slope_(slope),
        search_(search) {}

  // Either way along the axis, to rest on the target.
  MotionProfile to_rest() {
    if (closed_form_change()) {  // the phases only where they are the profile
      const TrapezChange<double> arrive = plan_trapez_change(start_.v, start_.a, v_end_, lim_);
      const double miss = trapez_change_end(to_state_of(start_), arrive, lim_.j).p - target_;
      if (is_round_off(miss, arrive.duration(start_.a, lim_.j)))
        return MotionProfile(start_, phases_of(velocity_change(start_.v, start_.a, v_end_, lim_, slope_)));
      return drive_and_arrive(miss < 0 ? 1.0 : -1.0, miss).profile;
    }
    const VelocityChange arrive = velocity_change(start_.v, start_.a, v_end_, lim_, slope_);
    const double miss = arrive.end(start_).p - target_;
    if (is_round_off(miss, arrive.duration())) return MotionProfile(start_, phases_of(arrive));
    return drive_and_arrive(miss < 0 ? 1.0 : -1.0, miss).profile;
  }

  // Forward only (along a path): if v_end cannot be reached within the
  // distance, arrive with the reachable velocity closest to it.
  BlockProfile forward() {
    const VelocityChange arrive = velocity_change(start_.v, start_.a, v_end_, lim_, slope_);
    const double miss = arrive.end(start_).p - target_;
    if (is_round_off(miss, arrive.duration()) || (miss > 0 && miss <= overshoot_tolerance()))
      return {MotionProfile(start_, phases_of(arrive)), Arrival::as_asked};
    if (miss < 0) return drive_and_arrive(1.0, miss);
    // v_end is the most the path may arrive with (a block transition's
    // limit). Arriving with a = 0, a lower velocity can need less way than
    // v_end (braking, the way to the end velocity is not monotone in it): if
    // one fits, arrive with the highest such one rather than faster than
    // v_end (KRN-3: override raised while the path accelerated towards a
    // line's end, v_end rose from 0.47 to 0.62 mm/s and became unreachable,
    // and it entered an arc of radius 0.058 mm at 7.3 mm/s).
    if (v_end_ > 0 && !lowered_) {
      auto fits = [&](double v) {
        return velocity_change_end(start_, v, lim_, slope_).p <= target_;
      };
      if (fits(0)) {
        Planner lower(start_, target_, last_fitting(0.0, v_end_, fits), lim_, slope_, search_);
        lower.lowered_ = true;
        BlockProfile lowered = lower.forward();
        if (lowered.arrival == Arrival::as_asked) lowered.arrival = Arrival::slower;
        return lowered;
      }
    }
    // SIN2 from a state inside a sin² pulse (a replan at a block transition,
    // while braking): a fresh pulse starts again at jerk 0 and can need more
    // way than the interrupted one had left, so that the path would arrive
    // too fast (KRN-3: 162,455 mm/s^2 when the setpoint then jumps onto the
    // end point). Linear ramps at the full jerk, the same limit, need the
    // least way: arrive with them.
    if (slope_ == SlopeType::sin2)
      return Planner(start_, target_, v_end_, lim_, SlopeType::trapez, search_).forward();
    return closest_reachable_arrival();
  }

 private:
  // A miss within round-off is no miss: the switch time grows with its
  // cube root, so chasing it would add microsecond wiggles to a profile
  // that is already right (and replanning along a profile would not
  // reproduce it).
  bool is_round_off(double miss, double t) const {
    const double round_off = 64 * std::numeric_limits<double>::epsilon() *
                             (std::abs(start_.p) + std::abs(target_) + (lim_.v + std::abs(start_.v)) * t +
                              std::abs(start_.a) * t * t);
    return std::abs(miss) <= round_off;
  }

  // Along a path, arriving with v_end a little beyond the end beats
  // arriving too fast: a stretch's v_end is the highest velocity from which
  // the next one can still be kept, to within 1e-12 (highest_entry_velocity),
  // and a state sampled from a plan over a long stretch carries that plan's
  // rounding (1e-13 mm over 500 mm). Treating such a miss as "v_end cannot
  // be reached" arrived a rounding faster, which the next short block could
  // no longer absorb: it arrived 1.9 mm/s fast at the program end (KRN-3).
  // 1 pm beyond the end is a setpoint jump of at most that much.
  double overshoot_tolerance() const {
    return tolerance::same_point_share * (1 + std::abs(start_.p) + std::abs(target_));
  }

  static PhaseList phases_of(const VelocityChange& change) {
    PhaseList phases;
    change.append_to(phases);
    return phases;
  }

  // Drive towards the target as hard as the limits allow and change to
  // v_end at the instant from which that change ends on the target. With
  // lim.v = 0 (feed hold) the drive is a stop short of the target.
  BlockProfile drive_and_arrive(double dir, double miss) {
    PhaseList phases;
    if (search_ == SwitchSearch::fast && start_.v == 0 && start_.a == 0 && v_end_ == 0 &&
        rest_to_rest_phases(target_ - start_.p, lim_, slope_, phases))
      return {MotionProfile(start_, phases), Arrival::as_asked};
    drive_ = velocity_change(start_.v, start_.a, dir * lim_.v, lim_, slope_);
    // Where the drive ends, and the overshoot from there with its slope
    // along the last phase (the closed form's; Newton starts from it).
    MotionState last_start = start_;
    for (int i = 0; i + 1 < drive_.count(); ++i)
      last_start = advance(last_start, drive_.phase(i), drive_.phase(i).duration);
    const Phase& last = drive_.phase(drive_.count() - 1);
    const MotionState driven = advance(last_start, last, last.duration);
    const Dual driven_overshoot = closed_form_change() && last.duration > 0
                                      ? overshoot_along(last_start, last, last.duration)
                                      : Dual{overshoot(driven), std::numeric_limits<double>::quiet_NaN()};
    const double miss_driven = driven_overshoot.x;
    if (dir * miss_driven <= 0) {
      drive_.append_to(phases);
      if (!(lim_.v > 0)) return {MotionProfile(start_, phases), Arrival::held};
      // The target is beyond the full drive: cruise, then arrive.
      phases.push_back(hold(-miss_driven / (dir * lim_.v), 0.0));
      velocity_change(driven.v, 0, v_end_, lim_, slope_).append_to(phases);
      return {MotionProfile(start_, phases), Arrival::as_asked};
    }
    MotionState s = start_;
    // SIN2 keeps the search over the whole drive: from a state inside a sin²
    // pulse the stop point need not rise monotonically along the drive
    // (forward to an end velocity, 5 of 82,198 random cases had a second root,
    // up to 1.5 % apart in duration), and the phase-wise search would take
    // another root than the one planned so far.
    if (search_ == SwitchSearch::reference || slope_ == SlopeType::sin2) {
      const double t_switch = find_switch_reference(miss, miss_driven);
      double left = t_switch;  // counted down: a sum of durations would drift past it
      for (int i = 0; i < drive_.count() && left > 0; ++i) {
        Phase ph = drive_.phase(i);
        if (ph.duration > left) {
          ph.duration = left;
          ph.a_end = advance(s, drive_.phase(i), left).a;
        }
        phases.push_back(ph);
        s = advance(s, ph, ph.duration);
        left -= ph.duration;
      }
    } else {
      const Switch at = find_switch(miss, driven_overshoot);
      for (int i = 0; i < at.phase; ++i) {
        phases.push_back(drive_.phase(i));
        s = advance(s, drive_.phase(i), drive_.phase(i).duration);
      }
      if (at.tau > 0) {
        Phase ph = drive_.phase(at.phase);
        if (ph.duration > at.tau) {
          ph.a_end = advance(s, ph, at.tau).a;
          ph.duration = at.tau;
        }
        phases.push_back(ph);
        s = advance(s, ph, ph.duration);
      }
    }
    velocity_change(s.v, s.a, v_end_, lim_, slope_).append_to(phases);
    return {MotionProfile(start_, phases), Arrival::as_asked};
  }

  // The end point of a change to v moves monotonically away from v_natural
  // (the velocity of ramping a straight to 0): bisect for the v whose change
  // ends on the target. If even ramping to a = 0 passes it, arrive with the
  // change that passes it least: braking (a < 0), ramping a to 0 covers more
  // way than braking on to v_end, so a miss by round-off (a state sampled
  // from a plan over a long stretch carries the stretch's rounding into the
  // short one after a block transition) must not turn into arriving at
  // v_natural far beyond the end (KRN-3: a last block of 0.05 mm entered
  // at 7 mm/s braking, left at 4.8 mm/s, and the setpoint jumped onto the
  // program's end point).
  //
  // The arrival keeps v_end where it is slower on the target (accelerating,
  // v_natural below v_end); else it is too fast.
  BlockProfile closest_reachable_arrival() const {
    const double v_natural = std::max(0.0, velocity_after_ramp_to_zero(start_.v, start_.a, lim_, slope_));
    auto change_to = [&](double v) { return velocity_change(start_.v, start_.a, v, lim_, slope_); };
    const VelocityChange natural = change_to(v_natural);
    const double natural_end = natural.end(start_).p;
    VelocityChange closest = natural;
    if (natural_end >= target_) {
      const VelocityChange to_v_end = change_to(v_end_);
      if (to_v_end.end(start_).p < natural_end) closest = to_v_end;
    } else {  // v_natural ends before the target, v_end beyond it
      closest = change_to(last_fitting(v_natural, v_end_, [&](double v) { return change_to(v).end(start_).p <= target_; }));
    }
    const bool kept = arrives_within(closest.end(start_), target_, v_end_);
    return {MotionProfile(start_, phases_of(closest)), kept ? Arrival::slower : Arrival::too_fast};
  }

 private:
  // Where the fastest change to v_end from `s` ends, relative to the target.
  double overshoot(const MotionState& s) const {
    return velocity_change_end(s, v_end_, lim_, slope_).p - target_;
  }

  // The switch from the drive to the arrival: `tau` into drive phase `phase`.
  struct Switch {
    int phase = 0;
    double tau = 0;
  };

  // The overshoot rises monotonically along the drive from f0 to f1 (of
  // opposite signs; TRAPEZ knows f1's slope along the last phase). The
  // drive phase in which it changes sign is found from its values at the
  // phase ends; within the phase it is smooth. It stops at a zero, at a
  // bracket of adjacent doubles, or at an overshoot 1/64 of what
  // is_round_off accepts (the noise of evaluating it).
  Switch find_switch(double f0, const Dual& driven_overshoot) const {
    const double f_tol = std::numeric_limits<double>::epsilon() *
                         (std::abs(start_.p) + std::abs(target_) + (lim_.v + std::abs(start_.v)) * drive_.duration() +
                          std::abs(start_.a) * drive_.duration() * drive_.duration());
    const double f1 = driven_overshoot.x;
    Bracket b{0, 0, f0, f1, f_tol, f1 > 0};  // its hi: the phase's duration, once the phase is known
    double slope_hi = driven_overshoot.d;    // at the phase's end, where known
    // The phase: the first whose end is beyond the target.
    int phase = drive_.count() - 1;
    MotionState s = start_;
    for (int i = 0; i + 1 < drive_.count(); ++i) {
      const Phase& ph = drive_.phase(i);
      const MotionState e = advance(s, ph, ph.duration);
      if (ph.duration > 0) {
        const Dual f = closed_form_change() ? overshoot_along(s, ph, ph.duration)
                                            : Dual{overshoot(e), std::numeric_limits<double>::quiet_NaN()};
        if (f.x == 0 || std::abs(f.x) <= f_tol) return {i, ph.duration};
        if (b.beyond(f.x)) {
          phase = i;
          b.f_hi = f.x;
          slope_hi = f.d;
          break;
        }
        b.f_lo = f.x;
      }
      s = e;
    }
    const Phase& ph = drive_.phase(phase);
    b.hi = ph.duration;
    if (!closed_form_change()) return {phase, regula_falsi_within(s, ph, b)};
    return {phase, newton_within(s, ph, b, slope_hi)};
  }

  // The switch lies in [lo, hi] of a drive phase, the overshoot f_lo, f_hi there.
  struct Bracket {
    double lo, hi, f_lo, f_hi, f_tol;
    bool rising;
    bool beyond(double f) const { return (f > 0) == rising; }
    double closer() const { return std::abs(f_lo) <= std::abs(f_hi) ? lo : hi; }
  };

  // TRAPEZ has its velocity change in closed form (trapez_change_end).
  bool closed_form_change() const { return slope_ == SlopeType::trapez && std::isfinite(lim_.j); }

  // Where the change to v_end from `tau` into drive phase `ph` (begun in s)
  // ends, less the target, and its derivative in tau.
  Dual overshoot_along(const MotionState& s, const Phase& ph, double tau) const {
    const Dual t{tau, 1};
    // As advance(): at the phase's end its end acceleration exactly.
    const Dual a = tau >= ph.duration ? Dual{ph.a_end, ph.jerk} : s.a + t * ph.jerk;
    const StateOf<Dual> driven{s.p + t * (s.v + t * (s.a / 2 + t * ph.jerk / 6)), s.v + t * (s.a + t * ph.jerk / 2), a,
                               ph.jerk};
    return trapez_change_end(driven, v_end_, lim_).p - target_;
  }

  // Steps to the root of the parabola through the last two points, with
  // the slope the closed form gives at the newer one (Dual), kept in the
  // bracket: where a step would leave it or not halve the step before the
  // last, the middle instead. The first step is from the bracket's end,
  // whose slope the phase search evaluated along with its value. From
  // random states 3.0 evaluations per search where regula falsi took 8.9
  // (issue 36 item 3).
  double newton_within(const MotionState& s, const Phase& ph, Bracket b, double slope_hi) const {
    // The root next to tau of the parabola with f's value and slope there
    // and its value at tau_before (f + f' x + c x^2, c d^2 = curve), in the
    // form that does not cancel and has one division; where it has none,
    // the tangent's.
    auto parabola_root = [](double tau, const Dual& f, double tau_before, double f_before) {
      const double d = std::abs(tau_before - tau), f_d = f.d * d;
      const double curve = f_before - f.x - f.d * (tau_before - tau);
      const double disc = f_d * f_d - 4 * f.x * curve;
      const double root = disc >= 0 && f.d != 0 ? tau - 2 * f.x * d / (f_d + std::copysign(std::sqrt(disc), f_d))
                                                 : tau - f.x / f.d;
      return std::isfinite(root) ? root : tau - f.x / f.d;
    };
    // From the bracket's end with its slope where known, else regula falsi.
    double tau = std::isfinite(slope_hi) ? parabola_root(b.hi, Dual{b.f_hi, slope_hi}, b.lo, b.f_lo)
                                         : (b.lo * b.f_hi - b.hi * b.f_lo) / (b.f_hi - b.f_lo);
    double step_before = b.hi - b.lo, step = step_before;
    double tau_before = b.lo, f_before = b.f_lo;
    for (int iteration = 0; iteration < 200; ++iteration) {
      if (!(tau > b.lo && tau < b.hi)) tau = b.lo + (b.hi - b.lo) / 2;
      if (!(tau > b.lo && tau < b.hi)) break;  // the bracket is down to adjacent doubles
      const Dual f = overshoot_along(s, ph, tau);
      if (f.x == 0 || std::abs(f.x) <= b.f_tol) return tau;
      (b.beyond(f.x) ? b.hi : b.lo) = tau;
      (b.beyond(f.x) ? b.f_hi : b.f_lo) = f.x;
      const double next = parabola_root(tau, f, tau_before, f_before);
      tau_before = tau;
      f_before = f.x;
      // That step unless it leaves the bracket or would not halve the step
      // before the last; else the middle (so also from where f is flat, the
      // drive running along the arrival's own first ramp).
      step_before = step;
      if (next > b.lo && next < b.hi && 2 * std::abs(next - tau) <= std::abs(step_before)) {
        step = next - tau;
        tau = next;
      } else {
        step = (b.hi - b.lo) / 2;
        tau = b.lo + step;
      }
    }
    return b.closer();
  }

  // Anderson-Bjoerck regula falsi (a bisection step wherever the bracket
  // did not halve in three) converges superlinearly.
  double regula_falsi_within(const MotionState& s, const Phase& ph, Bracket b) const {
    double g_lo = b.f_lo, g_hi = b.f_hi;  // f_lo, f_hi scaled down where a side was kept
    double width_before = b.hi - b.lo;
    int side = 0;  // the side replaced last: -1 lo, 1 hi
    for (int iteration = 0; iteration < 200; ++iteration) {
      double tau = (b.lo * g_hi - b.hi * g_lo) / (g_hi - g_lo);
      if (iteration % 3 == 2) {
        if (b.hi - b.lo > width_before / 2) tau = b.lo + (b.hi - b.lo) / 2;
        width_before = b.hi - b.lo;
      }
      if (!(tau > b.lo && tau < b.hi)) tau = b.lo + (b.hi - b.lo) / 2;
      if (!(tau > b.lo && tau < b.hi)) break;  // the bracket is down to adjacent doubles
      const double f = overshoot(advance(s, ph, tau));
      if (f == 0 || std::abs(f) <= b.f_tol) return tau;
      if (b.beyond(f)) {
        if (side == 1) {  // lo kept twice: pull its weight down
          const double m = 1 - f / b.f_hi;
          g_lo *= m > 0 ? m : 0.5;
        }
        b.hi = tau;
        b.f_hi = g_hi = f;
        side = 1;
      } else {
        if (side == -1) {
          const double m = 1 - f / b.f_lo;
          g_hi *= m > 0 ? m : 0.5;
        }
        b.lo = tau;
        b.f_lo = g_lo = f;
        side = -1;
      }
    }
    return b.closer();
  }

  MotionState driven_for(double t) const {
    MotionState s = start_;
    for (int i = 0; i < drive_.count(); ++i) {
      const double d = drive_.phase(i).duration;
      if (t <= d) return advance(s, drive_.phase(i), t);
      s = advance(s, drive_.phase(i), d);
      t -= d;
    }
    return s;
  }

  // The solver before issue 17, the reference its fast paths are tested
  // against: Illinois regula falsi with a bisection every fourth step, over
  // the whole drive, down to adjacent doubles.
  double find_switch_reference(double f0, double f1) const {
    double lo = 0, hi = drive_.duration();
    double f_lo = f0, f_hi = f1;  // the true values; f0 and f1 get halved
    int side = 0;
    for (int iteration = 0; iteration < 200; ++iteration) {
      double t = (iteration % 4 == 3) ? (lo + hi) / 2 : (lo * f1 - hi * f0) / (f1 - f0);
      if (!(t > lo && t < hi)) t = (lo + hi) / 2;
      if (!(t > lo && t < hi)) break;  // the bracket is down to adjacent doubles
      const double f = overshoot(driven_for(t));
      if (f == 0) return t;
      if ((f > 0) == (f1 > 0)) {
        hi = t;
        f_hi = f1 = f;
        if (side == 1) f0 /= 2;
        side = 1;
      } else {
        lo = t;
        f_lo = f0 = f;
        if (side == -1) f1 /= 2;
        side = -1;
      }
    }
    return std::abs(f_lo) <= std::abs(f_hi) ? lo : hi;
  }

  MotionState start_;
  double target_;
  double v_end_;
  bool lowered_ = false;  // v_end_ already lowered to one that fits
  Limits lim_;
  SlopeType slope_;
  SwitchSearch search_;
  VelocityChange drive_;
};

}  // namespace

MotionProfile position_profile(const MotionState& start, double target, const Limits& lim, SlopeType slope,
                               SwitchSearch search) {
  return Planner(start, target, 0.0, lim, slope, search).to_rest();
}

BlockProfile block_profile(const MotionState& start, double end_position, double end_velocity, const Limits& lim,
                           SlopeType slope, SwitchSearch search) {
  BlockProfile planned = Planner(start, end_position, std::clamp(end_velocity, 0.0, lim.v), lim, slope, search).forward();
  // Faster than lim.v (the cruise velocity, lowered by the override while
  // the path moved faster) but not than end_velocity keeps what the block
  // transition allows.
  if (planned.arrival == Arrival::too_fast && end_velocity > lim.v &&
      arrives_within(planned.profile.end(), end_position, end_velocity))
    planned.arrival = Arrival::slower;
  return planned;
}

MotionProfile rest_to_rest(double distance, const Limits& lim, SlopeType slope) {
  return position_profile(MotionState{}, distance, lim, slope);
}

}  // namespace hil::cnc
