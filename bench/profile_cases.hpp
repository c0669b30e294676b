#pragma once
// Seeded 1-D positioning cases of the profile benchmark (issue 17, KRN-3),
// per family: random moves from rest, moves on which a_max or v_max is just
// reached, and random initial states. SI units; limits v in [0.01, 1] m/s,
// a in [0.1, 31.6] m/s², j in [1, 3162] m/s³, positions in ±20 mm.
#include <cmath>
#include <random>
#include <vector>

#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::bench {

struct ProfileCase {
  cnc::MotionState start;
  double target = 0;
  cnc::Limits lim;
};

enum class CaseFamily { random_from_rest, a_max_boundary, v_max_boundary, random_state };

inline const char* to_string(CaseFamily family) {
  switch (family) {
    case CaseFamily::random_from_rest: return "random from rest";
    case CaseFamily::a_max_boundary: return "a_max boundary";
    case CaseFamily::v_max_boundary: return "v_max boundary";
    case CaseFamily::random_state: return "random initial state";
  }
  return "?";
}

// Rest-to-rest distance at which a_max is just reached (0 where v_max comes
// first), and the one at which v_max is just reached (TRAPEZ).
inline double a_max_edge(const cnc::Limits& lim) {
  return lim.v * lim.j >= lim.a * lim.a ? 2 * lim.a * lim.a * lim.a / (lim.j * lim.j) : 0.0;
}
inline double v_max_edge(const cnc::Limits& lim) {
  return lim.v * lim.j >= lim.a * lim.a ? lim.v * (lim.v / lim.a + lim.a / lim.j)
                                        : 2 * lim.v * std::sqrt(lim.v / lim.j);
}

inline std::vector<ProfileCase> profile_cases(CaseFamily family, int count, unsigned seed = 20261123) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  std::vector<ProfileCase> cases;
  cases.reserve(static_cast<size_t>(count));
  while (static_cast<int>(cases.size()) < count) {
    ProfileCase c;
    c.lim = {std::pow(10.0, -2 + 2 * w(rng)), std::pow(10.0, -1 + 2.5 * w(rng)), std::pow(10.0, 3.5 * w(rng))};
    c.start.p = 0.02 * u(rng);
    const double dir = u(rng) < 0 ? -1.0 : 1.0;
    // Within a millionth of the edge, a tenth of them on it exactly.
    const double near = w(rng) < 0.1 ? 1.0 : 1 + 1e-6 * u(rng);
    switch (family) {
      case CaseFamily::random_from_rest: c.target = 0.02 * u(rng); break;
      case CaseFamily::a_max_boundary:
        if (a_max_edge(c.lim) == 0) continue;
        c.target = c.start.p + dir * a_max_edge(c.lim) * near;
        break;
      case CaseFamily::v_max_boundary: c.target = c.start.p + dir * v_max_edge(c.lim) * near; break;
      case CaseFamily::random_state:
        // Inside the limits, and |v| need not pass v_max.
        c.start.v = c.lim.v * u(rng);
        c.start.a = c.lim.a * u(rng);
        if (std::abs(cnc::velocity_after_ramp_to_zero(c.start.v, c.start.a, c.lim, cnc::SlopeType::trapez)) >
            c.lim.v)
          continue;
        c.target = 0.02 * u(rng);
        break;
    }
    cases.push_back(c);
  }
  return cases;
}

}  // namespace hil::bench
