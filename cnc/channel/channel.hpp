#pragma once
// The CNC channel: HLI semantics, program start, feed hold and override,
// and interpolation of the decoded program at the cycle time along the
// path planned by the look-ahead (KRN-3). One call of step() is one cycle.
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "block.hpp"
#include "event.hpp"
#include "hli.hpp"
#include "look_ahead.hpp"
#include "machine_config.hpp"
#include "motion_profile.hpp"

namespace hil::cnc {

struct AxisSetpoint {
  double position = 0;      // mm
  double velocity = 0;      // mm/s
  double acceleration = 0;  // mm/s^2
};

class Channel {
 public:
  Channel(MachineConfig machine, std::string nc_program);
  Channel(const Channel&) = delete;  // the look-ahead refers to machine_
  Channel& operator=(const Channel&) = delete;

  // Interpolates cycle `cycle`, after applying the PLC's control written in
  // answer to the previous cycle (lock-step, RIG-6).
  void step(int64_t cycle, const HliControl& control);

  const std::vector<AxisSetpoint>& setpoints() const { return setpoints_; }
  const HliState& hli() const { return hli_; }
  // Events raised since the last call.
  std::vector<Event> take_events();
  // Program end or error reached: the channel commands no more motion.
  bool finished() const;

  // A drive reported a monitoring error (RIG-3): the channel stops along the
  // path as fast as the limits allow, jerk-limited, aborts the program and
  // shows the channel error on the HLI. Applied before the next step().
  void drive_error(const std::string& axis, const std::string& what);

 private:
  void apply_program_start(const ControlUnitBool& start);
  void apply_velocity_control(const HliControl& control);
  void apply_delete_distance_to_go(const HliControl& control);
  // Feed hold, a pending delete distance to go and an error stop the path;
  // otherwise the override sets its velocity.
  void update_velocity_factor();
  // DDTG-1: the path stands still; replace the rest of the front block and
  // the next motion block by a linear short cut to the latter's end point
  // (DDTG-5: everything up to the first valid end marker).
  void start_short_cut(double t);
  // Where the path stands in its front block, for a short cut or a turn.
  struct StopPoint {
    size_t block = 0;           // of the front segment
    double front_length = 0;    // of the front segment
    double s = 0;               // path position on it
    bool rapid = false;         // a short cut from here runs in G00 (DDTG-2)
    std::vector<double> position;
  };
  // Counts the front segment's travelled part into dist_prog_start (with
  // the direction's sign) and empties the look-ahead.
  StopPoint leave_front(double t);
  // A linear short cut from `stop` to `end`, the block `target`'s end
  // point (or start point, backward); then the look-ahead is refilled.
  void run_short_cut(const StopPoint& stop, size_t target, const std::vector<double>& end, double t);
  // Refills the look-ahead and plans from standstill at t.
  void go_on_from_standstill(double t);
  std::vector<double> setpoint_positions() const;
  // KRN-5 (backward_motion.cpp): the path stands still; go on along the
  // stored contour the other way. The short cut backward goes to the start
  // point of the block before the interrupted one (DDTG-10).
  void reverse_direction(double t);
  // Each cycle: a pending direction change turns the path once it stands,
  // or is refused with 50729 while a short cut runs.
  void change_direction(double t, bool standing);
  void refill_backward();
  void start_backward_short_cut(double t);
  // The PLC's backward_motion request differs from the direction moved in.
  bool direction_change_pending() const { return hli_.backward_motion.request_r != backward_; }
  // The path runs on a short cut; its direction cannot change (DDTG-10).
  bool on_short_cut() const { return hli_.delete_distance_to_go_active_r; }
  double direction_sign() const { return backward_ ? -1.0 : 1.0; }
  // M functions and dwells of a block, in order, before its motion.
  void queue_synchronous_actions(const Block& block);
  // Outputs the next M function, takes the PLC's acknowledgement, counts
  // down a dwell; the path moves again once none is left.
  void run_synchronous_actions(const HliControl& control, double t);
  void start_program();
  void refill_look_ahead();
  // Makes the look-ahead's front block the one in the interpolator, after
  // running the blocks without motion before it, and plans from `state`
  // (path position within the block) at time t0.
  void begin_front(const MotionState& state, double t0);
  void plan(const MotionState& state, double t0);
  void finish_front();
  void run_blocks_without_motion(size_t up_to);
  void interpolate(double t);
  MotionState path_state_at(double t) const;
  void output(const MotionState& path);
  // An event about the block in the interpolator (its NC line and N number).
  Event event_at_block(Severity severity, std::string message) const;
  void raise(Event event);

  MachineConfig machine_;
  std::string nc_program_;
  HliState hli_;
  std::vector<AxisSetpoint> setpoints_;
  std::vector<Block> blocks_;  // the decoded program
  bool decode_failed_ = false;
  LookAhead look_ahead_;
  size_t next_to_look_ahead_ = 0;  // next block of blocks_ to enter the look-ahead
  size_t next_to_run_ = 0;         // next block of blocks_ the interpolator reaches
  MotionProfile plan_;             // of the stretch from the front block on; p = 0 at its start
  double plan_start_ = 0;          // s after program start
  bool replan_ = false;            // override or feed hold changed
  bool error_stop_ = false;        // stopping on a drive error: still moving
  bool ddtg_requested_ = false;    // delete distance to go: stopping for the short cut (DDTG-1)
  bool previous_ddtg_command_ = false;
  // Backward motion on the path (KRN-5): the blocks stored for it are the
  // original contour of the motion blocks below blocks_begun_, as many as
  // P-STUP-00033 holds (a block takes sizeof(Block) bytes).
  bool backward_ = false;          // the path moves (or stands, set to move) backward
  size_t blocks_begun_ = 0;        // 1 + the furthest block run forward; their commands ran
  size_t next_backward_ = 0;       // going backward, blocks below this enter the look-ahead next
  size_t lowest_stored_ = 0;       // the first block still stored for backward motion
  size_t last_finished_block_ = 0; // the block the path left last (where it stands if the look-ahead is empty)
  bool reversal_refused_warned_ = false;  // 50729 raised for the pending direction change
  size_t short_cut_target_ = 0;    // while a short cut runs: the block whose end point it goes to
  bool short_cut_rapid_ = false;   // the short cut runs in G00 (DDTG-2)
  // What the path waits for, in order: an M function's acknowledgement
  // (m_function >= 0) or a dwell (dwell_s > 0), before it moves on.
  struct SynchronousAction {
    int m_function = -1;
    double dwell_s = 0;
  };
  std::deque<SynchronousAction> synchronous_;
  double dwell_end_ = -1;          // s after program start, while the front action is a dwell
  bool previous_m_ack_command_ = false;
  // The channel starts once: ON and CLEAR, the defaults at program start (DPS-2).
  bool dps_counting_ = true;       // #DISTANCE PROG START ON
  double dps_before_front_ = 0;    // mm counted before the front block
  int64_t current_nc_line_ = 0;    // NC line of the block in the interpolator, for events
  int64_t start_cycle_ = 0;
  int64_t cycle_ = 0;
  bool previous_start_command_ = false;
  int32_t previous_override_command_ = override_full;
  std::vector<Event> events_;
};

}  // namespace hil::cnc
