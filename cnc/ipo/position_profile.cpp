#include "position_profile.hpp"

#include <cmath>
#include <limits>

#include "velocity_profile.hpp"

namespace hil::cnc {
namespace {

class Planner {
 public:
  Planner(const MotionState& start, double target, const Limits& lim, SlopeType slope)
      : start_{start.p, start.v, start.a, 0}, target_(target), lim_(lim), slope_(slope) {}

  MotionProfile plan() {
    const VelocityChange brake = velocity_change(start_.v, start_.a, 0, lim_, slope_);
    const double miss = brake.end(start_).p - target_;
    std::vector<Phase> phases;
    // A miss within round-off is no miss: the switch time grows with its
    // cube root, so chasing it would add microsecond wiggles to a profile
    // that is already right (and replanning along a profile would not
    // reproduce it).
    const double t_brake = brake.duration();
    const double round_off = 64 * std::numeric_limits<double>::epsilon() *
                             (std::abs(start_.p) + std::abs(target_) + (lim_.v + std::abs(start_.v)) * t_brake +
                              std::abs(start_.a) * t_brake * t_brake);
    if (std::abs(miss) <= round_off) {
      brake.append_to(phases);
      return MotionProfile(start_, phases);
    }
    const double dir = miss < 0 ? 1.0 : -1.0;
    drive_ = velocity_change(start_.v, start_.a, dir * lim_.v, lim_, slope_);
    const MotionState driven = drive_.end(start_);
    const double miss_driven = overshoot(driven);
    if (dir * miss_driven <= 0) {
      // The target is beyond the full drive: cruise at v_max, then brake.
      drive_.append_to(phases);
      phases.push_back(hold(-miss_driven / (dir * lim_.v), 0.0));
      velocity_change(driven.v, 0, 0, lim_, slope_).append_to(phases);
      return MotionProfile(start_, phases);
    }
    const double t_switch = find_switch(miss, miss_driven);
    MotionState s = start_;
    double left = t_switch;  // counted down: a sum of durations would drift past it
    for (int i = 0; i < drive_.count && left > 0; ++i) {
      Phase ph = drive_.phases[i];
      if (ph.duration > left) {
        ph.duration = left;
        ph.a_end = advance(s, drive_.phases[i], left).a;
      }
      phases.push_back(ph);
      s = advance(s, ph, ph.duration);
      left -= ph.duration;
    }
    velocity_change(s.v, s.a, 0, lim_, slope_).append_to(phases);
    return MotionProfile(start_, phases);
  }

 private:
  // Where the fastest stop from `s` ends, relative to the target.
  double overshoot(const MotionState& s) const {
    return velocity_change(s.v, s.a, 0, lim_, slope_).end(s).p - target_;
  }

  MotionState driven_for(double t) const {
    MotionState s = start_;
    for (int i = 0; i < drive_.count; ++i) {
      const double d = drive_.phases[i].duration;
      if (t <= d) return advance(s, drive_.phases[i], t);
      s = advance(s, drive_.phases[i], d);
      t -= d;
    }
    return s;
  }

  // The overshoot rises monotonically along the drive from f0 to f1 (of
  // opposite signs): Illinois regula falsi with bisection steps.
  double find_switch(double f0, double f1) const {
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
  Limits lim_;
  SlopeType slope_;
  VelocityChange drive_;
};

}  // namespace

MotionProfile position_profile(const MotionState& start, double target, const Limits& lim, SlopeType slope) {
  return Planner(start, target, lim, slope).plan();
}

MotionProfile rest_to_rest(double distance, const Limits& lim, SlopeType slope) {
  return position_profile(MotionState{}, distance, lim, slope);
}

}  // namespace hil::cnc
