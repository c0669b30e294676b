#include "hsc_spline.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "axis_vector.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

constexpr double deg = M_PI / 180;
// Points of a span checked against the polyline, per block it replaces.
constexpr int samples_per_block = 8;
// A span longer than this share of the polyline it replaces wiggles (an arc
// over chords turning 29 degrees each is 1.1 % longer than they are).
constexpr double longest_share = 1.02;
// Points behind the last span kept for the fits, beyond what they need.
constexpr size_t drop_batch = 64;

// The bend from line a into line b (rad).
double bend(const PathSegment& a, const PathSegment& b) {
  return std::acos(std::clamp(dot(a.tangent(a.length()), b.tangent(0)), -1.0, 1.0));
}

// The parameters that shape a spline (ON, the AUTO_OFF_G00/G60 switches and
// MAX_PATH_LENGTH act on single blocks).
bool same_spline(const HscMode& a, const HscMode& b) {
  return a.path_dev == b.path_dev && a.track_dev == b.track_dev && a.merge == b.merge &&
         a.auto_off_path == b.auto_off_path && a.auto_off_track == b.auto_off_track && a.max_angle == b.max_angle;
}

}  // namespace

bool HscSpline::smooths(const MotionPiece& piece, const PathSegment& segment) {
  if (!piece.out || !piece.out->hsc.on || !piece.whole_block || piece.curve) return false;
  if (piece.motion.type != MotionType::linear) return false;
  const double longest = piece.out->hsc.max_path_length;
  return !(longest > 0 && segment.length() > longest) && segment.length() > tolerance::shortest_part_mm;
}

bool HscSpline::continues_with(const PathSegment& segment, const HscMode& mode) const {
  if (members_.empty() || !same_spline(mode, mode_)) return false;
  const std::vector<double> start = segment.position(0);
  for (size_t i = 0; i < start.size(); ++i)
    if (std::abs(start[i] - points_.back()[i]) > tolerance::no_length_mm) return false;
  const double corner = (mode.max_angle > 0 ? mode.max_angle : hsc_corner_angle_deg) * deg;
  return bend(members_.back().segment, segment) <= corner;
}

std::vector<HscOutput> HscSpline::add(const MotionPiece& piece, PathSegment segment, bool stop_before) {
  std::vector<HscOutput> out;
  stop_before = stop_before || take_exact_stop();
  if (has_open() && (stop_before || !continues_with(segment, piece.out->hsc))) close(out);
  if (!has_open()) {
    mode_ = piece.out->hsc;
    points_ = {segment.position(0)};
    chord_ = {0.0};
  }
  points_.push_back(segment.end());
  chord_.push_back(chord_.back() + segment.length());
  members_.push_back({piece, std::move(segment), stop_before});
  if (piece.out->transition == BlockTransition::exact_stop) {
    close(out);
    exact_stop_next_ = true;
  } else {
    emit(false, out);
    drop_behind();
  }
  return out;
}

std::vector<HscOutput> HscSpline::flush() {
  std::vector<HscOutput> out;
  if (has_open()) close(out);
  return out;
}

void HscSpline::clear() {
  forget_run();
  exact_stop_next_ = false;
}

bool HscSpline::take_exact_stop() { return std::exchange(exact_stop_next_, false); }

void HscSpline::close(std::vector<HscOutput>& out) {
  // A run of one block is no spline: its line, with its own limits.
  if (members_.size() == 1 && done_ == 0) separate(0, 1, out);
  else emit(true, out);
  forget_run();
}

void HscSpline::forget_run() {
  points_.clear();
  chord_.clear();
  members_.clear();
  done_ = 0;
  done_knot_.reset();
}

// The fit around point k over `half_window` mm on either side (at least
// the neighbours); nothing where it has fewer than three points or no
// direction.
std::optional<HscSpline::Fit> HscSpline::fit(size_t k, double half_window) const {
  const size_t n = points_.size(), axes = points_[k].size();
  size_t lo = k, hi = k;
  while (lo > 0 && (lo == k || chord_[k] - chord_[lo - 1] <= half_window)) --lo;
  while (hi + 1 < n && (hi == k || chord_[hi + 1] - chord_[k] <= half_window)) ++hi;
  const Eigen::Index m = static_cast<Eigen::Index>(hi - lo + 1);
  if (m < 3) return std::nullopt;
  const Eigen::Index degree = std::min<Eigen::Index>(3, m - 1);
  // Scaled parameter (conditioning): t in about [-1, 1].
  const double scale = std::max(chord_[hi] - chord_[k], chord_[k] - chord_[lo]);
  Eigen::MatrixXd basis(m, degree + 1), values(m, static_cast<Eigen::Index>(axes));
  for (Eigen::Index r = 0; r < m; ++r) {
    const size_t i = lo + static_cast<size_t>(r);
    const double t = (chord_[i] - chord_[k]) / scale;
    double power = 1;
    for (Eigen::Index c = 0; c <= degree; ++c, power *= t) basis(r, c) = power;
    for (size_t a = 0; a < axes; ++a) values(r, static_cast<Eigen::Index>(a)) = points_[i][a] - points_[k][a];
  }
  const Eigen::MatrixXd c = basis.colPivHouseholderQr().solve(values);
  Fit result{std::vector<double>(axes), std::vector<double>(axes),
             (basis * c - values).rowwise().norm().maxCoeff(), hi - lo};
  for (size_t a = 0; a < axes; ++a) {
    result.d1[a] = c(1, static_cast<Eigen::Index>(a)) / scale;
    result.d2[a] = 2 * c(2, static_cast<Eigen::Index>(a)) / (scale * scale);
  }
  const double speed = std::sqrt(dot(result.d1, result.d1));
  if (!(speed > 0) || !std::isfinite(speed)) return std::nullopt;
  return result;
}

// A cubic over 2 mm cannot follow a letter's tip of 0.3 mm (real CAM
// output, tests/programs/public/jscut_jsdc.nc): its tangent there was so far
// off that no span met PATH_DEV, and the blocks, separated, stopped at every
// corner. Where the fit misses its own points by more than a quarter of
// PATH_DEV, the window is halved while more than the neighbours remain; a
// CAM program's rounding (7e-5 mm at 4 decimals, 7e-4 at 3) stays below it.
HscSpline::Knot HscSpline::knot(size_t k) const {
  const size_t axes = points_[k].size();
  Knot result{points_[k], std::vector<double>(axes, 0.0), std::vector<double>(axes, 0.0)};
  std::optional<Fit> f = fit(k, fit_half_window_mm);
  const double misses = mode_.path_dev > 0 ? mode_.path_dev / 4 : std::numeric_limits<double>::infinity();
  for (double window = fit_half_window_mm / 2; f && f->largest_miss > misses && f->intervals > 2; window /= 2) {
    std::optional<Fit> narrower = fit(k, window);
    if (!narrower) break;
    f = std::move(narrower);
  }
  if (!f) {  // a run of one block: its line
    result.tangent = (k < members_.size() ? members_[k].segment : members_[k - 1].segment).tangent(0);
    return result;
  }
  const double speed = std::sqrt(dot(f->d1, f->d1));
  for (size_t a = 0; a < axes; ++a) result.tangent[a] = f->d1[a] / speed;
  const double along = dot(f->d2, result.tangent);
  for (size_t a = 0; a < axes; ++a) result.curvature[a] = (f->d2[a] - along * result.tangent[a]) / (speed * speed);
  return result;
}

std::optional<size_t> HscSpline::span_end(size_t from, bool closing) const {
  const size_t last = points_.size() - 1;
  size_t to = from + 1;
  if (to > last) return std::nullopt;
  if (mode_.merge) {
    double turned = 0;
    while (to < last) {
      turned += bend(members_[to - 1].segment, members_[to].segment);
      if (chord_[to + 1] - chord_[from] > merge_span_mm || turned > hsc_span_turn_deg * deg) break;
      ++to;
    }
    if (to == last && !closing) return std::nullopt;  // the span may take more
  }
  // Its end knot's fit needs the points up to the window's end.
  if (!closing && chord_[last] - chord_[to] < fit_half_window_mm) return std::nullopt;
  return to;
}

void HscSpline::emit(bool closing, std::vector<HscOutput>& out) {
  while (done_ + 1 < points_.size()) {
    const std::optional<size_t> to = span_end(done_, closing);
    if (!to) return;
    const Knot a = done_knot_ ? *done_knot_ : knot(done_);
    Knot b = knot(*to);
    emit_span(done_, *to, a, b, out);
    done_ = *to;
    done_knot_ = std::move(b);
  }
}

bool HscSpline::within_tolerance(const ContourCurve& curve, size_t from, size_t to) const {
  const double polyline = chord_[to] - chord_[from];
  if (!(curve.length() <= longest_share * polyline) || !std::isfinite(curve.length())) return false;
  const bool path = mode_.path_dev > 0, track = mode_.track_dev > 0;
  if (!path && !track) return true;
  std::vector<char> main_axis;  // by axis: out of the loops below (a name's comparison was a third of their cost)
  for (const AxisConfig& axis : machine_.axes) main_axis.push_back(is_main_axis(axis.name) ? 1 : 0);
  const int samples = std::max(16, samples_per_block * static_cast<int>(to - from));
  for (int k = 1; k < samples; ++k) {
    const std::vector<double> q = curve.position(curve.length() * k / samples);
    // Nearest point of the polyline in the main axes; the other axes' miss there.
    double best_main = std::numeric_limits<double>::infinity(), best_track = 0;
    for (size_t i = from; i < to; ++i) {
      const std::vector<double>& p0 = points_[i];
      const std::vector<double>& p1 = points_[i + 1];
      double along = 0, size = 0;
      for (size_t a = 0; a < q.size(); ++a)
        if (main_axis[a]) {
          along += (q[a] - p0[a]) * (p1[a] - p0[a]);
          size += (p1[a] - p0[a]) * (p1[a] - p0[a]);
        }
      const double u = size > 0 ? std::clamp(along / size, 0.0, 1.0) : 0.5;
      double main = 0, track_miss = 0;
      for (size_t a = 0; a < q.size(); ++a) {
        const double miss = q[a] - (p0[a] + u * (p1[a] - p0[a]));
        if (main_axis[a]) main += miss * miss;
        else track_miss = std::max(track_miss, std::abs(miss));
      }
      if (main < best_main) {
        best_main = main;
        best_track = track_miss;
      }
    }
    if (path && std::sqrt(best_main) > mode_.path_dev) return false;
    if (track && best_track > mode_.track_dev) return false;
  }
  if (path)
    for (size_t i = from + 1; i < to; ++i)
      if (curve.distance_to(points_[i]) > mode_.path_dev) return false;
  return true;
}

void HscSpline::emit_span(size_t from, size_t to, const Knot& a, const Knot& b, std::vector<HscOutput>& out) {
  auto curve = std::make_shared<const ContourCurve>(a, b);
  if (!within_tolerance(*curve, from, to)) {
    if (to - from > 1 && !mode_.auto_off_path && !mode_.auto_off_track) {
      const size_t middle = (from + to) / 2;
      const Knot m = knot(middle);
      emit_span(from, middle, a, m, out);
      emit_span(middle, to, m, b, out);
    } else {
      separate(from, to, out);
    }
    return;
  }
  auto joint = std::make_shared<ContourJoint>();
  joint->curve = curve;
  const double length = curve->length(), polyline = chord_[to] - chord_[from];
  for (size_t i = from; i < to; ++i) {
    const PathSegment& s = members_[i].segment;
    const double end = i + 1 == to ? length : length * (chord_[i + 1] - chord_[from]) / polyline;
    joint->parts.push_back({members_[i].piece.block, s.covered_distance(), s.programmed_velocity(),
                            Limits::none(), end});
  }
  std::shared_ptr<const ContourJoint> shared = std::move(joint);
  for (size_t i = from; i < to; ++i) {
    const size_t part = i - from;
    out.emplace_back(SplinePiece{
        PathPiece{members_[i].piece.block,
                  PathSegment(shared, shared->begin(part), shared->parts[part].end, false, machine_),
                  members_[i].piece.slope, members_[i].stop_before, true, true},
        *members_[i].piece.out});
  }
}

void HscSpline::separate(size_t from, size_t to, std::vector<HscOutput>& out) {
  for (size_t i = from; i < to; ++i)
    out.emplace_back(SeparatedBlock{members_[i].piece, members_[i].segment, members_[i].stop_before});
}

void HscSpline::drop_behind() {
  size_t keep = done_;
  while (keep > 0 && chord_[done_] - chord_[keep - 1] <= fit_half_window_mm) --keep;
  if (keep > 0) --keep;  // the neighbour a fit takes in any case
  if (keep < drop_batch) return;
  const auto n = static_cast<std::ptrdiff_t>(keep);
  points_.erase(points_.begin(), points_.begin() + n);
  chord_.erase(chord_.begin(), chord_.begin() + n);
  members_.erase(members_.begin(), members_.begin() + n);
  done_ -= keep;
}

}  // namespace hil::cnc
