#pragma once
// The kernel's tolerances, each named and explained once (issue 35; as
// LinuxCNC's tp_types.h keeps its epsilons): lengths in mm, velocities in
// mm/s, times in s, as everywhere in the CNC (docs/UNITS.md). Two kinds:
// round-off (numbers equal but for their last bits) and the smallest
// geometry the kernel tells apart.
#include <cmath>

namespace hil::cnc::tolerance {

// --- Round-off -----------------------------------------------------------

// A length that is 0 but for round-off: positions and path lengths up to
// 1e6 mm (value_ranges.hpp) carry ~1e-10 mm after the additions of a
// program; 1e-9 is ten times that and 1e-5 of the HLI's 0.1 um.
constexpr double length_mm = 1e-9;
// The same for lengths of size `scale` (a path summed over many blocks):
// 1e-9 of it, and never less than length_mm.
inline double length_at(double scale) { return length_mm * (1 + std::abs(scale)); }
// A velocity that is 0 but for round-off (a profile's end at rest).
constexpr double velocity_mm_s = 1e-9;
// An acceleration that is 0 but for round-off (mm/s^2; Advanced Lifting's landing).
constexpr double acceleration_mm_s2 = 1e-6;
// A time that is reached but for round-off (a dwell's end).
constexpr double time_s = 1e-9;
// One limit (v, a, j) not below another but for round-off: relative.
constexpr double limit_share = 1e-9;
// Curvatures of one circle, or of a contouring curve's end and the path it
// joins: relative to their size.
constexpr double curvature_share = 1e-9;
// Unit tangents (no unit) of collinear lines from the decoder differ by
// this much.
constexpr double direction = 1e-12;
// The end of one part and the start of the next computed from the same
// numbers: one point, relative to 1 + the position.
constexpr double same_point_share = 1e-12;
// A bisection is done when its interval is this (relative to 1 + its
// value, or absolute on a path parameter in mm).
constexpr double bisection_share = 1e-12;

// --- The smallest geometry ----------------------------------------------

// What a part program's coordinates are rounded to (TwinCAT's programming
// resolution, 0.0001 mm: TF5200 system parameters, 2.17; what CAM posts
// write). A point is off by up to sqrt(3) / 2 of it in space.
constexpr double programming_resolution_mm = 1e-4;
// No joint turning more than this is near-tangent, however short its
// blocks (3 degrees: the default of TF5200's TRC option TANGENTIAL_LIMIT,
// up to which the TRC calls its own inserted transitions tangential).
constexpr double near_tangent_max_rad = 3.0 * M_PI / 180.0;

// No part shorter than this (10 nm) is split off or moved: a shorter arc
// could not be told from a full circle.
constexpr double shortest_part_mm = 1e-5;
// A length below this (1 nm) is none: a point this close to a motion is on
// it, a corner distance this short needs no curve, a lift range with less
// path has none, an arc of smaller radius has none.
constexpr double no_length_mm = 1e-6;
// An axis stands on a position within this (0.1 nm): far below
// no_length_mm, so that a crossing found by bisection is not mistaken.
constexpr double standing_on_mm = 1e-7;

}  // namespace hil::cnc::tolerance
