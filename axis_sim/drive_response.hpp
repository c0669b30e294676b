#pragma once
// How far a drive of the rig's model (drive_model) overshoots a
// jerk-limited command, found by running the model itself: the CNC plans
// Advanced Lifting's acceleration so that the drive's actual acceleration
// stays below its P-AXIS-00442 error limit (LIFT-2, docs/LIFT.md).
#include "drive_model.hpp"

namespace hil::axis {

// The largest |actual acceleration| (the monitor's: the mean over a cycle)
// of the drive under the hardest commands it is given with |a| <= a and
// |j| <= j: from rest to +a, a turn to -a through a reversal of the
// velocity (Coulomb friction flips there), back to rest; the same without
// plateaus (+a to -a at once: the jerk steps by 2 j at the tips); a ramp
// to -a during which the velocity reverses (the friction's step and the
// ramp's end add); each sampled at two phases of the cycle.
double peak_actual_acceleration(const DriveParameters& drive, double a, double j);

// Share of the limit kept free for what the test commands do not cover
// (a profile's own sampling phase, round-off): 0.5 %.
constexpr double followed_acceleration_reserve = 0.005;

// The largest commanded acceleration (<= limit) whose peak actual
// acceleration at jerk j stays within limit * (1 - reserve).
double largest_followed_acceleration(const DriveParameters& drive, double limit, double j);

}  // namespace hil::axis
