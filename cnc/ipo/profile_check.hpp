#pragma once
// Exact extremes of a motion profile and how well it meets a target (KRN-3):
// what the tests, the `jerk_cases` tool and the benchmarks verify a planned
// profile with. Extremes come from phase ends and the instants where the
// acceleration crosses zero, not from sampling.
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

struct ProfileExtremes {
  double max_v = 0, max_a = 0, max_j = 0;  // of |v|, |a|, |jerk| (jerk 0 for STEP jumps)
  bool finite = true;                      // no NaN or infinity anywhere
  bool durations_valid = true;             // every phase duration >= 0
};

ProfileExtremes extremes(const MotionProfile& profile);

// The profile is finite, ends at rest on `target` within `tolerance`, and
// exceeds no limit by more than `relative` (|v| against max(lim.v, |v0|),
// |a| against max(lim.a, |a0|) for starts outside the limits).
bool meets(const MotionProfile& profile, double target, const Limits& lim, SlopeType slope,
           double tolerance = 1e-9, double relative = 1e-9);

}  // namespace hil::cnc
