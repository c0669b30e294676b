#include "drive_response.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hil::axis {
namespace {

struct JerkPhase {
  double jerk;      // mm/s^3
  double duration;  // s
};

// The drive's peak |acceleration| under the command of `phases` from rest,
// sampled every cycle from `offset` (0 .. 1 cycles) into the first phase.
double peak_under(const DriveParameters& drive, const std::vector<JerkPhase>& phases, double offset) {
  DriveModel model(drive, 0);
  const double dt = drive.cycle_time_s;
  double p = 0, v = 0, a = 0, t_phase = offset * dt, peak = 0;
  size_t i = 0;
  // The exact cubic over one cycle, across phase boundaries.
  auto advance = [&](double h) {
    while (h > 0 && i < phases.size()) {
      const double left = phases[i].duration - t_phase;
      const double step = std::min(h, left);
      const double jj = phases[i].jerk;
      p += v * step + a * step * step / 2 + jj * step * step * step / 6;
      v += a * step + jj * step * step / 2;
      a += jj * step;
      h -= step;
      t_phase += step;
      if (t_phase >= phases[i].duration) {
        ++i;
        t_phase = 0;
      }
    }
    p += v * h + a * h * h / 2;  // past the last phase: on at a (0 there)
    v += a * h;
  };
  advance(0);
  while (i < phases.size()) {
    advance(dt);
    peak = std::max(peak, std::abs(model.step(p, v).acceleration));
  }
  return peak;
}

}  // namespace

double peak_actual_acceleration(const DriveParameters& drive, double a, double j) {
  if (!(a > 0) || !(j > 0)) return 0;
  // Long enough for the loop to settle after each change of the jerk.
  const double settle = std::max(0.05, 20 * drive.velocity_lag_s + (drive.kv > 0 ? 5 / drive.kv : 0.2));
  const double ramp = a / j;
  // The -a plateau reverses the velocity halfway.
  const std::vector<JerkPhase> plateaus{{j, ramp},     {0, settle}, {-j, 2 * ramp}, {0, 2 * settle + ramp},
                                        {j, 2 * ramp}, {0, settle}, {-j, ramp},     {0, settle}};
  // Without plateaus (a short lift's up and down): at the tips the jerk
  // steps by 2 j, not j, and the overshoot with it.
  const std::vector<JerkPhase> tips{{j, ramp}, {-j, 2 * ramp}, {j, 2 * ramp}, {-j, ramp}, {0, settle}};
  double peak = 0;
  auto take = [&](const std::vector<JerkPhase>& phases) {
    for (const double offset : {0.0, 0.5}) peak = std::max(peak, peak_under(drive, phases, offset));
  };
  take(plateaus);
  take(tips);
  // The velocity reversing (friction flipping) as a ramp to -a ends, or
  // shortly before or after: both transients add (fuzz lift 40200958 and
  // 40211326 on other machines, --vary-machine: the reversal 4 cycles before
  // the ramp's end, the actual acceleration 7.2 % over the command and 0.2 %
  // over P-AXIS-00442's limit).
  // Reversal at f ramps into the ramp; the velocity for it comes from a
  // pulse of +a' and back (a' <= a).
  for (const double f : {0.5, 0.75, 0.9, 1.0, 1.1, 1.25, 1.5}) {
    const double v0 = f <= 1 ? j * f * f * ramp * ramp / 2 : j * ramp * ramp / 2 + a * (f - 1) * ramp;
    const double pulse = std::sqrt(v0 / j);
    take({{j, pulse}, {-j, pulse}, {-j, ramp}, {0, settle}, {j, ramp}, {0, settle}});
  }
  return peak;
}

double largest_followed_acceleration(const DriveParameters& drive, double limit, double j) {
  const double target = limit * (1 - followed_acceleration_reserve);
  if (peak_actual_acceleration(drive, limit, j) <= target) return limit;
  double ok = 0, too_high = limit;
  for (int i = 0; i < 40 && too_high - ok > 1e-6 * limit; ++i) {
    const double mid = 0.5 * (ok + too_high);
    (peak_actual_acceleration(drive, mid, j) <= target ? ok : too_high) = mid;
  }
  return ok;
}

}  // namespace hil::axis
