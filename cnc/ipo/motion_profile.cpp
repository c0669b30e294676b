#include "motion_profile.hpp"
#include "tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hil::cnc {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double two_pi = 2 * pi;

// The sin² ramp's acceleration shape and its first two integrals over u.
double g0(double u) { return u - std::sin(two_pi * u) / two_pi; }
double g1(double u) { return u * u / 2 + std::cos(two_pi * u) / (two_pi * two_pi); }
double g2(double u) { return u * u * u / 6 + std::sin(two_pi * u) / (two_pi * two_pi * two_pi); }

}  // namespace

MotionState advance_sin2(const MotionState& s, const Phase& ph, double tau) {
  const double T = ph.ramp_time, da = ph.ramp_delta_a, u0 = ph.u0, u = u0 + tau / T;
  const double base = s.a - da * g0(u0);
  MotionState r;
  r.a = base + da * g0(u);
  r.v = s.v + base * tau + da * T * (g1(u) - g1(u0));
  r.p = s.p + s.v * tau + base * tau * tau / 2 + da * T * T * (g2(u) - g2(u0) - g1(u0) * (u - u0));
  r.j = da / T * (1 - std::cos(two_pi * u));
  return r;
}

Phase sin2_ramp(double a_from, double a_to, double peak_jerk) {
  Phase ph;
  ph.shape = Phase::Shape::sin2;
  // Peak of da/T (1 - cos) is 2 da / T.
  ph.duration = ph.ramp_time = 2 * std::abs(a_to - a_from) / peak_jerk;
  ph.ramp_delta_a = a_to - a_from;
  ph.a_end = a_to;
  return ph;
}

MotionProfile::MotionProfile(MotionState start, const PhaseList& phases) : phases_(phases), start_(start) {
  MotionState state = start;
  double time = 0;
  double v_scale = std::abs(start_.v);
  for (std::size_t i = 0; i < phases_.size(); ++i) {
    const Phase& ph = phases_[i];
    starts_.push_back(state);
    times_.push_back(time);
    v_scale = std::max(v_scale, std::abs(state.v));
    state = advance(state, ph, ph.duration);
    time += ph.duration;
  }
  state.j = 0;
  end_ = state;
  duration_ = time;
  moving_at_end_ = std::abs(end_.v) > tolerance::limit_share * v_scale;
}

MotionState MotionProfile::at(double t) const {
  if (!(t < duration_) || phases_.empty()) {
    MotionState s = end_;
    if (t > duration_ && std::isfinite(t) && moving_at_end_) s.p += end_.v * (t - duration_);
    return s;
  }
  t = std::max(t, 0.0);
  // The last phase starting at or before t: it lasts past t, and jumps of
  // zero duration at t are already in its start state.
  const size_t i = static_cast<size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
  return advance(starts_[i], phases_[i], t - times_[i]);
}

}  // namespace hil::cnc
