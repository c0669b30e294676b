#include "look_ahead.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bisect.hpp"
#include "corner_rule.hpp"
#include "velocity_profile.hpp"
#include "tolerances.hpp"

namespace hil::cnc {

namespace {

// TRAPEZ: the v0 whose braking to v_exit (a = 0 at both ends) after
// reaction_s at v0 covers `distance`, in closed form to round-off. The
// change is point-symmetric in time, so it covers its mean velocity times
// its duration: (v0 + v_exit) / 2 * T, T = dv / a + a / j where the
// plateau is reached (dv >= a^2 / j: a quadratic in v0), else 2 s with
// s = sqrt(dv / j) (a cubic in s, increasing: Newton from above).
double trapez_entry_estimate(double v_exit, double distance, const Limits& lim, double reaction_s) {
  const double a = lim.a, j = lim.j, r = reaction_s;
  const double dv_plateau = a * a / j;
  auto covers = [&](double v0) {
    const double dv = v0 - v_exit;
    const double t = dv >= dv_plateau ? dv / a + a / j : 2 * std::sqrt(dv / j);
    return r * v0 + (v0 + v_exit) / 2 * t;
  };
  if (covers(v_exit + dv_plateau) <= distance) {
    // v0^2 / (2a) + v0 (a / 2j + r) - (v_exit^2 / 2a - v_exit a / 2j + distance) = 0
    const double b = a / (2 * j) + r, c = v_exit * v_exit / (2 * a) - v_exit * a / (2 * j) + distance;
    return 2 * c / (b + std::sqrt(b * b + 2 * c / a));
  }
  // j s^3 + r j s^2 + 2 v_exit s + r v_exit - distance = 0, 0 <= s < a / j.
  // g is increasing and convex for s >= 0: Newton from any s above the root
  // descends onto it. Without its cubic and square terms, or without its
  // linear and square terms, g is smaller, so their roots lie above its
  // own: start from the least of them (from a / j, the braking ramps of a
  // look-ahead, dv ~ 1e-3 a^2 / j, took 8.4 steps on average, from these
  // 3.7). Where a step no longer moves s beyond round-off, s is the root.
  auto g = [&](double s) { return ((j * s + r * j) * s + 2 * v_exit) * s + r * v_exit - distance; };
  const double rest = distance - r * v_exit;
  double s = a / j;
  if (rest > 0) {
    if (v_exit > 0) s = std::min(s, rest / (2 * v_exit));
    // (cbrt is dear: only where the linear bound is far off, dv >~ v_exit)
    if (j * s * s > v_exit) s = std::min(s, std::cbrt(rest / j));
  }
  for (int i = 0; i < 40; ++i) {
    const double slope = (3 * j * s + 2 * r * j) * s + 2 * v_exit;
    const double next = s - g(s) / slope;
    if (!(next < s) || !(next >= 0)) break;
    const bool converged = s - next <= 1e-15 * s;
    s = next;
    if (converged) break;
  }
  return v_exit + j * s * s;
}

}  // namespace

double highest_entry_velocity(double v_exit, double distance, double v_cap, const Limits& lim, SlopeType slope,
                              double reaction_s) {
  if (v_cap <= v_exit) return v_cap;
  auto covers = [&](double v0) { return v0 * reaction_s + velocity_change_end({0, v0, 0, 0}, v_exit, lim, slope).p; };
  const bool closed_form = slope == SlopeType::trapez && std::isfinite(lim.j) && lim.a > 0 && lim.j > 0;
  const double estimate = closed_form ? trapez_entry_estimate(v_exit, distance, lim, reaction_s)
                                      : std::numeric_limits<double>::quiet_NaN();
  // The estimate is exact to round-off: a v_cap clearly above it does not
  // fit, no braking needs to say so (a third of the brakings measured).
  constexpr double clearly = 1e-9;
  double at_cap = std::numeric_limits<double>::quiet_NaN();
  if (!(estimate < v_cap * (1 - clearly))) {
    at_cap = covers(v_cap);
    if (at_cap <= distance) return v_cap;
  }
  // v_exit fits, v_cap does not; the distance grows with v0, smoothly.
  double good = v_exit, bad = v_cap, at_good = v_exit * reaction_s, at_bad = at_cap;
  // A hair below the estimate (far beyond its round-off) fits: one braking
  // instead of stepping to the last double that does (the look-ahead's
  // backward pass re-walks a braking ramp of ~85 pieces at every block on
  // a G261 chord polyline, issue 36 item 3; a lower v_end is only more
  // conservative for the plans that aim at it).
  const double below = estimate * (1 - entry_velocity_margin);
  if (below > good && below < bad && covers(below) <= distance) return below;
  if (estimate > good && estimate < bad) {
    // From the estimate the last double that fits is a few away: step to
    // it, and bracket it for the search where it is not.
    const double at = covers(estimate);
    const bool fits = at <= distance;
    (fits ? good : bad) = estimate;
    (fits ? at_good : at_bad) = at;
    for (int step = 0; step < 4; ++step) {
      const double next = fits ? std::nextafter(good, bad) : std::nextafter(bad, good);
      if (next == good || next == bad) return good;
      const double at_next = covers(next);
      if ((at_next <= distance) != fits) {
        (fits ? bad : good) = next;
        return good;
      }
      (fits ? good : bad) = next;
      (fits ? at_good : at_bad) = at_next;
    }
  }
  if (std::isnan(at_bad)) at_bad = covers(bad);
  return last_below(good, bad, distance, at_good, at_bad, covers);
}

LookAhead::LookAhead(const MachineConfig& machine, size_t capacity)
    : machine_(machine), builder_(machine), hsc_(machine), capacity_(capacity) {}

void LookAhead::push(const MotionPiece& piece, bool stop_before) {
  const size_t before = blocks_.size();
  PathSegment segment = piece.segment(machine_);
  if (HscSpline::smooths(piece, segment)) {
    take(hsc_.add(piece, std::move(segment), stop_before));
  } else {
    flush_spline();
    stop_before = stop_before || hsc_.take_exact_stop();
    add_to_builder(piece, std::move(segment), stop_before);
  }
  plan_pushed(before);
}

// Once for all the pieces a block brought (a contoured block's curve halves
// and middle, a spline's span): the backward pass walks the braking ramp
// behind them, some 85 pieces on a G261 chord polyline, and walked it for
// each piece (issue 36 item 3). It ends, as it did after the last of them,
// at the first limiting transition before them that keeps its v_end, and
// not before the piece they came after: its jerk share may have risen
// (push_piece), which changes the pieces before it even where its own
// v_end stays (a stop after it).
void LookAhead::plan_pushed(size_t before) {
  if (blocks_.size() > before) backward_pass(blocks_.size() - 1, before > 0 ? before - 1 : 0);
}

void LookAhead::add_to_builder(const MotionPiece& piece, PathSegment&& segment, bool stop_before) {
  ++programmed_;
  if (spline_exit_ && !blocks_.empty()) {
    const PathSegment& spline = blocks_.back().segment;
    builder_.enter_from(spline.curve_end(spline.length()), *spline_exit_);
  }
  spline_exit_.reset();
  if (!piece.out) {
    flush_pending();
    push_piece({piece.block, std::move(segment), piece.slope, stop_before, true, true});
    return;
  }
  for (PathPiece& part : builder_.add(piece, std::move(segment), stop_before)) push_piece(std::move(part));
}

// KRN-9: the builder may hold the block before a spline until the spline
// hands on its first part (the block after it may be separated: then the
// builder contours into it, G261). Where a spline and a block whose
// transition is contoured meet, the builder's curve lies on the block
// (ContourBuilder::enter_from, flush_into).
void LookAhead::take(std::vector<HscOutput>&& items) {
  for (HscOutput& item : items) {
    if (auto* separated = std::get_if<SeparatedBlock>(&item)) {
      add_to_builder(separated->piece, std::move(separated->segment), separated->stop_before);
      continue;
    }
    SplinePiece& spline = std::get<SplinePiece>(item);
    PathPiece& part = spline.piece;
    for (PathPiece& piece : part.stop_before ? builder_.flush() : builder_.flush_into(part.segment.curve_end(0)))
      push_piece(std::move(piece));
    part.stop_before = part.stop_before || builder_.take_exact_stop();
    push_spline_piece(std::move(part));
    spline_exit_ = spline.exit;
  }
}

double LookAhead::path_length() const {
  double sum = 0;
  for (const LookAheadPiece& b : blocks_) sum += b.segment.length();
  return sum;
}

// The blocks a spline holds back for its fits (some 40 of 0.1 mm) count
// only once it hands them over: counted before, they shortened the plan's
// horizon to what a path on the spline could brake within (89 of F6000's
// 100 mm/s on the chord circle).
void LookAhead::push_spline_piece(PathPiece&& piece) {
  ++programmed_;
  push_piece(std::move(piece));
}

void LookAhead::flush_spline() { take(hsc_.flush()); }

void LookAhead::flush_pending() {
  flush_spline();
  for (PathPiece& piece : builder_.flush()) push_piece(std::move(piece));
}

void LookAhead::flush() {
  const size_t before = blocks_.size();
  flush_pending();
  if (blocks_.empty() || motion_ends_) return;
  // Known now: no curvature step after the last piece. A piece pushed after
  // all is entered from a stop, as planned.
  motion_ends_ = true;
  const size_t last = blocks_.size() - 1;
  if (!blocks_[last].after_curvature_step) blocks_[last].jerk_share = 1;
  backward_pass(last, std::min(before, last));
}

void LookAhead::pop_front() {
  if (blocks_.front().ends_block && programmed_ > 0) --programmed_;
  blocks_.pop_front();
}

void LookAhead::clear() {
  spline_exit_.reset();
  motion_ends_ = false;
  blocks_.clear();
  builder_.clear();
  hsc_.clear();
  programmed_ = 0;
}

// The last piece is planned at the share a curvature step into what
// follows would give it, until that is known: a later push only raises it.
// Halved only once the next piece came, it took away jerk a braking in it
// already used: from a < 0, v < a^2 / j, every plan at the halved jerk ran
// the velocity below 0 (fuzz AJ: the path 1e-4 mm past its stop and back;
// contour seed 13009555: an arc entered at the velocity from which it could
// stop for a dwell at full jerk, not at half).
void LookAhead::push_piece(PathPiece&& piece) {
  spline_exit_.reset();
  bool after_step = false;
  if (!blocks_.empty()) {
    LookAheadPiece& back = blocks_.back();
    const Junction j = junction(back.segment, piece.segment, machine_);
    if (motion_ends_) piece.stop_before = true;
    back.junction_limit = piece.stop_before ? 0.0 : j.v_max;
    // The path stands at a stop there: no curvature step to pass. Nor where
    // the corner rule lets none pass (a kink between blocks too short to
    // space it, kink_spacing_velocity): fuzz contour seed 23002858, a 1.35 um
    // block's curve halves planned at full jerk, then halved by a 21 nm rest
    // after them.
    after_step = j.curvature_step && !piece.stop_before && j.v_max > 0;
    back.curvature_step = after_step;
    back.jerk_share = after_step || back.after_curvature_step ? curvature_step_jerk_share : 1.0;
  }
  motion_ends_ = false;
  blocks_.emplace_back(std::move(piece)).after_curvature_step = after_step;
}

void LookAhead::set_velocity_factor(double factor) {
  if (factor == factor_) return;
  factor_ = factor;
  if (!blocks_.empty()) backward_pass(blocks_.size() - 1, 0);  // all of it: every cruise velocity moved
}

Limits LookAhead::cruise_limits(size_t i) const {
  const PathSegment& seg = blocks_[i].segment;
  Limits lim = seg.limits();
  lim.v = std::min(lim.v, factor_ * seg.programmed_velocity());
  lim.j *= blocks_[i].jerk_share;
  return lim;
}

// The stretch runs on to the first limiting transition. A non-limiting
// block's v_end is only its cruise velocity, not what the transitions after
// it need, so a stretch must not end there with that v_end: it made the
// path leave the block at cruise velocity, and a short block before a
// reversal then left too little way to stop (KRN-3: 66,609 mm/s^2 on X for
// N10 G01 X1 F3000 / X2 / X3 / X4 / X0, where the velocity reached lay a
// rounding above the cruise velocity and ended the stretch at N30; and after
// a lower override the path ended every short block at its new cruise
// velocity, with a = 0, instead of braking through them).
//
// One reason to end it early remains: the path moves faster than a
// non-limiting transition allows (after a lower override, feed hold or a
// stop request the cruise velocity drops below v_now, and transitions
// stop limiting because nothing is above the new cruise). There the stretch
// ends with the highest velocity from which the next limiting transition
// can still be kept (what the backward pass gives a limiting transition).
Stretch LookAhead::stretch(double v_now, size_t pass_through) const {
  Stretch st{0, 0, cruise_limits(0), blocks_.front().slope};
  size_t passed = 0;
  for (size_t i = 0; i < blocks_.size(); ++i) {
    const Limits lim = cruise_limits(i);
    st.lim.a = std::min(st.lim.a, lim.a);
    st.lim.j = std::min(st.lim.j, lim.j);
    st.length += blocks_[i].segment.length();
    st.v_end = blocks_[i].v_end;
    // Only a transition limiting by the programmed velocities alone: not a
    // curvature step, nor into lower limits or another slope (those the
    // path must pass with a = 0).
    const bool passable = i + 1 < blocks_.size() && blocks_[i + 1].slope == st.slope &&
                          blocks_[i].junction_limit >= v_now && blocks_[i].jerk_share == 1 &&
                          blocks_[i + 1].jerk_share == 1 && cruise_limits(i + 1).a >= (1 - tolerance::limit_share) * lim.a &&
                          cruise_limits(i + 1).j >= (1 - tolerance::limit_share) * lim.j;
    if (blocks_[i].limiting && passed < pass_through && passable) {
      ++passed;
      st.lim.v = std::min({st.lim.v, blocks_[i].junction_limit, cruise_limits(i + 1).v});
      continue;
    }
    if (blocks_[i].limiting) break;
    if (blocks_[i].junction_limit < v_now * (1 - tolerance::limit_share)) {  // not a rounding above it (cruising at v_max)
      st.v_end = std::min(st.v_end, entry_velocity_after(i));
      break;
    }
  }
  return st;
}

double LookAhead::entry_velocity_after(size_t i) const {
  double distance = 0;
  Limits lim{cruise_limits(i + 1).v, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  size_t k = i + 1;
  for (; k < blocks_.size(); ++k) {  // the last block is limiting
    const Limits next = cruise_limits(k);
    distance += blocks_[k].segment.length();
    lim.a = std::min(lim.a, next.a);
    lim.j = std::min(lim.j, next.j);
    if (blocks_[k].limiting) break;
  }
  return highest_entry_velocity(blocks_[k].v_end, distance, blocks_[i].v_end, lim, blocks_[i + 1].slope,
                                machine_.cycle_time_s());
}

void LookAhead::backward_pass(size_t last, size_t settled_before) {
  blocks_[last].v_end = 0;  // nothing known beyond it: it must be able to stop
  blocks_[last].limiting = true;
  double v_next = 0, distance = 0;  // of the next limiting transition
  Limits lim{0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (size_t i = last; i-- > 0;) {
    const LookAheadPiece& next = blocks_[i + 1];
    const Limits next_lim = cruise_limits(i + 1);
    distance += next.segment.length();
    lim = {next_lim.v, std::min(lim.a, next_lim.a), std::min(lim.j, next_lim.j)};
    LookAheadPiece& b = blocks_[i];
    const Limits own = cruise_limits(i);
    const double cruise = own.v;
    const double cap = std::min({b.junction_limit, cruise, next_lim.v});
    // Into lower acceleration or jerk limits (a line into a tangent arc)
    // the path passes with a = 0, so that a stretch's limits are its front
    // block's: replanned from a later block of it, the limits never drop
    // under an acceleration the path already carries (it would be unwound
    // at the lower jerk and carry the velocity below 0: the path ran
    // backward for a moment after a lower override or feed hold).
    // Collinear lines from rounded end points differ in their limits by
    // round-off: not lower. (A cap a rounding below the cruise velocity made
    // such a transition limiting once an override above 100 % lifted the
    // cruise velocity to the axes' limit: the path, braking through it for
    // the program end, had to reach it with a = 0 and could not, KRN-3.)
    constexpr double same = 1 - tolerance::limit_share;
    // A curvature step (a near-tangent kink) is crossed with a = 0 below
    // the cruise velocity too: its rule assumes it (corner_rule.hpp), and
    // the stretches then brake through a chain of them as the path can.
    // Passed at cruise, a path braking for a corner after a chain of
    // kinks carried an acceleration no plan could unwind once an override
    // raise lifted the cruise above them (issue 36, fuzz contour seed
    // 24002435: the corner run through at 8.6 mm/s, X 492,652 mm/s^3).
    b.limiting = cap < same * std::max(cruise, next_lim.v) || b.curvature_step || b.slope != next.slope ||
                 next_lim.a < same * own.a || next_lim.j < same * own.j;
    if (!b.limiting) {
      b.v_end = cap;  // the path passes at cruise velocity or below
      continue;
    }
    const double v = highest_entry_velocity(v_next, distance, cap, lim, next.slope, machine_.cycle_time_s());
    if (i < settled_before && v == b.v_end) break;
    b.v_end = v_next = v;
    distance = 0;
    lim.a = lim.j = std::numeric_limits<double>::infinity();
  }
}

}  // namespace hil::cnc
