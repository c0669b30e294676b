#include "rest_to_rest.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hil::cnc {
namespace {

bool usable(double x) { return x > 0 && std::isfinite(x); }

}  // namespace

bool rest_to_rest_phases(double distance, const Limits& lim, SlopeType slope, PhaseList& out) {
  const bool step = slope == SlopeType::step;
  if (slope == SlopeType::sin2 || !std::isfinite(distance) || !usable(lim.v) || !usable(lim.a) ||
      !(step || usable(lim.j)))
    return false;
  const double dir = distance < 0 ? -1.0 : 1.0, L = std::abs(distance), v = lim.v, a = lim.a;
  const double j = step ? std::numeric_limits<double>::infinity() : lim.j;
  // The velocity change 0 -> v: ramps to the peak acceleration a_p and back
  // (of a_p / j each, none for STEP) and a plateau h; by symmetry it covers
  // v T / 2, so driving to v and stopping again covers v (2 a_p / j + h).
  const double a_p = step ? a : std::min(a, std::sqrt(j * v));
  const double h = step ? v / a : std::max(0.0, (v - a_p * a_p / j) / a_p);
  const double full = v * ((step ? 0.0 : 2 * a_p / j) + h);
  if (L >= full) {  // cruise at v_max in between
    out.push_back(linear_ramp(0, dir * a_p, j));
    out.push_back(hold(h, dir * a_p));
    out.push_back(linear_ramp(dir * a_p, 0, j));
    out.push_back(hold((L - full) / v, 0));
    out.push_back(linear_ramp(0, -dir * a_p, j));
    out.push_back(hold(h, -dir * a_p));
    out.push_back(linear_ramp(-dir * a_p, 0, j));
    return true;
  }
  if (!step && L * j * j <= 2 * a * a * a) {  // no plateau: four ramps of t = cbrt(L / 2j)
    const double peak = j * std::cbrt(L / (2 * j));
    out.push_back(linear_ramp(0, dir * peak, j));
    out.push_back(linear_ramp(dir * peak, -dir * peak, j));
    out.push_back(hold(0, -dir * peak));
    out.push_back(linear_ramp(-dir * peak, 0, j));
    return true;
  }
  // Plateaus of a: the peak velocity v_p solves L = v_p (v_p / a + a / j)
  // (STEP: L = v_p^2 / a), the plateaus last v_p / a - a / j.
  const double b = step ? 0.0 : a * a / j;
  const double v_p = 2 * a * L / (b + std::sqrt(b * b + 4 * a * L));
  const double plateau = std::max(0.0, (v_p - b) / a);
  out.push_back(linear_ramp(0, dir * a, j));
  out.push_back(hold(plateau, dir * a));
  out.push_back(linear_ramp(dir * a, -dir * a, j));
  out.push_back(hold(plateau, -dir * a));
  out.push_back(linear_ramp(-dir * a, 0, j));
  return true;
}

}  // namespace hil::cnc
