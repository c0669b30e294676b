#pragma once
// The CNC channel: a short state machine over the interpolator and one unit
// per TF5200 function (KRN-3, KRN-4). One call of step() is one cycle: the
// PLC's control applies, the path moves, the HLI state is written.
//
//   feed_control           feed hold, override
//   delete_distance_to_go  DDTG-1 .. DDTG-11 (short_cut_target)
//   backward_motion        KRN-5
//   synchronous_actions    M functions with acknowledgement, #TIME dwell
//   distance_from_program_start  DPS-1, DPS-2
//   drive_error_stop       RIG-3
//   insert_stop            ISC-1 .. ISC-9 (axis_crossing: POSITION mode)
//   programmed_stop        M00 / M01, continue motion, m01_stop_enable (ISC-5)
//   lift                   LIFT-1 .. LIFT-8: the lift axis' setpoint in a lift range
//   path_hold              why the path holds: velocity factor, stop_conditions_r
//                          (channel_holds.cpp: each unit's reason; what holds program end)
//   path_interpolator      look-ahead, plan, block cursors, travel direction
//   program_run            the units of one program run, made anew at a reset
//   block search (cnc/search)  DPS-3: a program start at a block number and distance
//   reset                  abort the program where the path stands: READY again
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backward_motion.hpp"
#include "block.hpp"
#include "channel_events.hpp"
#include "delete_distance_to_go.hpp"
#include "distance_from_program_start.hpp"
#include "drive_error_stop.hpp"
#include "event.hpp"
#include "feed_control.hpp"
#include "hli.hpp"
#include "insert_stop.hpp"
#include "lift.hpp"
#include "machine_config.hpp"
#include "path_hold.hpp"
#include "path_interpolator.hpp"
#include "block_search.hpp"
#include "program_run.hpp"
#include "program_stream.hpp"
#include "programmed_stop.hpp"
#include "rising_edge.hpp"
#include "synchronous_actions.hpp"

namespace hil::cnc {

class Channel : private PathObserver {
 public:
  // The program text is read anew at each program start, line by line as
  // the path needs its blocks (issue 17): a file (program_file) is never
  // held whole; a string (the rig's scenarios) is held by the caller's copy.
  Channel(MachineConfig machine, std::string nc_program);
  Channel(MachineConfig machine, ProgramText nc_program);
  Channel(const Channel&) = delete;  // the units refer to machine_
  Channel& operator=(const Channel&) = delete;

  // Interpolates cycle `cycle`, after applying the PLC's control written in
  // answer to the previous cycle (lock-step, RIG-6).
  void step(int64_t cycle, const HliControl& control);

  // The path's, with a lift axis' own in a lift range.
  const std::vector<AxisSetpoint>& setpoints() const { return setpoints_; }
  const HliState& hli() const { return hli_; }
  const MachineConfig& machine() const { return machine_; }
  // Events raised since the last call.
  std::vector<Event> take_events() { return events_.take(); }
  // The blocks it holds now (issue 17: bounded, whatever the program's length).
  size_t blocks_held() const { return run_->path.blocks().held() + (run_->program ? run_->program->blocks_held() : 0); }
  // What does not hold of the interpolator's state ("" if all does): the
  // channel fuzz asks every cycle.
  std::string check_invariants() const { return run_ ? run_->path.check_invariants() : ""; }
  // Program end or error reached: the channel commands no more motion.
  bool finished() const;

  // A drive reported a monitoring error (RIG-3); applied before the next step().
  void drive_error(const std::string& axis, const std::string& what);
  // The rig lost a participant that is no drive (the PLC or the logger fell
  // silent, RIG-6): the same error stop, for that reason.
  void error_stop(const std::string& reason);

 private:
  // The phases of a cycle.
  void apply_control(const HliControl& control);
  double time_s() const { return static_cast<double>(cycle_ - start_cycle_) * machine_.cycle_time_s(); }
  void apply_program_start(const HliControl& control);
  // The reset control unit: aborts the program where the path stands.
  void apply_reset(const ControlUnitBool& reset);
  // KRN-8: a G54..G59 table entry written by the PLC.
  void apply_zero_offset(const ControlUnitZeroOffset& write);
  // A new program run's units, at where the axes stand.
  void begin_program_run();
  void run_path(const HliControl& control, double t);
  // The path stands (`standing`: at the cycle's interpolation): the units
  // that act there, in their order of priority.
  void on_standstill(double t, bool standing);
  void interpolate(double t);
  void start_short_cut(double t);
  void change_direction(double t, bool standing);
  // Insert stop marks (ISC-3 .. ISC-7): a command set where the path
  // stands, the mark's M function where it is reached, leaving it.
  void set_insert_command(double t);
  void reach_insert_mark(double t);
  void leave_insert_mark(double t);
  double distance_mm() const;
  void write_state();
  void enter(ChannelState state);
  bool holds_program_end() const;

  void start_program(const ControlUnitBlockSearch& search);
  // DPS-3: the program goes on from the continuation point; false if the
  // search failed (the program does not start).
  bool search_continuation(const ControlUnitBlockSearch& search);
  // A decode error or pre-output warning the program stream has met.
  void take_stream_events();
  // Why the path holds now; its velocity factor goes to the interpolator.
  PathHold hold() const;
  void update_hold();
  bool moving() const { return hli_.channel_state == ChannelState::active || run_->error_stop.stopping(); }

  // PathObserver
  void reach_block(const Block& block, size_t index, bool run_commands) override;
  void travelled(double covered_distance) override {
    run_->distance.count(covered_distance);
    run_->lift.count(covered_distance);
  }
  void finish_block(size_t index) override { ddtg_.finish_block(index); }

  MachineConfig machine_;
  ProgramText nc_program_;
  // G54..G59's tables, mm per axis: the machine file's as the PLC changed
  // them (they outlast a program, as a real CNC's zero offset data).
  std::vector<std::vector<double>> zero_offsets_;
  ZeroOffsetCommand last_zero_offset_write_;
  HliState hli_;
  ChannelEvents events_;
  // Made anew at a reset (it refers to machine_).
  std::optional<ProgramRun> run_;
  FeedControl feed_;
  DeleteDistanceToGo ddtg_;
  BackwardMotion backward_;
  SynchronousActions actions_;
  ProgrammedStop programmed_stop_;
  std::vector<AxisSetpoint> setpoints_;
  RisingEdge program_start_;
  RisingEdge reset_;
  int64_t start_cycle_ = 0;
  int64_t cycle_ = 0;
};

}  // namespace hil::cnc
