// Where an HSC spline (KRN-9) meets a block whose transition is contoured
// (KRN-6): the curve lies on the block alone, from the spline's end into
// it (lead-in, ContourBuilder::add after enter_from) or from it onto the
// spline's start (lead-out, flush_into). docs/HSC.md, "Where a spline
// meets a block".
#include <memory>

#include "axis_vector.hpp"
#include "contour_builder.hpp"
#include "contour_fit.hpp"
#include "motion_parts.hpp"

namespace hil::cnc {
using namespace contour_fit;

namespace {
// Largest share of a block (of what is left of it) a lead-out takes where
// it does not meet the curve before it: the rest keeps a middle between
// the two.
constexpr double one_sided_share = 0.4;
}  // namespace

ContourBuilder::OneSidedCurve ContourBuilder::one_sided_curve(const ContourCurve::End& fixed,
                                                              const PathSegment& block, const Motion& motion,
                                                              const Corner& corner, bool lead_in, double d_max,
                                                              double budget) const {
  // Not in a lift range: its caps hold per block, and Advanced Lifting
  // times its landing by the programmed distance (corner_curve's lone
  // curves alike).
  // Not on an arc: its rest could be the full circle again (fuzz hsc seed
  // 41002823: a G02 full circle's lead-out, dist_prog_start one circle
  // too far at the end).
  if (corner.transition != BlockTransition::contour || motion.in_lift_range || block.is_contour_curve() ||
      block.is_arc())
    return {};
  const double len = block.length(), at = lead_in ? 0 : len;
  if (!same_point(block.position(at), fixed.point)) return {};
  const std::vector<double> t = block.tangent(at);
  if (dot(fixed.tangent, t) < cos_sharpest) return {};
  if (!tangent_break(fixed.tangent, t) && !curvature_step(fixed.curvature, block.curvature(at))) return {};
  const bool dev = corner.mode.type == ContourMode::Type::dev;
  double d = dev ? d_max : std::min(d_max, corner.mode.dist);
  for (int attempt = 0; attempt < 60 && d >= shortest_mm; ++attempt) {
    const double s = lead_in ? d : len - d;
    const ContourCurve::End on_block = block.curve_end(s);
    auto curve = std::make_shared<const ContourCurve>(lead_in ? fixed : on_block, lead_in ? on_block : fixed);
    // Only a turn of up to about 4 degrees is no longer than its d (fuzz
    // hsc seed 41000100: a DIST lead-in turning 162 degrees counted 0.80 of
    // the path it ran).
    if (fits_block(*curve, block, d, corner, budget)) return {d, std::move(curve)};
    d *= 0.7;
  }
  return {};
}

PathPiece ContourBuilder::single_part(const std::shared_ptr<const ContourCurve>& curve, double covered,
                                      bool begins_block) const {
  const Open& a = *open_;
  auto joint = std::make_shared<ContourJoint>();
  joint->curve = curve;
  const double length = curve->length();
  joint->parts = {{a.piece.block, covered, a.full.programmed_velocity(), a.motion().path_caps, length}};
  std::shared_ptr<const ContourJoint> shared = std::move(joint);
  return {a.piece.block, PathSegment(shared, 0, length, false, machine_), a.piece.slope, false, begins_block,
          !begins_block};
}

std::vector<PathPiece> ContourBuilder::flush_into(const ContourCurve::End& spline_start) {
  std::vector<PathPiece> out;
  if (!open_) return out;
  Open& a = *open_;
  const double len = a.full.length();
  // Where a curve ends on the block, the lead-out takes all the rest and
  // meets it with the polyline's bend (the spline's first turn counts as
  // the corner after: over half the block); else, or where that leaves
  // PATH_DEV, it takes at most one_sided_share of the block.
  const OneSidedCurve check = one_sided_curve(spline_start, a.full, a.motion(), a.out(), false,
                                              one_sided_share * (len - a.d_start), a.out().mode.path_dev);
  if (!check.curve) {
    close(out);
    return out;
  }
  std::shared_ptr<const ContourCurve> lead_out = check.curve;
  if (pending_ && a.d_start > 0) {
    const std::vector<double> k = line_bend(*pending_, a.full, spline_start.tangent, len / 2, pending_->kappa_cap);
    auto meeting = std::make_shared<const ContourCurve>(
        ContourCurve::End{a.full.position(a.d_start), a.full.tangent(a.d_start), k}, spline_start);
    if (fits_block(*meeting, a.full, len - a.d_start, a.out(), a.out().mode.path_dev)) {
      emit_curve(k, out);
      lead_out = std::move(meeting);
    }
  }
  if (lead_out == check.curve) {
    if (pending_) emit_curve(a.full.curvature(a.d_start), out);
    emit_middle(check.d, out);
  }
  out.push_back(single_part(lead_out, a.full.covered_distance() - a.covered_used, false));
  open_.reset();
  return out;
}

}  // namespace hil::cnc
