#pragma once
// Whether a contouring curve is needed between two ends of the path, and
// whether one fits the programmed path it replaces (KRN-6, DPS-1): shared
// by the corner curves and the one-sided curves where an HSC spline meets
// a block (ContourBuilder).
#include <cmath>
#include <vector>

#include "contour_curve.hpp"
#include "motion_piece.hpp"
#include "path_segment.hpp"
#include "tolerances.hpp"

namespace hil::cnc::contour_fit {

// A corner sharper than this (a reversal) keeps its stop: the curve would
// need a cusp.
inline const double cos_sharpest = std::cos(170.0 * M_PI / 180.0);
// Shorter corner distances are not worth a curve (and a shorter rest of
// a block is no piece: an arc of it could not be told from a full circle).
constexpr double shortest_mm = tolerance::no_length_mm;
// Next to a tight arc a curve may be longer than the path it replaces,
// whose programmed distance it counts (DPS-1): dist_prog_start would grow
// slower than the axes move (fuzz M and U: by up to 0.27 % at arcs of
// r <= 0.3 mm). Such a curve shrinks until it is not, but for this share.
constexpr double longest_share = 1 + 5e-4;

// Something to contour between two ends: a tangent break, or a curvature
// step (KRN-6, thresholds as in the corner rule).
bool tangent_break(const std::vector<double>& t1, const std::vector<double>& t2);
bool curvature_step(const std::vector<double>& k1, const std::vector<double>& k2);
bool needs_curve(const PathSegment& a, const PathSegment& b);

// Largest distance of `curve` from the programmed path it replaces: the
// end of `a` from s = a_from and the start of `b` up to s = b_to. Sampled;
// a sample's distance is to the nearest point of either within that span
// (where a projection falls outside, to the span's end: an upper bound).
double deviation(const ContourCurve& curve, const PathSegment& a, double a_from, const PathSegment& b, double b_to);
// Largest distance of `curve` from `block` (sampled, to the nearest point
// of the whole block).
double deviation_from(const ContourCurve& curve, const PathSegment& block);

// A one-sided curve replacing `d` of `block` fits it: never longer than
// that d, whose distance it counts (DPS-1), in DIST mode too; within
// `budget` of the block in contour mode DEV.
bool fits_block(const ContourCurve& curve, const PathSegment& block, double d, const Corner& corner, double budget);

}  // namespace hil::cnc::contour_fit
