#include "contour_curve.hpp"
#include "axis_vector.hpp"
#include "tolerances.hpp"

#include <algorithm>
#include <cmath>

namespace hil::cnc {
namespace {

// 5-point Gauss-Legendre on [-1, 1].
constexpr double gl_x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
constexpr double gl_w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                            0.2369268850561891};
// Samples per interval for the bounds, and the margin for what lies between
// samples (the quantities change smoothly over 1/(intervals*samples) of u).
constexpr int bound_samples = 192;
constexpr double bound_margin = 1.1;

}  // namespace

namespace {
// The turn's blend b(u) of the tangents and its derivatives (the path's
// velocity, acceleration and jerk shape), and its integral B(u).
double blend(double u) { return u <= 0.5 ? 2 * u * u : 1 - 2 * (1 - u) * (1 - u); }
double blend_rate(double u) { return u <= 0.5 ? 4 * u : 4 * (1 - u); }
double blend_jerk(double u) { return u < 0.5 ? 4 : -4; }
double blend_integral(double u) { return u <= 0.5 ? 2 * u * u * u / 3 : u - 0.5 + 2 * (1 - u) * (1 - u) * (1 - u) / 3; }
}  // namespace

ContourCurve::ContourCurve(const End& start, const End& end, double tangent_scale, Shape shape)
    : start_(start), end_(end) {
  const size_t n = start.point.size();
  double chord_sq = 0;
  for (size_t i = 0; i < n; ++i) chord_sq += (end.point[i] - start.point[i]) * (end.point[i] - start.point[i]);
  const double L = std::sqrt(chord_sq) * tangent_scale;
  if (shape == Shape::turn && L > 0) {
    // The turn ends at L (t1 + t2) / 2 from its start: a corner's
    // symmetric span between two lines (to round-off of the coordinates).
    double miss = 0, bend = 0;
    for (size_t i = 0; i < n; ++i) {
      const double d = end.point[i] - start.point[i] - L * (start.tangent[i] + end.tangent[i]) / 2;
      miss = std::max(miss, std::abs(d));
      bend = std::max({bend, std::abs(start.curvature[i]), std::abs(end.curvature[i])});
    }
    turn_ = miss <= tolerance::length_mm && bend == 0;
  }
  if (turn_) {
    turn_L_ = L;
    turn_dt_.resize(n);
    for (size_t i = 0; i < n; ++i) turn_dt_[i] = end.tangent[i] - start.tangent[i];
    table_s_ = {0.0, L};
    return;
  }
  coefficients_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    // Bezier control points of the quintic Hermite curve.
    const double p0 = 0, p5 = end.point[i] - start.point[i];
    const double p1 = p0 + L * start.tangent[i] / 5;
    const double p2 = p0 + 2 * L * start.tangent[i] / 5 + L * L * start.curvature[i] / 20;
    const double p4 = p5 - L * end.tangent[i] / 5;
    const double p3 = p5 - 2 * L * end.tangent[i] / 5 + L * L * end.curvature[i] / 20;
    std::array<double, 6>& c = coefficients_[i];
    c[0] = p0;
    c[1] = 5 * (p1 - p0);
    c[2] = 10 * (p2 - 2 * p1 + p0);
    c[3] = 10 * (p3 - 3 * p2 + 3 * p1 - p0);
    c[4] = 5 * (p4 - 4 * p3 + 6 * p2 - 4 * p1 + p0);
    c[5] = p5 - 5 * p4 + 10 * p3 - 10 * p2 + 5 * p1 - p0;
  }
  table_s_.resize(intervals + 1, 0.0);
  for (size_t k = 0; k < static_cast<size_t>(intervals); ++k)
    table_s_[k + 1] = table_s_[k] + s_between(double(k) / intervals, double(k + 1) / intervals);
}

double ContourCurve::offset(size_t i, double u) const {
  if (turn_) return turn_L_ * (u * start_.tangent[i] + turn_dt_[i] * blend_integral(u));
  const std::array<double, 6>& c = coefficients_[i];
  return c[0] + u * (c[1] + u * (c[2] + u * (c[3] + u * (c[4] + u * c[5]))));
}

double ContourCurve::speed(double u) const {
  double sum = 0;
  for (const std::array<double, 6>& c : coefficients_) {
    const double d = c[1] + u * (2 * c[2] + u * (3 * c[3] + u * (4 * c[4] + u * 5 * c[5])));
    sum += d * d;
  }
  return std::sqrt(sum);
}

double ContourCurve::s_between(double u0, double u1) const {
  const double half = (u1 - u0) / 2, mid = (u0 + u1) / 2;
  double sum = 0;
  for (int k = 0; k < 5; ++k) sum += gl_w[k] * speed(mid + half * gl_x[k]);
  return sum * half;
}

double ContourCurve::u_at(double s) const {
  if (s <= 0) return 0;
  if (s >= length()) return 1;
  if (turn_) return s / turn_L_;
  const size_t k = static_cast<size_t>(std::upper_bound(table_s_.begin(), table_s_.end(), s) - table_s_.begin()) - 1;
  const double lo = double(k) / intervals, hi = double(k + 1) / intervals;
  double u = lo + (hi - lo) * (s - table_s_[k]) / (table_s_[k + 1] - table_s_[k]);
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double miss = table_s_[k] + s_between(lo, u) - s;
    const double step = miss / speed(u);
    u = std::clamp(u - step, lo, hi);
    if (std::abs(step) < 1e-15) break;
  }
  return u;
}

namespace {
// Path positions this close to an end are the end: its exact values.
bool at_start(double s) { return s <= 0; }
bool at_end(double s, double length) { return s >= length * (1 - tolerance::same_point_share); }
}  // namespace

std::vector<double> ContourCurve::position(double s) const {
  if (at_start(s)) return start_.point;
  if (at_end(s, length())) return end_.point;
  const double u = u_at(s);
  std::vector<double> p(start_.point.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = offset(i, u) + start_.point[i];
  return p;
}

void ContourCurve::frame(double u, Frame& f) const {
  const size_t n = start_.point.size();
  if (f.t.size() != n)
    for (std::vector<double>* v : {&f.t, &f.k, &f.dk, &f.r, &f.q, &f.w, &f.normal}) v->resize(n);
  if (turn_) {  // derivatives by s = L u
    const double b = blend(u), rate = blend_rate(u) / turn_L_, jerk = blend_jerk(u) / (turn_L_ * turn_L_);
    for (size_t i = 0; i < n; ++i) {
      f.t[i] = start_.tangent[i] + turn_dt_[i] * b;
      f.k[i] = turn_dt_[i] * rate;
      f.dk[i] = turn_dt_[i] * jerk;
    }
    return;
  }
  std::vector<double>&r = f.r, &q = f.q, &w = f.w, &normal = f.normal;
  double rr = 0;
  for (size_t i = 0; i < n; ++i) {  // d^1..3 P / du^1..3, by Horner
    const std::array<double, 6>& c = coefficients_[i];
    r[i] = (((5 * c[5] * u + 4 * c[4]) * u + 3 * c[3]) * u + 2 * c[2]) * u + c[1];
    q[i] = ((20 * c[5] * u + 12 * c[4]) * u + 6 * c[3]) * u + 2 * c[2];
    w[i] = (60 * c[5] * u + 24 * c[4]) * u + 6 * c[3];
    rr += r[i] * r[i];
  }
  // One division per frame (bounds() takes hundreds of frames per curve).
  const double sigma = std::sqrt(rr), inv = 1 / sigma, inv2 = inv * inv;
  double a = 0, qq = 0, wt = 0;
  for (size_t i = 0; i < n; ++i) {
    f.t[i] = r[i] * inv;
    a += q[i] * f.t[i];
    qq += q[i] * q[i];
    wt += w[i] * f.t[i];
  }
  // d/du of (q - a t) / sigma², then / sigma for d/ds.
  const double da = wt + (qq - a * a) * inv;
  for (size_t i = 0; i < n; ++i) {
    normal[i] = q[i] - a * f.t[i];
    f.k[i] = normal[i] * inv2;
    const double dnormal = w[i] - da * f.t[i] - a * normal[i] * inv;
    f.dk[i] = (dnormal - 2 * normal[i] * a * inv) * inv2 * inv;
  }
}

std::vector<double> ContourCurve::tangent(double s) const {
  if (at_start(s)) return start_.tangent;
  if (at_end(s, length())) return end_.tangent;
  Frame f;
  frame(u_at(s), f);
  return f.t;
}
std::vector<double> ContourCurve::curvature(double s) const {
  if (at_start(s)) return start_.curvature;
  if (at_end(s, length())) return end_.curvature;
  Frame f;
  frame(u_at(s), f);
  return f.k;
}

ContourCurve::AxisBounds ContourCurve::bounds(double s_from, double s_to) const {
  const size_t n = start_.point.size();
  AxisBounds b{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  const double u0 = u_at(s_from), u1 = u_at(s_to);
  if (turn_) {
    // Exact: b is monotonic, b' peaks at u = ½, |b''| = 4 throughout.
    const double b0 = blend(u0), b1 = blend(u1), rate = blend_rate(std::clamp(0.5, u0, u1)) / turn_L_;
    const double jerk = 4 / (turn_L_ * turn_L_);
    double dt_sq = 0;
    for (size_t i = 0; i < n; ++i) {
      const double dt = std::abs(turn_dt_[i]);
      const double t1 = start_.tangent[i];
      b.tangent[i] = std::max(std::abs(t1 + turn_dt_[i] * b0), std::abs(t1 + turn_dt_[i] * b1));
      b.curvature[i] = dt * rate;
      b.curvature_rate[i] = dt * jerk;
      dt_sq += dt * dt;
    }
    b.curvature_norm = std::sqrt(dt_sq) * rate;
    b.curvature_rate_norm = std::sqrt(dt_sq) * jerk;
    return b;
  }
  const int samples = std::max(8, static_cast<int>(bound_samples * (u1 - u0)));
  Frame f;
  for (int k = 0; k <= samples; ++k) {
    frame(u0 + (u1 - u0) * k / samples, f);
    b.curvature_norm = std::max(b.curvature_norm, std::sqrt(dot(f.k, f.k)));
    b.curvature_rate_norm = std::max(b.curvature_rate_norm, std::sqrt(dot(f.dk, f.dk)));
    for (size_t i = 0; i < n; ++i) {
      b.tangent[i] = std::max(b.tangent[i], std::abs(f.t[i]));
      b.curvature[i] = std::max(b.curvature[i], std::abs(f.k[i]));
      b.curvature_rate[i] = std::max(b.curvature_rate[i], std::abs(f.dk[i]));
    }
  }
  for (size_t i = 0; i < n; ++i) {
    b.tangent[i] = std::min(1.0, b.tangent[i] * bound_margin);
    b.curvature[i] *= bound_margin;
    b.curvature_rate[i] *= bound_margin;
  }
  b.curvature_norm *= bound_margin;
  b.curvature_rate_norm *= bound_margin;
  return b;
}

double ContourCurve::distance_to(const std::vector<double>& point) const {
  auto dist_sq = [&](double u) {
    double sum = 0;
    for (size_t i = 0; i < point.size(); ++i) {
      const double d = offset(i, u) + start_.point[i] - point[i];
      sum += d * d;
    }
    return sum;
  };
  constexpr int samples = 64;
  int best = 0;
  double best_d = dist_sq(0);
  for (int k = 1; k <= samples; ++k)
    if (const double d = dist_sq(double(k) / samples); d < best_d) {
      best_d = d;
      best = k;
    }
  // Golden-section refinement around the best sample.
  double lo = std::max(0.0, (best - 1.0) / samples), hi = std::min(1.0, (best + 1.0) / samples);
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
    if (dist_sq(m1) < dist_sq(m2)) hi = m2;
    else lo = m1;
  }
  return std::sqrt(std::min(best_d, dist_sq((lo + hi) / 2)));
}

double ContourJoint::covered(double s_from, double s_to) const {
  const auto share = [&](double lo, double hi, double covered_half) {
    const double overlap = std::min(s_to, hi) - std::max(s_from, lo);
    return hi > lo && overlap > 0 ? covered_half * overlap / (hi - lo) : 0.0;
  };
  double sum = 0;
  for (size_t i = 0; i < parts.size(); ++i) sum += share(begin(i), parts[i].end, parts[i].covered);
  return sum;
}

}  // namespace hil::cnc
