#pragma once
// HSC smoothing (KRN-9, programming manual "Trim a contour (#HSC ON/OFF)"):
// a run of G01 blocks under #HSC ON [BSPLINE ..] becomes one curvature-
// continuous spline through their programmed end points (docs/HSC.md).
//
// Why not the corner curves of G261: CAM programs write their points
// rounded (4 decimals), so every corner of a polyline of 0.1 mm chords is a
// little different, and a curve per corner takes its tangent and curvature
// from one or two chords: their rounding (1e-3 rad, 1e-2 /mm) becomes the
// path's curvature rate, and the jerk limit the feed. Here tangent and
// curvature at a knot come from a least-squares cubic through every
// programmed point within fit_half_window_mm of it, which averages the
// rounding out; between knots runs a quintic Hermite curve (ContourCurve)
// with those ends, so tangent and curvature are continuous at every knot.
//
// Knots are programmed end points, kept exactly: a block boundary stays
// where the program has it (block numbers, DPS-1, a stop there and a
// restart from there join the program). Kept on the rounded point, the
// span's curvature swings by ~60 e / L² for a rounding e: spans of 3 mm
// keep that below the fit's own noise. MERGE=0: a knot at every end point; MERGE=1: a span takes
// blocks up to merge_span_mm and hsc_span_turn_deg of turning, its blocks'
// ends lying inside it at the share of the polyline's length they end at.
// A span that leaves PATH_DEV (main axes, from the programmed polyline) or
// TRACK_DEV (the other axes) is halved; a single block that still does is
// separated (AUTO_OFF_PATH/TRACK=1: the whole span is), as is a run of one
// block: it goes to the contour builder and runs with the transitions
// programmed for it (G261 contours them).
//
// The spline ends (its end knot has the tangent of a one-sided fit) where
// a block is not smoothed (G00, an arc, a split or rest of a block, a lift
// range, a block longer than MAX_PATH_LENGTH), at a bend sharper than
// MAX_ANGLE (hsc_corner_angle_deg where it is 0), where the path must
// stand (an M function, a dwell, an exact stop) and where the look-ahead
// sees no further block (flush).
#include <cstddef>
#include <optional>
#include <variant>
#include <vector>

#include "contour_builder.hpp"
#include "machine_config.hpp"
#include "motion_piece.hpp"
#include "path_segment.hpp"

namespace hil::cnc {

// A block the spline leaves as programmed ("block is separated"): a run of
// one block, or one whose span leaves PATH_DEV or TRACK_DEV on its own. It
// runs with the transitions programmed for it (G261 contours its corners).
struct SeparatedBlock {
  MotionPiece piece;
  PathSegment segment;
  bool stop_before = false;
};
// One block's part of a span, and how the path leaves that block (a
// contoured transition after the spline's last block: the builder's curve
// into the block after it, ContourBuilder::enter_from).
struct SplinePiece {
  PathPiece piece;
  Corner exit;
};
// What the spline hands on, in program order.
using HscOutput = std::variant<SplinePiece, SeparatedBlock>;

class HscSpline {
 public:
  static constexpr double fit_half_window_mm = 2.0;
  static constexpr double merge_span_mm = 3.0;
  static constexpr double hsc_span_turn_deg = 30.0;
  static constexpr double hsc_corner_angle_deg = 30.0;

  explicit HscSpline(const MachineConfig& machine) : machine_(machine) {}

  // Whether `piece` joins a spline: a whole G01 block under #HSC ON.
  static bool smooths(const MotionPiece& piece, const PathSegment& segment);

  // The next smoothed block; returns what is final now (spans whose end
  // knot's fit has all its points, and the blocks separated before them).
  std::vector<HscOutput> add(const MotionPiece& piece, PathSegment segment, bool stop_before);
  // Nothing follows (yet): the spline ends at its last programmed point.
  std::vector<HscOutput> flush();
  void clear();
  bool has_open() const { return !members_.empty(); }
  // The last spline ended with an exact stop: the path stands before
  // whatever follows it.
  bool take_exact_stop();

 private:
  struct Member {
    MotionPiece piece;
    PathSegment segment;
    bool stop_before = false;
  };
  // A knot: a programmed point with the tangent and curvature the spans
  // on either side share there.
  using Knot = ContourCurve::End;

  bool continues_with(const PathSegment& segment, const HscMode& mode) const;
  // A least-squares cubic through the points around one of them: its first
  // and second derivative there by polyline length, how far it misses the
  // farthest of its points, and how many of its intervals it spans.
  struct Fit {
    std::vector<double> d1, d2;
    double largest_miss = 0;
    size_t intervals = 0;
  };
  std::optional<Fit> fit(size_t k, double half_window) const;
  // Point k of the run, with tangent and curvature of the fit around it.
  Knot knot(size_t k) const;
  // Where the span from point `from` ends, once the points it and its end
  // knot's fit need are there.
  std::optional<size_t> span_end(size_t from, bool closing) const;
  void emit(bool closing, std::vector<HscOutput>& out);
  void emit_span(size_t from, size_t to, const Knot& a, const Knot& b, std::vector<HscOutput>& out);
  void separate(size_t from, size_t to, std::vector<HscOutput>& out);
  bool within_tolerance(const ContourCurve& curve, size_t from, size_t to) const;
  void close(std::vector<HscOutput>& out);
  void forget_run();
  void drop_behind();

  const MachineConfig& machine_;
  HscMode mode_;
  std::vector<std::vector<double>> points_;  // points_[i] .. points_[i + 1]: members_[i]
  std::vector<double> chord_;                // polyline length up to each point
  std::vector<Member> members_;
  size_t done_ = 0;                // spans are out up to this point
  std::optional<Knot> done_knot_;  // its knot, shared with the span after it
  bool exact_stop_next_ = false;
};

}  // namespace hil::cnc
