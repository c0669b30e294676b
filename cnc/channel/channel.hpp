#pragma once
// The CNC channel: HLI semantics, program start, and interpolation of the
// decoded program at the cycle time. One call of step() is one cycle.
#include <cstdint>
#include <string>
#include <vector>

#include "block.hpp"
#include "event.hpp"
#include "hli.hpp"
#include "motion_profile.hpp"
#include "machine_config.hpp"
#include "path_segment.hpp"

namespace hil::cnc {

struct AxisSetpoint {
  double position = 0;      // mm
  double velocity = 0;      // mm/s
  double acceleration = 0;  // mm/s^2
};

class Channel {
 public:
  Channel(MachineConfig machine, std::string nc_program);

  // Interpolates cycle `cycle`, after applying the PLC's control written in
  // answer to the previous cycle (lock-step, RIG-6).
  void step(int64_t cycle, const HliControl& control);

  const std::vector<AxisSetpoint>& setpoints() const { return setpoints_; }
  const HliState& hli() const { return hli_; }
  // Events raised since the last call.
  std::vector<Event> take_events();
  // Program end or error reached: the channel commands no more motion.
  bool finished() const;

 private:
  // A decoded block placed on the time line of the running program.
  struct PlannedBlock {
    Block block;
    std::vector<PathSegment> segment;  // empty for a block without motion
    MotionProfile profile;
    double t_begin = 0;          // s after program start
    double dist_before = 0;      // mm covered before this block
  };

  void apply_control(const HliControl& control);
  void start_program();
  void interpolate(double t);
  void raise(Event event);

  MachineConfig machine_;
  std::string nc_program_;
  HliState hli_;
  std::vector<AxisSetpoint> setpoints_;
  std::vector<PlannedBlock> planned_;
  bool decode_failed_ = false;
  int64_t start_cycle_ = 0;
  int64_t cycle_ = 0;
  size_t current_ = 0;
  bool previous_start_command_ = false;
  std::vector<Event> events_;
};

}  // namespace hil::cnc
