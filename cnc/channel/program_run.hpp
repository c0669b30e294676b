#pragma once
// What belongs to one program run (issue 35): made anew at a reset, so that
// nothing of an aborted run reaches the next one. The units that face the
// PLC's levels and edges (feed control, delete distance to go, backward
// motion, M function acknowledgements, M00/M01) outlast a run and are only
// aborted.
#include <cstddef>
#include <memory>
#include <optional>

#include "distance_from_program_start.hpp"
#include "drive_error_stop.hpp"
#include "insert_stop.hpp"
#include "lift.hpp"
#include "machine_config.hpp"
#include "path_interpolator.hpp"
#include "program_stream.hpp"

namespace hil::cnc {

struct ProgramRun {
  ProgramRun(const MachineConfig& machine, PathObserver& observer)
      : path(machine, observer), insert(machine), lift(machine) {}
  ProgramRun(const ProgramRun&) = delete;  // the units refer to the machine
  ProgramRun& operator=(const ProgramRun&) = delete;

  // The run's blocks; the interpolator reads them (declared first: it outlives the interpolator).
  std::unique_ptr<ProgramStream> program;
  PathInterpolator path;
  InsertStop insert;
  Lift lift;
  DistanceFromProgramStart distance;
  DriveErrorStop error_stop;
  // DPS-3: the collected M functions and the approach come first; the
  // block with this index is the continuation's.
  std::optional<size_t> continuation_block;
  bool continuation_reached = false;
  bool decode_failed = false;
  bool backward_refused = false;  // warned once that a lift range forbids backward motion
};

}  // namespace hil::cnc
