#pragma once
// The interpolator (KRN-3): moves the path along the decoded program at the
// cycle time, on the plan of the look-ahead, in the travel direction
// (KRN-5). The channel's functions act on it through a narrow interface:
// where the path stands, leave the front block, go on from standstill,
// turn, stop at a path position, the velocity factor of the path's hold.
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "block.hpp"
#include "block_source.hpp"
#include "block_window.hpp"
#include "look_ahead.hpp"
#include "motion_piece.hpp"
#include "machine_config.hpp"
#include "motion_profile.hpp"
#include "path_stop.hpp"
#include "program_position.hpp"
#include "position_profile.hpp"
#include "ring_queue.hpp"

namespace hil::cnc {

struct AxisSetpoint {
  double position = 0;      // mm
  double velocity = 0;      // mm/s
  double acceleration = 0;  // mm/s^2
};

// What the interpolator tells the channel while it moves.
class PathObserver {
 public:
  // The interpolator reached `block`: one without motion, or a motion block
  // now in front; `index` is its place in the program. run_commands: its
  // commands (M functions, dwell, #DISTANCE PROG START) run now; they run
  // once, and never backward.
  virtual void reach_block(const Block& block, size_t index, bool run_commands) = 0;
  // The path left a block, or part of it: what that adds to the distance
  // from program start, signed by the direction (DPS-1).
  virtual void travelled(double covered_distance) = 0;
  // The path finished the block at `index` of the program.
  virtual void finish_block(size_t index) = 0;

 protected:
  ~PathObserver() = default;
};

// Where the path stood in its front block when it left it.
struct StopPoint {
  size_t block = 0;         // of the front segment
  double front_length = 0;  // of the front segment
  double s = 0;             // path position on it
  std::vector<double> position;
  // On a contouring curve (KRN-6), off the programmed motion: which, where
  // on it, and whether the path ran along it from its end to its start.
  std::shared_ptr<const ContourJoint> curve;
  double curve_s = 0;
  bool curve_reversed = false;
  // Where it stood in the block's programmed distance, counted from the
  // block's start in program order (DPS-1; on a curve, off the motion, the
  // position alone would not say it).
  double programmed_place = 0;
};

enum class PathProgress {
  moving,                 // on a block (possibly held short of its end)
  reached_contour_start,  // backward: left the first stored block this cycle
  at_contour_start,       // backward: stands where the stored contour begins
  all_blocks_run,         // forward: every decoded block has run
  setpoint_not_finite,    // a setpoint came out not finite: the path stopped on the last valid one
  invalid_block,          // forward: the blocks before invalid_block() have run; it cannot be moved
};

class PathInterpolator {
 public:
  PathInterpolator(const MachineConfig& machine, PathObserver& observer);
  PathInterpolator(const PathInterpolator&) = delete;  // the look-ahead refers to the machine
  PathInterpolator& operator=(const PathInterpolator&) = delete;

  // The program's blocks, read from `source` as the look-ahead needs them
  // (issue 17); `stored_blocks`: the motion blocks P-STUP-00033 keeps
  // behind the furthest one begun, for backward motion (KRN-5).
  void load(BlockSource& source, size_t stored_blocks) { program_.load(source, stored_blocks); }
  // All at once (tests), all kept.
  void load(std::vector<Block> blocks) { program_.load(std::move(blocks)); }
  const BlockWindow& blocks() const { return program_.blocks(); }
  // Nothing more is read from the program: it ends after the blocks read.
  void close_program() { program_.close(); }
  // What a short cut (delete distance to go, DDTG-6 .. DDTG-10) does to
  // where the interpolator is in the program; the cursors stay its own.
  // The commands of `block` and before have run (forward after backward
  // motion: they ran already).
  void mark_run_through(size_t block) { program_.mark_run_through(block); }
  // DDTG-8: nothing more of the program: neither motion nor commands.
  void abort_program() { program_.abort_program(); }
  // DDTG-6: no motion block more forward; the commands still run.
  void end_motion_here() { program_.end_motion_here(); }
  // Forward: the look-ahead goes on after `block` (a short cut's target).
  void look_ahead_after(size_t block) { program_.look_ahead_after(block); }
  // Backward: the blocks below `block` enter the look-ahead next.
  void look_back_below(size_t block) { program_.look_back_below(block); }
  // DDTG-6 backward: nothing more to run back to; the path stands in
  // `block`, forward again goes on from there.
  void stand_in_block(size_t block) { program_.stand_in_block(block); }
  // The first block still stored for backward motion (P-STUP-00033).
  size_t lowest_stored_block() const { return program_.cursors().lowest_stored; }
  // What does not hold of the cursors' meaning ("" if all does; the
  // channel fuzz asks every cycle).
  std::string check_invariants() const;
  TravelDirection direction() const { return program_.direction(); }
  double direction_sign() const { return program_.backward() ? -1.0 : 1.0; }

  // Where the path stands.
  bool empty() const { return look_ahead_.empty(); }
  const Block& front_block() const { return program_[look_ahead_.front().block_index]; }
  size_t front_index() const { return look_ahead_.front().block_index; }
  // Nothing left to move, or the plan ended (held short of a block end).
  bool standing(double t) const { return look_ahead_.empty() || since_plan_start(t) >= plan_.profile.duration(); }
  const std::vector<AxisSetpoint>& setpoints() const { return out_.axes; }
  std::vector<double> setpoint_positions() const;
  double path_velocity() const { return out_.velocity; }
  double path_acceleration() const { return out_.acceleration; }
  // The front block's part travelled so far, signed by the direction (DPS-1).
  double front_covered() const { return out_.front_covered; }

  // The hold's velocity factor (override, or 0); replans in the next interpolate().
  void set_velocity_factor(double factor);
  // Reports the travelled part of the front block and empties the
  // look-ahead: the path stands there.
  StopPoint leave_front(double t);
  // The path stands; axis `axis` stands at `position` instead of where the
  // path put it (a lift axis landed by the lift function before a short
  // cut, LIFT-2): the path goes on from there.
  void place_axis(size_t axis, double position) { out_.axes[axis] = {position, 0, 0}; }
  // A linear segment as block `target` into the empty look-ahead, not
  // smoothed (DDTG-2); false if it has no length.
  bool push_short_cut(size_t target, const Motion& cut);
  // Refills the look-ahead and plans from standstill at t.
  void go_on_from_standstill(double t);
  // KRN-5: the path stands; the travel direction changes, and the look-ahead
  // holds what is left of the front block the other way, then the stored
  // contour (backward: as many motion blocks below the furthest one run as
  // `stored_blocks`). False where it cannot turn: forward with nothing left.
  bool turn(double t, size_t stored_blocks);

  // A stop `distance` mm further along the path from where it is at t, at
  // v = 0 (insert stop marks): the path holds there until release_stop().
  // Where the path stands (ISC-3), `distance` is on the scale of
  // dist_prog_start (PathSegment::covered_distance) and the block in which
  // the stop lies is split there into two look-ahead segments, the second
  // one entered from standstill: the look-ahead brakes for it as for an M
  // function at a block end, jerk-limited, and the path stops on the mark.
  // Beyond the last block (the program end, or backward the start of the
  // stored contour) it stops at the end. While moving, `distance` is path
  // length, and a stop closer than the path can brake moves out to where
  // it can stop.
  // rebuild = false: the look-ahead is about to be emptied and filled anew
  // (a delete distance to go short cut): the stop is placed as it fills.
  void stop_after(double t, double distance, bool rebuild = true);
  void release_stop();
  // The path stands: its look-ahead is built again from where it stands
  // (drops the split of a stop cleared); go on with go_on_from_standstill.
  void restart(double t) {
    if (!look_ahead_.empty()) restart_here(t);
  }
  // The motions from where the path stands on, in the travel direction: the
  // rest of the front block, the look-ahead, the blocks after it (POSITION
  // mode searches them, ISC-4): the blocks read so far, reading on at most
  // path_ahead_blocks blocks after the look-ahead (issue 17: a program is
  // streamed; a mark further on is not found, as if past the program end).
  std::vector<Motion> path_ahead() const;
  static constexpr size_t path_ahead_blocks = 100000;
  // Issue 36 item 3: the look-ahead fills up to FCT_LOOK_AHEAD_STANDARD
  // blocks over several cycles, so many a cycle besides those replacing the
  // blocks the path finishes. Filled in one cycle, a program's first cycle
  // (and a restart's) decoded and planned all 120 blocks: 13 ms with G261
  // on 0.1 mm chords, the cycle 1 ms. The path starts at once on the blocks
  // it has; its plan ends at rest on the last of them.
  static constexpr size_t look_ahead_fill_per_cycle = 4;
  // The path stands at the stop asked for.
  bool at_stop(double t) const;
  // Where the stop lies once the look-ahead has reached it.
  const std::optional<PlacedStop>& placed_stop() const { return stop_.placed(); }

  // A motion block whose geometry is not finite (a radius of 1e308): the
  // path stops at the end of the block before it, as at a decode error.
  const std::optional<size_t>& invalid_block() const { return program_.invalid_block(); }

  // Moves the path to time t (s after program start): a cycle's time k T,
  // as every t of this interface.
  PathProgress interpolate(double t);

 private:
  // What enters the look-ahead: look_ahead_filling.cpp.
  void refill();
  // Block k, whose own segment is `segment`, the way the path travels.
  MotionPiece whole_block(size_t k, const PathSegment& segment) const;
  // The rest of block k from the stop the way the path now travels.
  MotionPiece rest_of_block(size_t k, const Motion& rest) const;
  // Every motion enters the look-ahead here: where a stop asked for lies in
  // it, split in two (stop_after).
  void push(MotionPiece piece, bool stop_before = false);
  void hand_over(MotionPiece piece, bool stop_before);
  // From a stop on a contouring curve, the rest of the curve towards its
  // end (`towards_end`) or its start, then the motion of the block there;
  // the block whose motion it is.
  size_t push_along_curve(const StopPoint& stop, bool towards_end);
  // A span of a curve for `block` (split at a stop mark as push() does).
  void push_curve_span(size_t block, const CurveSpan& span);
  void place_stop(std::vector<double> position);
  // Nothing more comes into the look-ahead this way: a stop not placed yet lands at its end.
  void place_stop_at_end();
  // The path stands: the look-ahead is built again from where it stands.
  void restart_here(double t);
  void refill_forward();
  void refill_backward();
  bool may_fill() const;
  void filled_one();
  // At the cycle's start: what the budget allows after the last cycle's.
  void top_up();
  // interpolate() but for the look-ahead's filling.
  PathProgress move_to(double t);
  // Makes the look-ahead's front block the one in the interpolator, after
  // reaching the blocks without motion before it, and plans from `state`
  // (path position within the block) at time t0.
  void begin_front(const MotionState& state, double t0);
  void plan(const MotionState& state, double t0);
  // Plans again where the path is at t: a stop was placed or released, or
  // the velocity factor changed.
  void replan(double t);
  void finish_front();
  void run_blocks_without_motion(size_t up_to);
  // Drops the blocks nothing needs any more: below the look-ahead, the
  // blocks still to run and the stored contour (issue 17).
  void forget_history();
  // Seconds since the plan started, at the cycle time t = k T. Counted in
  // cycles: k is exact, while k T - k0 T carries the rounding of both, a
  // jitter that grows with the run (KRN-3: 2e-6 of the jerk limit, 40,000.08
  // mm/s^3, 24 minutes into a run).
  double since_plan_start(double t) const {
    return (std::nearbyint(t / machine_.cycle_time_s()) - plan_.start_cycles) * machine_.cycle_time_s();
  }
  MotionState path_state_at(double t) const { return plan_.profile.at(since_plan_start(t)); }
  // False (setpoints unchanged) if a setpoint is not finite.
  bool output(const MotionState& path);

  const MachineConfig& machine_;
  PathObserver& observer_;
  ProgramPosition program_;
  LookAhead look_ahead_;
  struct Plan {
    MotionProfile profile;    // of the stretch from the front block on; p = 0 at its start
    double start_cycles = 0;  // after program start; a plan may start between two cycles
    Arrival arrival = Arrival::as_asked;  // how it arrives at its stretch's end
  };
  Plan plan_;
  bool replan_ = false;          // a stop was placed or released: plan again
  bool factor_changed_ = false;  // the velocity factor changed: plan again
  bool grown_ = false;           // blocks entered the look-ahead at the cycle's start (top_up): plan again
  // Motion blocks that may still enter the look-ahead this cycle besides
  // those replacing the blocks the path finishes (look_ahead_filling.cpp).
  size_t fill_budget_ = look_ahead_fill_per_cycle;
  // Path length travelled (either direction) before the front segment; the
  // same on the scale of covered distance (DPS-1), and where the look-ahead's
  // pushed segments end on it.
  double travelled_before_front_ = 0;
  double covered_before_front_ = 0;
  double pushed_covered_ = 0;
  PathStop stop_;
  RingQueue<MotionPiece> pushed_;  // from the front's on
  // The front's finished pieces' dist_prog_start share (KRN-6: a motion is
  // several pieces).
  double front_done_ = 0;
  // What the path puts out at the cycle: the axes, the path's velocity and
  // acceleration, what the front block has covered there.
  struct Output {
    std::vector<AxisSetpoint> axes;
    double velocity = 0;
    double acceleration = 0;
    double front_covered = 0;
  };
  Output out_;
};

}  // namespace hil::cnc
