#pragma once
// The contouring curve of polynomial contouring (KRN-6): a quintic
// polynomial from one point to another that takes the position, the unit
// tangent and the curvature vector (d²x/ds²) of the path at both ends, so
// that the path stays continuous in tangent and curvature through it.
// Quintic Hermite form with |dP/du| = L at both ends and d²P/du² = L² k
// there, L = the chord times `tangent_scale`. Evaluated by path length s
// (0 .. length()).
//
// A lone corner between two lines takes another shape (Shape::turn): the
// jerk-limited turn of docs/CONTOURING.md "Corner speed bound", whose
// velocity vector blends the two tangents with a triangular acceleration,
//     dP/du = L (t1 + (t2 - t1) b(u)),  b = 2u² (u <= ½), 1 - 2(1 - u)²,
// L = the chord / cos(θ/2) (θ between t1 and t2), measured by its
// parameter: s = L u. A path passing it at one ds/dt turns as that bound
// does, its speed dipping to cos(θ/2) of ds/dt in the middle, instead of
// running the whole curve at the speed of its tightest point. |dP/ds| is 1
// at the ends and at most 1 between; tangent(), curvature() and bounds()
// are the derivatives by s (not the unit tangent and the curvature), which
// is what the axes see: velocity dP/ds v, acceleration d²P/ds² v² + dP/ds a.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "slope.hpp"

namespace hil::cnc {

class ContourCurve {
 public:
  struct End {
    std::vector<double> point, tangent, curvature;  // per axis
  };
  enum class Shape { quintic, turn };
  // Shape::turn: `start` and `end` d before and d after the corner on two
  // lines (curvatures 0); anything else makes a quintic.
  ContourCurve(const End& start, const End& end, double tangent_scale = 1, Shape shape = Shape::quintic);
  Shape shape() const { return turn_ ? Shape::turn : Shape::quintic; }

  double length() const { return table_s_.back(); }
  std::vector<double> position(double s) const;
  std::vector<double> tangent(double s) const;
  std::vector<double> curvature(double s) const;

  // Largest |t_i|, |k_i| and |dk_i/ds| of each axis between s_from and s_to
  // (sampled densely, with a margin for what lies between the samples).
  struct AxisBounds {
    std::vector<double> tangent, curvature, curvature_rate;
    double curvature_norm = 0, curvature_rate_norm = 0;  // of the vectors k and dk/ds
  };
  AxisBounds bounds(double s_from, double s_to) const;
  // Smallest distance between `point` and the curve.
  double distance_to(const std::vector<double>& point) const;

 private:
  static constexpr int intervals = 32;
  double u_at(double s) const;
  double speed(double u) const;
  double s_between(double u0, double u1) const;
  // Per axis the power-basis coefficients c0 .. c5 of u, relative to the
  // start point (small numbers: the end tangents come out to round-off of
  // the curve's size, not of the machine coordinates).
  std::vector<std::array<double, 6>> coefficients_;
  End start_, end_;  // what the ends must be, exactly
  std::vector<double> table_s_;  // s at u = k / intervals
  // Shape::turn: t2 - t1 and L (t1 is start_'s; the coefficients are unused).
  bool turn_ = false;
  std::vector<double> turn_dt_;
  double turn_L_ = 0;
  // P(u) less the start point, on axis i.
  double offset(size_t i, double u) const;
  struct Frame {
    std::vector<double> t, k, dk;  // tangent, curvature, dk/ds
    std::vector<double> r, q, w, normal;  // d^1..3 P/du^3, q - (q.t) t: kept for the next frame
  };
  // Into `f`, whose vectors keep their memory from frame to frame (bounds()
  // takes hundreds: allocating them was half the contour's planning time).
  void frame(double u, Frame& f) const;
};

// A contouring curve where it replaces a corner (KRN-6), or a span of the
// HSC spline (KRN-9), parted among the blocks it belongs to: a corner's
// curve has two parts, the half up to the split belongs to the block before
// the corner (in the travel direction it was built for), the rest to the
// block after it; a spline span one part per programmed block it replaces.
// Each part covers the programmed distance it replaces (DPS-1) and runs at
// most at its block's programmed velocity. Backward motion and a turn
// inside the curve run along the same curve (the rest of it, either way).
struct ContourJoint {
  std::shared_ptr<const ContourCurve> curve;
  struct Part {
    size_t block = 0;
    double covered = 0;
    double programmed_velocity = 0;
    // The lift function's caps of its block (Motion::path_caps): a curve
    // into or out of a lift range keeps the range's caps on its half.
    Limits caps = Limits::none();
    double end = 0;  // where on the curve it ends (the last: exactly the curve's length)
  };
  std::vector<Part> parts;  // in the curve's direction
  // A corner's curve no other curve meets (ContourBuilder): short, between
  // the blocks' own geometry, which the path passes at about one velocity.
  // Its limits give the curvature terms most of the axes' acceleration and
  // jerk (PathSegment::set_contour_limits).
  bool lone_corner = false;
  // An axis' acceleration divided by curvature_a goes to k v², by path_a to
  // a_t; its jerk divided by curvature_j to k' v³, by turning_j to 3 k v a_t,
  // by path_j to j_t.
  struct LimitShares {
    double curvature_a, path_a, curvature_j, turning_j, path_j;
  };
  static constexpr LimitShares thirds{2, 2, 3, 3, 3};
  static constexpr LimitShares lone_shares{1.5, 3, 1.5, 6, 6};  // 2/3 to the curvature terms
  double begin(size_t part) const { return part == 0 ? 0.0 : parts[part - 1].end; }
  // What [s_from, s_to] of the curve covers of the programmed distance.
  double covered(double s_from, double s_to) const;
};

}  // namespace hil::cnc
