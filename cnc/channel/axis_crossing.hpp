#pragma once
// Where an axis first reaches a position along a path (ISC-4, POSITION
// mode): the covered distance (DPS-1 scale) from the path's start to the
// first point of `motions` at which axis `axis` stands on `position`, or
// with `modulo` (an absolute position on a modulo axis, KRN-7) on any
// position a whole number of modulo ranges away: at most one revolution.
#include <cstddef>
#include <optional>
#include <vector>

#include "block.hpp"
#include "machine_config.hpp"

namespace hil::cnc {

std::optional<double> covered_until_axis_reaches(const std::vector<Motion>& motions, size_t axis, double position,
                                                 const MachineConfig& machine, bool modulo = false);

}  // namespace hil::cnc
