#pragma once
// The lift function's channel unit (TF5200_lift_function.txt, LIFT-1 ..
// LIFT-8): while the path runs a lift range, the lift axis' setpoint is
// the lift's, not the path's (the blocks of a range keep the lift axis
// where it stood). Lifting (path-based) couples it to the path parameter;
// Advanced Lifting moves it in time (advanced_lifting); a range without
// path motion, and a delete distance to go short cut in a range, position
// it while the path waits.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "advanced_lifting.hpp"
#include "block.hpp"
#include "lift_ranges.hpp"
#include "machine_config.hpp"
#include "motion_profile.hpp"
#include "path_interpolator.hpp"

namespace hil::cnc {

class Lift {
 public:
  explicit Lift(const MachineConfig& machine) : machine_(machine) {}

  // At program start: no range known yet.
  void begin_program();
  // A range the program's preparation found (LiftPreparation), before the
  // path reaches its blocks; ranges come in program order.
  void add_range(LiftRange range) { ranges_.push_back(std::move(range)); }
  // The path's covered distance as the interpolator reports it (DPS-1 scale, signed).
  void count(double covered) { covered_ += covered; }
  // The path reached block `index` for the first time.
  void reach_block(size_t index, int32_t override_value);
  // Every block has run (program end, or the blocks before a decode error).
  void all_blocks_run() { path_left_ = blocks_run_ = true; }
  // After the path moved to time `t`: the lift axis' setpoint into
  // `setpoints`. True if what the lift asks of the path changed
  // (override_cap, holds_path): the channel updates its hold. The lift
  // moves on once per cycle: a second call at the same `t` (a program's
  // first cycle interpolates at its start and in its run) repeats the
  // setpoint; moving on twice started a lift one cycle ahead, its first
  // output a cycle late (jerk 1.33 j_max, LIFT-2).
  bool update(const PathInterpolator& path, double t, int32_t override_value, std::vector<AxisSetpoint>& setpoints);
  // A delete distance to go short cut starts where the path stands: the
  // lift axis lands on POS first (the path waits), then stays there until
  // the range ends. The path's short cut starts from there: placed in `path`.
  void land_now(PathInterpolator& path);
  // The channel stops on an error: the lift axis brakes to rest as well.
  void stop_now();

  // A lift range runs or waits to (the program has not ended before it has).
  bool running() const { return active_ || !pending_.empty(); }
  // The path waits for the lift axis (a range without path motion, a
  // landing before a short cut, a landing no override would leave time for).
  bool holds_path() const;
  // The lift axis moves on a positioning of its own (after stop_now: braking to rest).
  bool positioning() const { return active_ && positioning_; }
  // LIFT-8: while Advanced Lifting rises, a higher override only as far as
  // the lift axis could still land in time; while it lowers, none higher
  // than at the start of lowering.
  int32_t override_cap(int32_t override_value) const;
  // Backward motion would run the path into a range against its geometry:
  // not in a program part at or after a range's start.
  bool forbids_backward(size_t front_block) const;
  // The lift axis had not reached POS when the path left the range (should
  // not happen: the caller reports it as an error); once.
  bool take_missed_landing() { return std::exchange(missed_landing_, false); }
  // Per axis: lift_active, lift_suppressed (LIFT-7).
  bool active(size_t axis) const;
  bool suppressed(size_t axis) const;

 private:
  const LiftRange& range() const { return ranges_[current_]; }
  void start(size_t range_index, int32_t override_value, double covered_at_start);
  void finish();
  void start_pending(int32_t override_value);
  void land_at_once();
  void apply_parked(std::vector<AxisSetpoint>& setpoints);
  void position_to(double target);
  // The difference first, constant within a block: summed with the
  // program's whole covered distance, the front's part lost its round-off
  // (5e-14 mm), which a lift rising fast over a crawling path multiplies by
  // dz/dq: Z's acceleration 1.2e-6 above a_max (fuzz AL, lift seeds
  // 43300505 and 43303849 on other machines).
  double since_start_covered(const PathInterpolator& path) const {
    return (covered_ - covered_at_start_) + path.front_covered();
  }

  const MachineConfig& machine_;
  std::vector<LiftRange> ranges_;
  double covered_ = 0;
  size_t last_reached_ = 0;  // the last block the path reached
  // The range the lift runs now.
  bool active_ = false;
  size_t current_ = 0;
  // Ranges reached while the current one had not ended yet (#FLUSH ends
  // one and begins the next; ranges without path motion one after the
  // other), in order, with where each began.
  struct Pending {
    size_t range = 0;
    double covered_at_start = 0;
    bool land = false;  // a short cut runs through it: it lands at once
  };
  std::deque<Pending> pending_;
  double covered_at_start_ = 0;
  bool path_left_ = false;
  // Every block has run: a range ended there leaves the lift axis on POS,
  // where no block of the path brings it (parked_).
  bool blocks_run_ = false;
  std::optional<AxisSetpoint> parked_;
  size_t parked_axis_ = 0;
  MotionState state_;
  std::optional<AdvancedLifting> advanced_;
  int32_t cap_ = 0;  // the highest override an Advanced lift accepts now (LIFT-8), 0.1 %
  std::optional<double> covered_last_cycle_;  // since the range's start, at the last Advanced Lifting step
  // Positioning (no path motion, or landing before a short cut): the profile, and how long it has run.
  bool positioning_ = false;
  bool landed_ = false;  // standing at hold_position_ until the range ends
  bool waits_for_landing_ = false;  // Advanced Lifting lands first, the path waits (LIFT-8)
  double hold_position_ = 0;
  MotionProfile positioning_profile_;
  double since_positioning_ = 0;
  bool missed_landing_ = false;
  std::optional<double> updated_at_;  // the time of the last update, s
  // The path reached the range within this cycle: the path's own motion
  // of the lift axis (the block before) comes to rest somewhere in it, so
  // the lift's own motion starts at its end (from the next output on).
  bool starts_next_cycle_ = false;
};

}  // namespace hil::cnc
