#pragma once
// Polynomial contouring (KRN-6): turns programmed motion blocks into the
// path pieces the look-ahead plans. Where a block transition is to be
// contoured (G261 / G61, see corner_transition), the corner (or a tangent
// transition with a curvature step) is replaced by a ContourCurve between
// a point at distance d before it and one at d after it: d at most half
// of each block, and for #CONTOUR MODE [DEV PATH_DEV=e] small enough that
// the curve passes within e of the programmed corner. The curve takes
// tangent and curvature of the path at both ends.
//
// Polylines of short chords (CAM programs): where two curves use up a line
// between them completely, the line's middle is no longer on the path, and
// curvature 0 there would make the curvature swing between 0 and twice the
// polyline's bend at every chord (a jerk of v^3 dk/ds, far beyond any
// axis). The curves meet there with the bend of the polyline around that
// line instead (the mean of its two corners' turning per length), so that a
// circle of chords runs as a smooth circle.
//
// A curve is emitted in two halves, the first belongs to the block before
// the corner, the second to the block after it: block ends stay where the
// programme has them for the channel (block numbers, DPS-1: a half covers
// the programmed distance d it replaces, so block-end values are the
// programmed sums). A block's end is known only once the next block is
// there: the last contoured block waits in `open_` until then (or flush()).
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "block.hpp"
#include "machine_config.hpp"
#include "motion_piece.hpp"
#include "path_segment.hpp"

namespace hil::cnc {

// What the path runs, after contouring: a block's part between two
// curves (all of it where nothing is contoured), or a contouring curve's
// half, with its covered distance and limits (the lift's caps among them)
// in its segment.
struct PathPiece {
  size_t block_index = 0;  // into the decoded program
  PathSegment segment;
  SlopeType slope = SlopeType::trapez;
  bool stop_before = false;   // v = 0 where it starts
  bool begins_block = true;   // the block's first piece
  bool ends_block = true;     // the block's last piece
};

class ContourBuilder {
 public:
  explicit ContourBuilder(const MachineConfig& machine) : machine_(machine) {}

  // The next piece (a block, or its rest), whose `out` says how the path is
  // to leave it into the piece added after it; `segment` its geometry.
  // `stop_before`: v = 0 at its start. Returns the pieces that are final
  // now (all of it unless its end is to be contoured).
  std::vector<PathPiece> add(const MotionPiece& piece, PathSegment segment, bool stop_before);
  // Nothing follows (yet): the open block ends where it is programmed.
  std::vector<PathPiece> flush();
  void clear();
  bool has_open() const { return open_.has_value(); }
  // The block closed last ends with an exact stop, and what follows does
  // not come here (an HSC spline, KRN-9): the path stands before it.
  bool take_exact_stop() { return std::exchange(exact_stop_next_, false); }

  // Where an HSC spline (KRN-9) meets a block whose transition is
  // contoured, the curve lies on the block alone; the spline keeps its
  // fitted shape and its knot on the programmed point. Without it the
  // joint was a corner of up to half a chord's turn, a stop (docs/HSC.md).
  // enter_from: the spline's last part ended at `spline_end`, leaving its
  // block as `corner` says; the next block added begins with the curve
  // from there (lead-in).
  void enter_from(const ContourCurve::End& spline_end, const Corner& corner) { entry_ = Entry{spline_end, corner}; }
  // A spline begins at `spline_start`: the open block ends with the curve
  // onto it where its transition is contoured (lead-out), else as flush().
  std::vector<PathPiece> flush_into(const ContourCurve::End& spline_start);

  // The corner distance d at which a curve between tangents t1, t2 (unit)
  // with end curvatures 0 (lines) and end tangents tangent_scale (λ) times
  // its chord passes `deviation` from the corner:
  // d (16 - 10 λ cos(θ/2)) sin(θ/2) / 16 = deviation. A curve another
  // curve may meet gets half of PATH_DEV (the other half is for the
  // curvature its ends get then), a lone corner's up to all of it.
  static double dev_distance(double deviation, const std::vector<double>& t1, const std::vector<double>& t2,
                             double tangent_scale = 1);
  // The same for the turn (ContourCurve::Shape::turn), whose middle passes
  // d sin(θ/2) / 3 from the corner.
  static double turn_distance(double deviation, const std::vector<double>& t1, const std::vector<double>& t2);

 private:
  struct Open {
    MotionPiece piece;
    PathSegment full;
    bool stop_before = false;
    double d_start = 0;  // taken by the curve before it
    double covered_used = 0;
    const Corner& out() const { return *piece.out; }
    const Motion& motion() const { return piece.motion; }
  };
  struct PendingCurve {
    ContourCurve::End start, end;
    std::vector<double> corner;
    size_t from_index = 0;
    SlopeType from_slope = SlopeType::trapez;
    double from_velocity = 0, from_covered = 0;
    Limits from_caps;  // the lift's caps of its block
    double kappa_cap = 0;  // largest curvature the end may get (PATH_DEV)
    bool lone = false;  // no other curve can meet it (ContourJoint::lone_corner)
    double tangent_scale = 1;  // of its ContourCurve
    ContourCurve::Shape shape = ContourCurve::Shape::quintic;
    double d = 0;
    double d_before = 0;  // programmed length it replaces before the corner
    std::vector<double> tangent_before;  // of the block before the corner, at the corner
    double length_before = 0;
    // A lead-in from a spline's end (enter_from): all of it belongs to the
    // block after the corner.
    bool one_sided = false;
  };
  static std::vector<double> line_bend(const PendingCurve& before, const PathSegment& a,
                                       const std::vector<double>& t_after, double after_span, double cap);

  // The pending curve with `end_curvature` at its end, as two halves.
  void emit_curve(std::vector<double> end_curvature, std::vector<PathPiece>& out);
  // The open block from its start trim to `d_end` before its end.
  void emit_middle(double d_end, std::vector<PathPiece>& out);
  void close(std::vector<PathPiece>& out);
  PathSegment piece_of(const Open& block, double s_from, double s_to) const;
  struct CornerCurve {
    double d = 0;  // the corner distance: the curve from d before the corner to d after it
    bool lone = false;
    double tangent_scale = 1;  // of its ContourCurve: a lone corner's is the turn's
    ContourCurve::Shape shape = ContourCurve::Shape::quintic;  // a lone corner between lines: the turn
  };
  // b: the geometry of the block after the corner, `after` its motion.
  CornerCurve corner_curve(const Open& a, const PathSegment& b, const Motion& after, const Corner& corner,
                           double d_max) const;

  // The curve between `fixed` (a spline's end or start) and the programmed
  // `block`: from `fixed` to d into it (lead_in), or from d before its end
  // to `fixed`; none (d = 0) where nothing is to be contoured or no curve
  // of at least shortest_mm keeps PATH_DEV.
  struct OneSidedCurve {
    double d = 0;
    std::shared_ptr<const ContourCurve> curve;
  };
  // Within `budget` of the block (contour mode DEV).
  OneSidedCurve one_sided_curve(const ContourCurve::End& fixed, const PathSegment& block, const Motion& motion,
                                const Corner& corner, bool lead_in, double d_max, double budget) const;
  // `curve` as the open block's only part on it: its first (a lead-in) or
  // its last (a lead-out) piece, covering `covered` of it.
  PathPiece single_part(const std::shared_ptr<const ContourCurve>& curve, double covered, bool begins_block) const;

  struct Entry {
    ContourCurve::End end;
    Corner corner;
  };
  const MachineConfig& machine_;
  std::optional<Entry> entry_;  // enter_from's, for the next block added
  std::optional<Open> open_;
  std::optional<PendingCurve> pending_;
  bool exact_stop_next_ = false;  // the block closed last ends with an exact stop
};

}  // namespace hil::cnc
