#include "path_segment.hpp"
#include "tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hil::cnc {
namespace {

// An arc's plane axis: set (>= 0) wherever it is used as an index.
size_t at(int axis) { return static_cast<size_t>(axis); }

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double two_pi = 2 * M_PI;
}  // namespace

bool is_main_axis(const std::string& name) {
  return name.size() == 1 && (name[0] == 'X' || name[0] == 'Y' || name[0] == 'Z');
}

std::array<int, 2> arc_plane_axes(const Motion& motion, const MachineConfig& machine) {
  return {motion.plane[0] >= 0 ? motion.plane[0] : machine.axis_index("X"),
          motion.plane[1] >= 0 ? motion.plane[1] : machine.axis_index("Y")};
}

PathSegment::PathSegment(const Motion& m, const MachineConfig& machine)
    : start_(m.start), end_(m.end), unit_(m.start.size(), 0.0) {
  arc_ = m.type == MotionType::arc_cw || m.type == MotionType::arc_ccw;
  if (arc_) set_arc_limits(m, machine);
  else set_line_limits(m, machine);
  // The lift function's caps in a lift range (LIFT-2, LIFT-3).
  limits_ = capped(limits_, m.path_caps);
  programmed_velocity_ = m.type == MotionType::rapid ? limits_.v : std::min(m.feed, limits_.v);
  set_covered_distance(machine);
}

PathSegment::PathSegment(std::shared_ptr<const ContourJoint> joint, double s_from, double s_to, bool reversed,
                         const MachineConfig& machine)
    : start_(joint->curve->position(reversed ? s_to : s_from)),
      end_(joint->curve->position(reversed ? s_from : s_to)),
      unit_(start_.size(), 0.0),
      length_(s_to - s_from),
      covered_distance_(joint->covered(s_from, s_to)),
      joint_(std::move(joint)),
      s_from_(s_from),
      reversed_(reversed) {
  // The lower velocity and caps of the halves it lies on.
  double programmed_velocity = inf;
  Limits cap = Limits::none();
  const std::vector<ContourJoint::Part>& parts = joint_->parts;
  for (size_t i = 0; i < parts.size(); ++i) {
    const bool last = i + 1 == parts.size();
    if ((last || s_from < parts[i].end) && (i == 0 || s_to > joint_->begin(i))) {
      programmed_velocity = std::min(programmed_velocity, parts[i].programmed_velocity);
      cap = capped(cap, parts[i].caps);
    }
  }
  // In a lift range the lift's time bound counts the covered distance, of
  // which a curve covers more than its own length (it cuts the corner):
  // there the velocity counts covered distance per second (LIFT-2, LIFT-8).
  if (cap.v < inf && length_ > 0 && covered_distance_ > length_) {
    const double shorter = length_ / covered_distance_;
    cap.v *= shorter;
    programmed_velocity *= shorter;
  }
  set_contour_limits(machine, programmed_velocity);
  limits_ = capped(limits_, cap);
  programmed_velocity_ = std::min(programmed_velocity, limits_.v);
}

double PathSegment::direction_rounding() const {
  if (joint_ || !(length_ > 0)) return 0;
  const double point = std::sqrt(3.0) * tolerance::programming_resolution_mm;
  if (!arc_) return point / length_;
  const double planar_length = length_ * planar_;
  if (!(planar_length > 0)) return point / length_;
  return (point + std::abs(radius_end_ - radius_)) / planar_length;
}

namespace {
// Limits rounded down onto a grid (steps of 2^(1/16)): neighbouring curves
// of a polyline of similar chords then share them, and the look-ahead plans
// through them as one stretch instead of passing each transition with a = 0.
double on_grid(double value) {
  if (!(value > 0) || std::isinf(value)) return value;
  return std::exp2(std::floor(16 * std::log2(value)) / 16);
}
}  // namespace

// As on an arc (set_arc_limits), with the curve's own bounds: an axis sees
// t_i a_t + k_i v² (acceleration) and t_i j_t + 3 k_i v a_t + k_i' v³
// (jerk). Half the acceleration goes to each term, a third of the jerk to
// each. A lone corner's curve that limits the path below its feed is
// passed at about one velocity: there the curvature terms get 2/3 of both,
// a_t the rest and j_t and 3 k v a_t a sixth each (issue 36 item 4: the
// corner's speed against the jerk-limited turn; 4/5 made the path slower
// on CAM programs, where it brakes and accelerates next to such curves;
// where the feed is below the curve's limit the path keeps the thirds).
// |t_i| <= 1 is used for the tangential terms, so that the limits do not
// change with the direction along a polyline.
void PathSegment::set_contour_limits(const MachineConfig& machine, double programmed_velocity) {
  using Shares = ContourJoint::LimitShares;
  constexpr const Shares &thirds = ContourJoint::thirds, &turn = ContourJoint::lone_shares;
  const ContourCurve::AxisBounds b = joint_->curve->bounds(s_from_, s_from_ + length_);
  // The lowest limits of the axes that move, against the norms of k and
  // dk/ds (|k_i| <= |k|): the same limits whichever way a polyline turns.
  double v_axis = inf, a_axis = inf, j_axis = inf;
  for (size_t i = 0; i < start_.size(); ++i) {
    if (!(b.tangent[i] > 0) && !(b.curvature[i] > 0)) continue;  // the axis does not move here
    const AxisConfig& axis = machine.axes[i];
    v_axis = std::min(v_axis, axis.v_max);
    a_axis = std::min(a_axis, axis.a_max);
    j_axis = std::min(j_axis, axis.j_max);
  }
  const double k = b.curvature_norm, dk = b.curvature_rate_norm;
  const auto velocity_limit = [&](const Shares& share) {
    double v = v_axis;
    if (k > 0) v = std::min(v, std::sqrt(a_axis / (share.curvature_a * k)));
    if (dk > 0) v = std::min(v, std::cbrt(j_axis / (share.curvature_j * dk)));
    return on_grid(v);
  };
  const double v_feed = programmed_velocity * machine.override_max_percent / 100.0;
  double v = velocity_limit(thirds);
  const bool passed_at_its_limit = joint_->lone_corner && v < v_feed;
  const Shares& share = passed_at_its_limit ? turn : thirds;
  if (passed_at_its_limit) v = velocity_limit(turn);
  // The 3 k v a term at the highest velocity the path can have here: the
  // feed at the highest override, or the curve's own limit.
  const double v_drive = std::min(v, v_feed);
  double a = a_axis / share.path_a;
  if (k > 0) a = std::min(a, j_axis / (3 * share.turning_j * k * v_drive));
  limits_ = {v, on_grid(a), j_axis / share.path_j};
  widen_on_a_gentle_curve(k, dk, v_drive, a_axis, j_axis);
  planar_ = 0;
}

// The shares above hold at the curve's own velocity limit. Where the path
// cannot go that fast (the feed, at the highest override, is lower) and the
// curvature terms there take at most a third of each axis' limits,
//     k v_drive² <= a_axis / 3,   3 k v_drive a_t + k' v_drive³ <= j_axis / 3,
// the tangential terms get the other two thirds: a_t = 2/3 a_axis,
// j_t = 2/3 j_axis. The path then brakes and accelerates on a gentle curve
// (an HSC spline through a CAM polyline, issue 36) at twice the jerk: a
// stop from F1016 takes 0.050 s instead of 0.071. One level, not what each
// curve leaves exactly: neighbouring curves must mostly share their
// limits, as a lower limit ahead is crossed with a = 0 (the chord circle at
// F6000 ran at 1.44x its ideal time with limits that followed each curve).
void PathSegment::widen_on_a_gentle_curve(double k, double dk, double v_drive, double a_axis, double j_axis) {
  const double a_t = 2 * a_axis / 3, j_t = 2 * j_axis / 3;
  const bool gentle = k * v_drive * v_drive <= a_axis / 3 &&
                      3 * k * v_drive * a_t + dk * v_drive * v_drive * v_drive <= j_axis / 3;
  if (!gentle) return;
  limits_.a = std::max(limits_.a, on_grid(a_t));
  limits_.j = std::max(limits_.j, j_t);
}

void PathSegment::set_covered_distance(const MachineConfig& machine) {
  double main_sq = 0, leading_time = 0, leading_travel = 0;
  for (size_t i = 0; i < start_.size(); ++i) {
    const bool main_axis = is_main_axis(machine.axes[i].name);
    const bool on_circle = static_cast<int>(i) == ix_ || static_cast<int>(i) == iy_;
    const double travel = on_circle ? 0 : std::abs(end_[i] - start_[i]);
    if (main_axis) main_sq += travel * travel;
    else if (travel / machine.axes[i].v_max > leading_time) {
      leading_time = travel / machine.axes[i].v_max;
      leading_travel = travel;
    }
  }
  const double arc_length = length_ * planar_;  // 0 on a line
  main_sq += arc_length * arc_length;
  covered_distance_ = main_sq > 0 ? std::sqrt(main_sq) : leading_travel;
}

void PathSegment::set_line_limits(const Motion& m, const MachineConfig& machine) {
  double sum = 0;
  for (size_t i = 0; i < start_.size(); ++i) sum += (end_[i] - start_[i]) * (end_[i] - start_[i]);
  length_ = std::sqrt(sum);
  limits_ = {inf, inf, inf};
  if (length_ == 0) return;
  for (size_t i = 0; i < start_.size(); ++i) {
    unit_[i] = (end_[i] - start_[i]) / length_;
    const double share = std::abs(unit_[i]);
    if (share == 0) continue;
    const AxisConfig& axis = machine.axes[i];
    limits_.v = std::min(limits_.v, (m.type == MotionType::rapid ? axis.v_rapid : axis.v_max) / share);
    limits_.a = std::min(limits_.a, axis.a_max / share);
    limits_.j = std::min(limits_.j, axis.j_max / share);
  }
}

// On the circle an axis sees c*a_t + c^2 v^2/R (acceleration) and
// c*j_t + 3 c^2 v a_t/R + c^3 v^3/R^2 (jerk), c the planar share of ds.
// Each term gets a fixed part of the axis limit: the centripetal terms half
// the acceleration and a third of the jerk, which bounds v, a_t and j_t.
void PathSegment::set_arc_limits(const Motion& m, const MachineConfig& machine) {
  const std::array<int, 2> plane = arc_plane_axes(m, machine);
  ix_ = plane[0];
  iy_ = plane[1];
  cx_ = m.center[0];
  cy_ = m.center[1];
  radius_ = std::hypot(m.start[at(ix_)] - cx_, m.start[at(iy_)] - cy_);
  radius_end_ = std::hypot(m.end[at(ix_)] - cx_, m.end[at(iy_)] - cy_);
  angle0_ = std::atan2(m.start[at(iy_)] - cy_, m.start[at(ix_)] - cx_);
  direction_ = m.type == MotionType::arc_ccw ? 1 : -1;
  const double angle_end = std::atan2(m.end[at(iy_)] - cy_, m.end[at(ix_)] - cx_);
  double sweep = direction_ * (angle_end - angle0_);  // > 0 along the direction
  sweep = std::fmod(sweep + 2 * two_pi, two_pi);
  if (sweep < tolerance::length_mm) sweep = two_pi;  // end = start: full circle
  sweep_ = sweep;
  // The decoder accepts an end radius a little off the start radius; the
  // radius is blended along the arc (a spiral). On a short arc the radial
  // part can be larger than the arc itself (0.9 um across 0.01 um of arc):
  // the plane's length bounds both, so that |d(x, y)/ds| <= planar_ everywhere.
  const double dr = radius_end_ - radius_, r_max = std::max(radius_, radius_end_);
  const double arc_length = std::hypot(r_max * sweep, dr);
  double sum = arc_length * arc_length;
  for (size_t i = 0; i < start_.size(); ++i)
    if (static_cast<int>(i) != ix_ && static_cast<int>(i) != iy_)
      sum += (end_[i] - start_[i]) * (end_[i] - start_[i]);
  length_ = std::sqrt(sum);
  planar_ = arc_length / length_;

  const AxisConfig& x = machine.axes[at(ix_)];
  const AxisConfig& y = machine.axes[at(iy_)];
  const double c = planar_;
  // |d2(x, y)/ds2| <= kappa and |d3(x, y)/ds3| <= kappa_rate, with the
  // radius' rate r' = dr / L and the angle's w = sweep / L (on a circle
  // c^2 / r and c^3 / r^2).
  const double r_rate = std::abs(dr) / length_, w = sweep / length_;
  const double kappa = 2 * r_rate * w + r_max * w * w;
  const double kappa_rate = 3 * r_rate * w * w + r_max * w * w * w;
  const double a_xy = std::min(x.a_max, y.a_max), j_xy = std::min(x.j_max, y.j_max);
  double v = std::min({std::min(x.v_max, y.v_max) / c, std::sqrt(a_xy / (2 * kappa)),
                       std::cbrt(j_xy / (3 * kappa_rate))});
  double a = a_xy / (2 * c);
  double j = j_xy / (3 * c);
  for (size_t i = 0; i < start_.size(); ++i) {
    if (static_cast<int>(i) == ix_ || static_cast<int>(i) == iy_) continue;
    unit_[i] = (end_[i] - start_[i]) / length_;
    const double share = std::abs(unit_[i]);
    if (share == 0) continue;
    v = std::min(v, machine.axes[i].v_max / share);
    a = std::min(a, machine.axes[i].a_max / share);
    j = std::min(j, machine.axes[i].j_max / share);
  }
  a = std::min(a, j_xy / (9 * kappa * v));
  limits_ = {v, a, j};
}

double PathSegment::length_to(const AxisValues& point) const {
  if (!arc_) {
    double s = 0;
    for (size_t i = 0; i < start_.size(); ++i) s += (point[i] - start_[i]) * unit_[i];
    return std::clamp(s, 0.0, length_);
  }
  // Along a spiral (end radius off the start radius) the angle, not a
  // part's own length, tells where the point lies: s is linear in it.
  double turned = direction_ * (std::atan2(point[at(iy_)] - cy_, point[at(ix_)] - cx_) - angle0_);
  turned = std::fmod(turned + 2 * two_pi, two_pi);
  return turned / sweep_ * length_;
}

std::vector<double> PathSegment::position(double s) const {
  if (joint_) return joint_->curve->position(curve_position(s));
  std::vector<double> p(start_.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = start_[i] + unit_[i] * s;
  if (arc_) {
    // The decoder accepts end radii a little off the start radius: blend
    // them along the arc so the path ends exactly where it was programmed.
    const double angle = angle_at(s), r = radius_at(s);
    p[at(ix_)] = cx_ + r * std::cos(angle);
    p[at(iy_)] = cy_ + r * std::sin(angle);
  }
  return p;
}

std::vector<double> PathSegment::tangent(double s) const {
  if (joint_) {
    std::vector<double> t = joint_->curve->tangent(curve_position(s));
    if (reversed_)
      for (double& x : t) x = -x;
    return t;
  }
  std::vector<double> t(unit_.size());
  tangent(s, t.data());
  return t;
}

void PathSegment::tangent(double s, double* t) const {
  if (joint_) {
    const std::vector<double> curve_t = tangent(s);
    std::copy(curve_t.begin(), curve_t.end(), t);
    return;
  }
  std::copy(unit_.begin(), unit_.end(), t);
  if (arc_) {
    // r' u + r phi' n (u radial, n along the direction).
    const double angle = angle_at(s), radial = (radius_end_ - radius_) / length_;
    const double along = direction_ * radius_at(s) * sweep_ / length_;
    t[at(ix_)] = radial * std::cos(angle) - along * std::sin(angle);
    t[at(iy_)] = radial * std::sin(angle) + along * std::cos(angle);
  }
}

std::vector<double> PathSegment::curvature(double s) const {
  if (joint_) return joint_->curve->curvature(curve_position(s));  // the same either way
  std::vector<double> k(start_.size(), 0.0);
  if (arc_) {
    // 2 r' phi' n - r phi'^2 u (r'' = phi'' = 0).
    const double angle = angle_at(s), w = sweep_ / length_;
    const double inward = radius_at(s) * w * w, turn = 2 * direction_ * (radius_end_ - radius_) / length_ * w;
    k[at(ix_)] = -inward * std::cos(angle) - turn * std::sin(angle);
    k[at(iy_)] = -inward * std::sin(angle) + turn * std::cos(angle);
  }
  return k;
}

}  // namespace hil::cnc
