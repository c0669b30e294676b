#include "contour_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "axis_vector.hpp"
#include "contour_fit.hpp"
#include "motion_parts.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
using namespace contour_fit;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Share of a block between two curves that is absorbed into them.
constexpr double absorbed_share = 1e-3;
// Largest value of the quintic Hermite basis functions of the end second
// derivatives, u²(1-u)³/2 at u = 2/5: a change dk of an end curvature moves
// the curve by at most this * L² * dk.
constexpr double curvature_basis_max = 0.01728;

// cos and sin of half the angle θ between two unit tangents.
struct HalfAngle {
  double c, s;
};
HalfAngle half_angle(const std::vector<double>& t1, const std::vector<double>& t2) {
  const double cos_theta = std::clamp(dot(t1, t2), -1.0, 1.0);
  return {std::sqrt((1 + cos_theta) / 2), std::sqrt((1 - cos_theta) / 2)};
}

// Largest end curvature a curve of chord L may get later and stay within
// PATH_DEV: a quarter of it per end.
double kappa_cap(const Corner& corner, double chord) {
  if (corner.mode.type != ContourMode::Type::dev) return inf;
  return corner.mode.path_dev / (4 * curvature_basis_max * chord * chord);
}

}  // namespace

double ContourBuilder::dev_distance(double deviation, const std::vector<double>& t1, const std::vector<double>& t2,
                                    double tangent_scale) {
  const auto [c, s] = half_angle(t1, t2);
  if (!(s > tolerance::direction)) return inf;
  return deviation * 16 / ((16 - 10 * tangent_scale * c) * s);
}

double ContourBuilder::turn_distance(double deviation, const std::vector<double>& t1, const std::vector<double>& t2) {
  const double s = half_angle(t1, t2).s;
  if (!(s > tolerance::direction)) return inf;
  return 3 * deviation / s;
}

namespace {
// The largest d of a curve from d before the end of a block of length `len`
// that began with a curve of d_start (0: none) to d into a block of length
// `len_b` that no other curve can meet: the next curve takes at most half
// of len_b (d_max), and what a curve leaves of a block is absorbed below
// absorbed_share (add()).
double lone_room(double len, double d_start, double len_b) {
  const double before = d_start > 0 ? len - d_start - absorbed_share * len - shortest_mm : inf;
  return std::min(before, len_b / 2 - absorbed_share * len_b - shortest_mm);
}

// Time a corner passed at v along a curve of `length` costs against passing
// it at the feed line.v: braking to v and back (point-symmetric in time,
// so at the mean velocity) and the curve at v.
double corner_time_loss(double v, double length, const Limits& line) {
  if (!(v > 0)) return inf;
  const double dv = std::max(0.0, line.v - v);
  const double t = dv >= line.a * line.a / line.j ? dv / line.a + line.a / line.j : 2 * std::sqrt(dv / line.j);
  return t * dv / line.v + length * (1 / v - 1 / line.v);
}

// The tangent scale whose curve is the velocity blend of a turn: 1 / cos(θ/2).
double turn_tangent_scale(const std::vector<double>& t1, const std::vector<double>& t2) {
  return 1 / half_angle(t1, t2).c;
}
}  // namespace

// The bend of the polyline around the line `a`, across its joint: the
// turning per length of its two corners (the one into it from the curve
// `before`, the one out of it into `t_after` over `after_span`): their mean
// where they are alike, the smaller where they turn the same way but differ
// more than twofold, and 0 where they do not turn the same way (minmod, so
// that a sharp corner next to gentle chords does not bend the gentle side:
// the curve would grow longer than the blocks it replaces); at most `cap`.
std::vector<double> ContourBuilder::line_bend(const PendingCurve& before, const PathSegment& a,
                                              const std::vector<double>& t_after, double after_span, double cap) {
  const double len = a.length();
  const std::vector<double> t_a = a.tangent(0);
  std::vector<double> c_before(t_a.size()), c_after(t_a.size());
  for (size_t i = 0; i < t_a.size(); ++i) {
    c_before[i] = (t_a[i] - before.tangent_before[i]) / ((before.length_before + len) / 2);
    c_after[i] = (t_after[i] - t_a[i]) / after_span;
  }
  const double along_before = dot(c_before, t_a), along_after = dot(c_after, t_a);
  for (size_t i = 0; i < t_a.size(); ++i) {
    c_before[i] -= along_before * t_a[i];
    c_after[i] -= along_after * t_a[i];
  }
  const double nb = norm(c_before), na = norm(c_after), same = dot(c_before, c_after);
  std::vector<double> k(t_a.size(), 0.0);
  if (same > 0 && nb > 0 && na > 0) {
    if (std::max(nb, na) <= 2 * std::min(nb, na)) {
      // Alike (a circle of chords, with the rounding of its points):
      // their mean, which halves the rounding's noise.
      for (size_t i = 0; i < k.size(); ++i) k[i] = (c_before[i] + c_after[i]) / 2;
    } else {
      const std::vector<double>& smaller = nb < na ? c_before : c_after;
      for (size_t i = 0; i < k.size(); ++i) k[i] = smaller[i] * same / (nb * na);
    }
  }
  const double size = norm(k);
  if (size > cap)
    for (double& x : k) x *= cap / size;
  return k;
}

ContourBuilder::CornerCurve ContourBuilder::corner_curve(const Open& a, const PathSegment& b, const Motion& after,
                                                         const Corner& corner, double d_max) const {
  if (!needs_curve(a.full, b)) return {};
  const double len = a.full.length();
  const std::vector<double> t1 = a.full.tangent(len), t2 = b.tangent(0);
  if (dot(t1, t2) < cos_sharpest) return {};
  const bool dev = corner.mode.type == ContourMode::Type::dev;
  if (!dev) {
    const double d = std::min(d_max, corner.mode.dist);
    return {d >= shortest_mm ? d : 0, false};
  }
  // A lone corner's curve keeps the blocks' own end curvatures: it may use
  // all of PATH_DEV for its turn (issue 36 item 4: the corner speed grows
  // with deviation^(2/3)); which curve it gets, see below.
  // Between lines the curve takes the turn's shape; next to an arc its ends'
  // tangents and curvatures are the arc's at d, not the corner's, and a
  // longer tangent would bend it away from the arc (fuzz contour 39000199:
  // a G03 of r 4.8 um into a line, the curve 28 % longer than the path it
  // replaced).
  // Between lines it is the jerk-limited turn (ContourCurve::Shape::turn),
  // passed at one ds/dt with its speed dipping in the middle as the bound's.
  const bool arcs = a.full.is_arc() || b.is_arc();
  using Shape = ContourCurve::Shape;
  const Shape lone_shape = arcs ? Shape::quintic : Shape::turn;
  const double turn = arcs ? 1.0 : turn_tangent_scale(t1, t2);
  // (A hair inside PATH_DEV: on it to round-off, the check below shrank it
  // by 0.7.)
  const double lone_dev = corner.mode.path_dev * (1 - 1e-9);
  const double room = lone_room(len, a.d_start, b.length());
  // A turn is lone where it finds room within 8/9 of PATH_DEV, and then
  // grows into the room up to all of it: one that needs the whole block's
  // half is a polyline's chord (a circle of chords, whose curves must meet
  // to run at the feed); 8/9 keeps the corners that were lone when the
  // turn was a quintic (its d: 8/9 of the turn's), which the CAM corpus
  // measured (a turn that grew beyond the room turned its neighbours into
  // shared curves: mixed_transitions 22.5 -> 23.6 s).
  const double d_lone = std::min(
      d_max, arcs ? dev_distance(lone_dev, t1, t2) : std::min(turn_distance(lone_dev, t1, t2), room));
  const double d_needed = arcs ? d_lone : std::min(d_max, turn_distance(lone_dev * 8 / 9, t1, t2));
  // Not in a lift range nor at its ends: Advanced Lifting times its landing
  // by the programmed distance left and the velocity of the cycle before;
  // a lone curve across the range's end at the feed, covering more
  // programmed distance per cycle than its length, left the range a cycle
  // before the lift axis had landed (the test "LIFT-2 KRN-6 G261: the path
  // passes the corners into and out of an Advanced Lifting range", PATH_DEV
  // 0.5).
  const bool lone = d_needed <= room && !a.motion().in_lift_range && !after.in_lift_range;
  // With arcs (and as a check for lines): shrink until the curve with the
  // ends' own curvatures passes within the budget of the corner and, next
  // to an arc, of the path it replaces: at a tangent joint with a
  // curvature step the curve passes the joint itself but leaves the arcs
  // between (issue 36: arcs of radius 7 and 15 in an S, 0.060 mm from the
  // path with PATH_DEV 0.01).
  // Next to a tight arc it may also not be longer than the 2d of path it
  // replaces (longest_share).
  const std::vector<double> programmed_corner = a.full.end();
  struct Fit {
    double d = 0;
    std::optional<ContourCurve> curve;
  };
  auto fit = [&](double budget, double d, double scale, Shape shape) {
    for (int attempt = 0; attempt < 60 && d >= shortest_mm; ++attempt) {
      ContourCurve curve(a.full.curve_end(len - d), b.curve_end(d), scale, shape);
      if (curve.distance_to(programmed_corner) <= budget &&
          (!arcs || (deviation(curve, a.full, len - d, b, d) <= budget && curve.length() <= 2 * d * longest_share)))
        return Fit{d, std::move(curve)};
      d *= 0.7;
    }
    return Fit{};
  };
  const double half = corner.mode.path_dev / 2;
  const Fit shared = fit(half, std::min(d_max, dev_distance(half, t1, t2)), 1.0, Shape::quintic);
  if (!lone || !shared.curve) return {shared.d, false, 1};
  const Fit whole = fit(corner.mode.path_dev, d_lone, turn, lone_shape);
  if (!whole.curve) return {shared.d, false, 1};
  // Of the curve a corner would have next to others (half of PATH_DEV, its
  // limits in thirds), the turn in all of PATH_DEV, and the turn in half of
  // it (the same shape at half the size: k doubles, k' quadruples): the one
  // that costs the least time. At wide angles a curve is slow whatever its
  // size, and the shorter one costs less.
  // The programmed feed and the axes' limits, not a lift range's caps: the
  // curve is the same whatever caps its halves get.
  Limits line{std::min(a.motion().feed, after.feed), inf, inf};
  for (size_t i = 0; i < t1.size(); ++i)
    if (t1[i] != 0 || t2[i] != 0) {
      const AxisConfig& axis = machine_.axes[i];
      line = {std::min(line.v, axis.v_max), std::min(line.a, axis.a_max), std::min(line.j, axis.j_max)};
    }
  // With the limits' shares of PathSegment::set_contour_limits; `scale`: of
  // the curve's size.
  auto loss = [&](const ContourCurve& curve, const ContourJoint::LimitShares& share, double scale) {
    const ContourCurve::AxisBounds bounds = curve.bounds(0, curve.length());
    const double v_a = std::sqrt(scale * line.a / (share.curvature_a * bounds.curvature_norm));
    const double v_j = std::cbrt(scale * scale * line.j / (share.curvature_j * bounds.curvature_rate_norm));
    return corner_time_loss(std::min({line.v, v_a, v_j}), scale * curve.length(), line);
  };
  const double loss_shared = loss(*shared.curve, ContourJoint::thirds, 1);
  const double loss_whole = loss(*whole.curve, ContourJoint::lone_shares, 1);
  const double loss_half = loss(*whole.curve, ContourJoint::lone_shares, 0.5);
  if (loss_shared <= std::min(loss_whole, loss_half)) return {shared.d, false, 1};
  if (loss_whole <= loss_half) return {whole.d, true, turn, lone_shape};
  return {fit(half, whole.d / 2, turn, lone_shape).d, true, turn, lone_shape};
}

PathSegment ContourBuilder::piece_of(const Open& block, double s_from, double s_to) const {
  const double len = block.full.length();
  if (s_from <= 0 && s_to >= len) return block.full;
  Motion m = block.motion();
  if (s_to < len) m = motion_until(m, block.full.position(s_to));
  if (s_from > 0) m = motion_from(m, block.full.position(s_from));
  return PathSegment(m, machine_);
}

void ContourBuilder::emit_curve(std::vector<double> end_curvature, std::vector<PathPiece>& out) {
  PendingCurve& p = *pending_;
  Open& a = *open_;  // the block after the corner
  auto joint = std::make_shared<ContourJoint>();
  joint->curve = std::make_shared<const ContourCurve>(
      p.start, ContourCurve::End{p.end.point, p.end.tangent, end_curvature}, p.tangent_scale, p.shape);
  const double len = a.full.length();
  // Split where the programmed shares meet, so that both halves count the
  // same share of programmed distance per path length.
  const double share_after = a.d_start, share_before = p.d_before;
  const double length = joint->curve->length();
  const double split = length * share_before / (share_before + share_after);
  const double covered = a.full.covered_distance() * a.d_start / len;
  a.covered_used += covered;
  joint->lone_corner = p.lone;
  if (p.one_sided) {
    out.push_back(single_part(joint->curve, covered, true));
    pending_.reset();
    return;
  }
  joint->parts = {{p.from_index, p.from_covered, p.from_velocity, p.from_caps, split},
                  {a.piece.block, covered, a.full.programmed_velocity(), a.motion().path_caps, length}};
  std::shared_ptr<const ContourJoint> shared = std::move(joint);
  out.push_back({p.from_index, PathSegment(shared, 0, split, false, machine_), p.from_slope, false, false, true});
  out.push_back(
      {a.piece.block, PathSegment(shared, split, length, false, machine_), a.piece.slope, false, true, false});
  pending_.reset();
}

void ContourBuilder::emit_middle(double d_end, std::vector<PathPiece>& out) {
  Open& a = *open_;
  const double len = a.full.length();
  const bool ends = d_end == 0;
  PathSegment middle = piece_of(a, a.d_start, len - d_end);
  if (a.d_start > 0 || d_end > 0) {
    const double covered = ends ? a.full.covered_distance() - a.covered_used
                                : a.full.covered_distance() * middle.length() / len;
    middle.set_covered_distance(covered);
    a.covered_used += covered;
  }
  out.push_back(
      {a.piece.block, std::move(middle), a.piece.slope, a.stop_before && a.d_start == 0, a.d_start == 0, ends});
}

void ContourBuilder::close(std::vector<PathPiece>& out) {
  Open& a = *open_;
  if (pending_) emit_curve(a.full.curvature(a.d_start), out);
  emit_middle(0, out);
  exact_stop_next_ = a.out().transition == BlockTransition::exact_stop;
  open_.reset();
}

std::vector<PathPiece> ContourBuilder::add(const MotionPiece& piece, PathSegment segment, bool stop_before) {
  std::vector<PathPiece> out;
  stop_before = stop_before || exact_stop_next_;
  exact_stop_next_ = false;
  const std::optional<Entry> entry = std::exchange(entry_, std::nullopt);
  double d_start = 0;
  // The lead-in waits, as any curve, for the block after it: where the
  // next curve takes the rest of the block, the two meet with the
  // polyline's bend (the spline's last turn counts as the corner before:
  // its tangent over no length).
  if (!open_ && entry && !stop_before) {
    // Half of PATH_DEV: its end may get curvature later (kappa_cap).
    const OneSidedCurve lead_in = one_sided_curve(entry->end, segment, piece.motion, entry->corner, true,
                                                  segment.length() / 2, entry->corner.mode.path_dev / 2);
    if (lead_in.curve) {
      d_start = lead_in.d;
      PendingCurve p;
      p.start = entry->end;
      p.end = segment.curve_end(d_start);
      p.corner = segment.position(0);
      p.from_index = piece.block;
      p.kappa_cap = kappa_cap(entry->corner, distance(p.start.point, p.end.point));
      p.one_sided = true;
      p.d = d_start;
      p.tangent_before = entry->end.tangent;
      pending_ = std::move(p);
    }
  }
  if (open_) {
    Open& a = *open_;
    const double len = a.full.length();
    const CornerCurve corner =
        stop_before ? CornerCurve{}
                    : corner_curve(a, segment, piece.motion, a.out(), std::min(len, segment.length()) / 2);
    const double d = corner.d;
    // Two curves that leave less than this of the block between them meet
    // (the rest goes to the curve after it): chords of a CAM polyline differ
    // in length by their rounding, and a micro-line between two curves would
    // bring back curvature 0 there.
    const bool vanished = d > 0 && a.d_start > 0 && len - a.d_start - d < absorbed_share * len + shortest_mm;
    std::vector<double> start_k = a.full.curvature(len - d);
    std::vector<double> start_point = a.full.position(len - d), start_t = a.full.tangent(len - d);
    if (vanished) {
      start_point = a.full.position(a.d_start);
      start_t = a.full.tangent(a.d_start);
      start_k = a.full.curvature(a.d_start);
      const MotionType type = a.motion().type;
      if (!a.full.is_contour_curve() && type != MotionType::arc_cw && type != MotionType::arc_ccw) {
        const double chord = distance(start_point, segment.position(d));
        start_k = line_bend(*pending_, a.full, segment.tangent(0), (len + segment.length()) / 2,
                            std::min(pending_->kappa_cap, kappa_cap(a.out(), chord)));
      }
    }
    if (pending_) emit_curve(vanished ? start_k : a.full.curvature(a.d_start), out);
    if (!vanished) emit_middle(d, out);
    if (d > 0) {
      PendingCurve p;
      p.start = {start_point, start_t, start_k};
      p.end = segment.curve_end(d);
      p.corner = a.full.end();
      p.from_index = a.piece.block;
      p.from_slope = a.piece.slope;
      p.from_velocity = a.full.programmed_velocity();
      p.from_caps = a.motion().path_caps;
      p.from_covered = a.full.covered_distance() - a.covered_used;
      p.kappa_cap = corner.lone ? 0.0 : kappa_cap(a.out(), distance(p.start.point, p.end.point));
      p.lone = corner.lone;
      p.tangent_scale = corner.tangent_scale;
      p.shape = corner.shape;
      p.d = d;
      p.d_before = len - (vanished ? a.d_start : len - d);
      p.tangent_before = a.full.tangent(len);
      p.length_before = len;
      pending_ = std::move(p);
    } else {
      exact_stop_next_ = false;
    }
    open_.reset();
    d_start = d;
  }
  open_ = Open{piece, std::move(segment), stop_before, d_start, 0.0};
  if (piece.out->transition != BlockTransition::contour) close(out);
  return out;
}

std::vector<PathPiece> ContourBuilder::flush() {
  std::vector<PathPiece> out;
  if (open_) close(out);
  return out;
}

void ContourBuilder::clear() {
  entry_.reset();
  open_.reset();
  pending_.reset();
  exact_stop_next_ = false;
}

}  // namespace hil::cnc
