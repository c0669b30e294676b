#pragma once
// Insert stop marks while the program runs (TF5200_insert_stop_cmd.txt,
// ISC-1 .. ISC-9). The PLC writes a mark into the insert command unit and
// raises semaphor_rw; the CNC reads it (and clears the semaphore), stops
// the path briefly if it moves (ISC-6), and asks the interpolator for a
// stop at the mark (PathInterpolator::stop_after: the block is split
// there). At the mark the channel runs the mark's M function: M00 / M01
// (ProgrammedStop, left by continue motion) or M<n> with add_nr,
// acknowledged by the PLC (SynchronousActions).
//
//   DISTANCE mode (axis_nr 0): the mark is a dist_prog_start (DPS-1).
//   POSITION mode (axis_nr > 0): the mark is where that axis first reaches
//   the position from where the path stands (axis_crossing.hpp).
//
// Reads: insert_cmd (command_w, enable_w, semaphor_rw).
// Writes: insert_cmd.semaphor_rw, insert_cmd.state_r.
#include <cstdint>
#include <optional>

#include "block.hpp"
#include "channel_events.hpp"
#include "hli.hpp"
#include "machine_config.hpp"
#include "path_interpolator.hpp"

namespace hil::cnc {

class InsertStop {
 public:
  explicit InsertStop(const MachineConfig& machine) : machine_(machine) {}

  // ISC-1: command_w is read when semaphor_rw is TRUE while enable_w, and
  // the semaphore cleared; new data without the semaphore is not read.
  // True if a command was taken.
  bool take(const InsertCmdUnit& unit, HliState& hli);
  // #INSERT CMD in the program (ISC-8), reached with the path standing.
  void program_command(const InsertCmdLine& line);
  // A command waits for the path to stand (ISC-6: it holds the path).
  bool pending() const { return pending_.has_value(); }
  // The path stands at t (or the program starts): the command waiting sets,
  // replaces or clears the mark. distance_mm: dist_prog_start now. The
  // look-ahead was built again: go on with go_on_from_standstill().
  // False if the command was ignored (the path is as it was).
  bool set_pending(PathInterpolator& path, double t, double distance_mm, ChannelEvents& events);

  // The path stands on the mark and its M function is not yet running.
  bool reached(const PathInterpolator& path, double t) const;
  const InsertCommand& command() const { return mark_->command; }
  // The mark's M function runs (ISC-7: HLI_SC_INSERT_STOP_AT_DIST).
  void begin_stop() {
    at_mark_ = true;
    mark_->reached = true;
  }
  bool at_mark() const { return at_mark_; }
  // The M function is done: a relative iterative mark is set again from
  // here (true: go on with go_on_from_standstill()), any other is cleared.
  bool leave(PathInterpolator& path, double t, double distance_mm);
  // ISC-9, KRN-5: before the path turns. DISTANCE: absolute and one-off
  // marks are cleared, a relative iterative one is set again the new way;
  // POSITION: the mark is cleared.
  void before_turn(PathInterpolator& path, double t, double distance_mm);
  // Before a delete distance to go short cut (the path stands): a DISTANCE
  // mark keeps its dist_prog_start, placed on the new path as it is built;
  // a POSITION mark is searched again, as an absolute one, once the path
  // stands again after the short cut began (a brief stop).
  void before_short_cut(PathInterpolator& path, double t, double distance_mm);
  // The program ended: no mark crosses into another program (ISC-6).
  void program_end();

  void write(HliState& hli, const PathInterpolator& path) const;
  int32_t stop_conditions() const { return at_mark_ ? stop_condition::insert_stop_at_dist : 0; }

 private:
  struct Mark {
    InsertCommand command;
    bool iterative = false;
    double base_mm = 0;      // dist_prog_start where it was set
    double target_mm = 0;    // DISTANCE: dist_prog_start of the mark
    double axis_target = 0;  // POSITION: the axis position, mm
    double sign = 1;         // the travel direction it was set in
    bool reached = false;    // its M function ran
  };
  // Sets the mark at distance `along` (covered, mm) from where the path stands.
  void place(PathInterpolator& path, double t, Mark mark, double along, bool rebuild = true);
  void set_position_mark(PathInterpolator& path, double t, Mark mark, ChannelEvents& events);

  const MachineConfig& machine_;
  std::optional<InsertCommand> pending_;
  std::optional<Mark> mark_;
  bool at_mark_ = false;
  bool disabled_ = false;   // #INSERT CMD OFF
};

}  // namespace hil::cnc
