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
  const std::vector<JerkPhase> phases{{j, ramp},      {0, settle},      {-j, 2 * ramp}, {0, 2 * settle + ramp},
                                      {j, 2 * ramp}, {0, settle},      {-j, ramp},     {0, settle}};
  return std::max(peak_under(drive, phases, 0), peak_under(drive, phases, 0.5));
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
