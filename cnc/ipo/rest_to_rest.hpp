#pragma once
// Time-optimal rest-to-rest motion over a distance under velocity,
// acceleration and jerk limits: the classic 7-segment profile (KRN-3,
// slope type TRAPEZ), in closed form.
#include "jerk_profile.hpp"

namespace hil::cnc {

struct Limits {
  double v = 0;  // > 0
  double a = 0;  // > 0
  double j = 0;  // > 0
};

// Profile from p = 0, v = a = 0 to p = distance (>= 0), v = a = 0.
JerkProfile rest_to_rest(double distance, const Limits& limits);

}  // namespace hil::cnc
