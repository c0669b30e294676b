#pragma once
// Rest-to-rest in closed form (KRN-3, issue 17): the time-optimal profile
// from rest to a target at rest is symmetric, and the distance decides its
// case and gives its durations directly, with no root search.
#include "motion_profile.hpp"
#include "slope.hpp"

namespace hil::cnc {

// The phases over `distance` (either sign) for TRAPEZ and STEP, as the
// general planner builds them (drive, cruise or switch, arrival); false,
// and nothing appended, for SIN2, a distance that is not finite or limits
// that are not positive and finite (the general planner takes those).
bool rest_to_rest_phases(double distance, const Limits& lim, SlopeType slope, PhaseList& out);

}  // namespace hil::cnc
