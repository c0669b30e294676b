#pragma once
// Look-ahead over the next motion blocks (KRN-3, FCT_LOOK_AHEAD_STANDARD =
// 120): for each block the highest velocity it may end with, so that every
// later block transition (corner rule) and a stop at the end of the last
// known block can still be kept, under the programmed velocities scaled by
// override and feed hold.
#include <cstddef>

#include "contour_builder.hpp"
#include "corner_rule.hpp"
#include "hsc_spline.hpp"
#include "machine_config.hpp"
#include "path_segment.hpp"
#include "ring_queue.hpp"
#include "slope.hpp"

namespace hil::cnc {

// A piece of the path as the look-ahead plans it: its geometry (a
// programmed block, or a part of one, or a contouring curve's half,
// KRN-6), and what the look-ahead found for it.
struct LookAheadPiece : PathPiece {
  // Made in its place in the look-ahead: a PathSegment is large to move.
  explicit LookAheadPiece(PathPiece&& piece) : PathPiece(std::move(piece)) {}

  double junction_limit = 0;  // corner rule into the next block; 0 while none follows
  // Of its path jerk limit: less next to a curvature step, and as the last
  // piece (a step into what follows may come).
  double jerk_share = curvature_step_jerk_share;
  bool curvature_step = false;  // into the next block (or a near-tangent kink): crossed with a = 0
  bool after_curvature_step = false;  // from the piece before
  // Highest velocity at its end: the corner rule and the programmed
  // velocities on both sides, and what the stretches after it allow.
  double v_end = 0;
  // The velocity must drop below a cruise velocity here (a corner, a feed
  // change), or a curvature step is crossed (with a = 0, whatever the
  // cruise velocity), or the slope type changes, or the next
  // block's acceleration or jerk limit is lower (passed with a = 0), or
  // nothing follows yet: where stretches end.
  bool limiting = true;
};

// The blocks from the front up to the first limiting transition: planned as
// one motion, so the path accelerates and brakes through transitions it
// need not slow down for (collinear lines, tangent arcs whose curvature
// allows the cruise velocity).
struct Stretch {
  double length = 0;  // path length, from the start of the front block
  double v_end = 0;   // velocity at its end
  Limits lim;         // v: cruise velocity; a, j: the lowest of its blocks
  SlopeType slope = SlopeType::trapez;
};

class LookAhead {
 public:
  static constexpr size_t fct_look_ahead_standard = 120;

  explicit LookAhead(const MachineConfig& machine, size_t capacity = fct_look_ahead_standard);

  // Pieces to plan (a contoured block waits for the next, see ContourBuilder).
  bool empty() const { return blocks_.empty(); }
  // Counted in programmed blocks, not pieces.
  bool full() const { return programmed_ >= capacity_; }
  size_t size() const { return blocks_.size(); }
  // Of the pieces to plan, from the front's start.
  double path_length() const;
  const LookAheadPiece& front() const { return blocks_.front(); }

  // The next piece; its `out` says how the path is to leave it into the
  // next one pushed (KRN-6: contoured with G261/G61); without one it is
  // taken as it is, not contoured (the DDTG short cut, DDTG-2; a span of a
  // contouring curve after a turn or a restart). stop_before: the path
  // must stand still where it starts (an M function synchronised before
  // its motion, a dwell).
  void push(const MotionPiece& piece, bool stop_before = false);
  // Nothing follows (the program's end, a stop placed, a block that cannot
  // be moved): a block waiting for its successor ends as programmed, and
  // the last piece gets its full jerk share back (no curvature step after
  // it); a piece pushed after all is entered from a stop.
  void flush();
  void pop_front();
  void clear();

  // Override times feed hold (0): scales every programmed velocity.
  void set_velocity_factor(double factor);

  // What block i is driven under: the dynamic limits with v lowered to the
  // scaled programmed velocity.
  Limits cruise_limits(size_t i) const;

  // The stretch that starts with the front block, for a path now moving at
  // v_now: up to the first limiting transition, or to a transition slower
  // than v_now (with an end velocity from which the next limiting one can
  // still be kept). `pass_through`: so many limiting transitions it runs
  // through (with v at most their junction limit, which must allow v_now):
  // one that turned limiting by an override change while the path brakes
  // through it can demand what the braking path cannot meet (KRN-3).
  Stretch stretch(double v_now, size_t pass_through = 0) const;

 private:
  // New v_end from block `last` down to the front, stretch by stretch: from
  // a limiting transition with a = 0 the path must reach the next one's
  // v_end within the stretch between. It stops at the first limiting
  // transition before `settled_before` that keeps its v_end.
  void backward_pass(size_t last, size_t settled_before);
  // After pieces were pushed from index `before` on.
  void plan_pushed(size_t before);
  // The highest velocity at the end of the non-limiting block i from which
  // the path still reaches the next limiting transition's v_end.
  double entry_velocity_after(size_t i) const;

  void push_piece(PathPiece&& piece);
  void push_spline_piece(PathPiece&& piece);  // counted as a programmed block
  void add_to_builder(const MotionPiece& piece, PathSegment&& segment, bool stop_before);
  void take(std::vector<HscOutput>&& items);  // what the spline hands on
  void flush_spline();
  void flush_pending();  // the builder's and the spline's blocks, without planning

  const MachineConfig& machine_;
  ContourBuilder builder_;
  HscSpline hsc_;
  // How the path leaves the block of the spline piece pushed last, while
  // nothing was pushed after it (the builder's curve into the next block).
  std::optional<Corner> spline_exit_;
  bool motion_ends_ = false;  // flush() said nothing follows the last piece
  size_t programmed_ = 0;  // blocks pushed and not yet popped (the last piece of each)
  size_t capacity_;
  double factor_ = 1;
  RingQueue<LookAheadPiece> blocks_;
};

// Relative: how far below the last double that fits highest_entry_velocity
// may answer (TRAPEZ: its closed form less this, checked by one braking).
constexpr double entry_velocity_margin = 1e-12;

// The highest velocity v0 <= v_cap (to entry_velocity_margin) from which a
// velocity change (a = 0 at both ends) reaches v_exit within `distance`,
// after going on at v0 for up to `reaction_s` first: the channel samples
// the path at its cycle time, and a plan that ends on a transition between
// two cycles is followed by the next one only from the next cycle
// (replanned there, the path has moved on at v0 for up to one cycle;
// without that reaction v0 was the exact limit, and any such delay, or
// rounding, left the next block too short to keep v_exit).
double highest_entry_velocity(double v_exit, double distance, double v_cap, const Limits& lim, SlopeType slope,
                              double reaction_s = 0);

}  // namespace hil::cnc
