#include "lift_ranges.hpp"

#include <algorithm>
#include <cmath>

#include "lift_limits.hpp"
#include "path_segment.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

// A range with less path than this has none: the lift axis positions alone.
constexpr double no_path_mm = tolerance::no_length_mm;

double overload_factor(const AxisConfig& axis) { return axis.dyn_monitoring_a_err / 1000.0; }

// The path in a Lifting range: no faster than the profile was planned for,
// and its acceleration and jerk within what the lift axis' overload range
// leaves (z''' v^3 + 3 z'' v a_path + z' j_path for the jerk).
Limits caps_for_lifting(const LiftRange& range, const AxisConfig& axis, double factor) {
  const Limits lift = lifting_limits(axis, factor);
  Limits caps = Limits::none();
  caps.v = range.v_plan;
  const double slope = range.profile.max_speed() / range.v_plan;  // largest |dz/dq|
  if (slope <= 0) return caps;
  const double a_left = factor * axis.a_max - lift.a;
  const double j_left = axis.j_max - lift.j;
  caps.a = std::min(a_left / slope, 0.5 * j_left * range.v_plan / (3 * lift.a));
  caps.j = 0.5 * j_left / slope;
  return caps;
}

void plan_lifting(LiftRange& range, const AxisConfig& axis, double factor, double v_programmed) {
  const Limits lim = lifting_limits(axis, factor);
  const double asked = range.length / v_programmed;
  // More internal blocks than it looks ahead: it cannot see the end, lifts
  // to the summit at once and lowers only when the end comes into view.
  const bool overflow = !range.suppressed && range.internal_blocks > lift_look_ahead_blocks;
  if (overflow) {
    const double to_summit = positioning_time(range.z0, range.peak, lim) + positioning_time(range.peak, range.command.pos, lim);
    range.profile = LiftProfile::plan(range.z0, range.command.pos, range.peak, std::max(asked, to_summit), lim);
  } else {
    range.profile = LiftProfile::plan(range.z0, range.command.pos, range.peak, asked, lim);
  }
  range.v_plan = range.length / range.profile.duration();
}

// The range's last motion block; past its end if it has none.
size_t last_motion(const std::vector<Block>& blocks, const LiftRange& range) {
  for (size_t k = range.end + 1; k-- > range.start;)
    if (blocks[k].has_motion) return k;
  return range.end + 1;
}

// TF5200 "Path smoothing and lifting": the lift axis is at rest at a
// range's start and end, so contouring (G61, G261) into or out of a range
// stays only where the lift axis does not move in the motion block before
// LIFT_START, or directly after LIFT_END (2nd case; Advanced Lifting only,
// below); otherwise that transition is standard (1st case). A neighbouring
// block in another range (#FLUSH: the lift axis reaches its target there)
// suppresses it as well, and so does, out of a range, a POS other than the
// height the range started at.
void suppress_contouring_at_ends(std::vector<Block>& blocks, const std::vector<LiftRange>& ranges,
                                 const Block* next_motion, const MachineConfig& machine) {
  auto in_a_range = [&](size_t k) {
    return std::any_of(ranges.begin(), ranges.end(), [k](const LiftRange& r) { return r.contains(k); });
  };
  // Anywhere along the motion, not only from its start to its end: an arc
  // moves the axes of its plane even where it ends where it began (a full
  // circle in G19 before LIFT_START moved Z on the curve into the range,
  // which the lift then took from the programmed height: 70,142 mm/s^2 in
  // a cycle, fuzz lift seed 19001122).
  auto moves = [&machine](const Block& block, size_t axis) {
    const Motion& m = block.motion;
    if (m.type == MotionType::arc_cw || m.type == MotionType::arc_ccw) {
      const std::array<int, 2> plane = arc_plane_axes(m, machine);
      if (static_cast<int>(axis) == plane[0] || static_cast<int>(axis) == plane[1]) return true;
    }
    return m.start[axis] != m.end[axis];
  };
  auto suppress = [](Block& block) {
    if (block.transition == BlockTransition::contour) block.transition = BlockTransition::standard;
    block.hsc.on = false;  // KRN-9: nor does an HSC spline pass there
  };
  // Lifting couples the lift axis to the covered distance (DPS-1), which a
  // curve counts at another rate per length than the line it joins: the
  // lift axis' velocity would step where the curve ends. Lifting keeps the
  // 1st case at both ends.
  const bool always = machine.lift_method == LiftMethod::path_based;
  for (const LiftRange& range : ranges) {
    const auto axis = static_cast<size_t>(range.command.axis);
    // A range without path motion: the path stops before it and waits
    // while the lift axis positions (a curve would run past it into the
    // block after, moving the lift axis there before the range ran).
    for (size_t k = range.start; k-- > 0;) {
      if (!blocks[k].has_motion) continue;
      if (always || range.positioning || in_a_range(k) || moves(blocks[k], axis)) suppress(blocks[k]);
      break;
    }
    const size_t last = last_motion(blocks, range);
    if (last > range.end) continue;
    const Block* after = next_motion;
    bool after_in_range = false;
    for (size_t k = range.end + 1; k < blocks.size(); ++k) {
      if (!blocks[k].has_motion) continue;
      after = &blocks[k];
      after_in_range = in_a_range(k);
      break;
    }
    // The range's blocks keep the lift axis at its start height; where POS
    // lies elsewhere the path steps there at the range's end and only the
    // lift bridges it: a curve across the step would move the lift axis.
    const bool step = blocks[last].motion.end[axis] != range.command.pos;
    if (always || !after || after_in_range || moves(*after, axis) || step) suppress(blocks[last]);
  }
}

}  // namespace

std::vector<LiftRange> prepare_lift_ranges(std::vector<Block>& blocks, const MachineConfig& machine,
                                           const std::vector<double>& start_position, const Block* next_motion) {
  std::vector<LiftRange> ranges;
  if (machine.lift_method == LiftMethod::none) return ranges;
  // Where the ranges lie, and where the lift axis stands at each start.
  AxisValues position = start_position;
  // Not std::optional: g++ 12 then warns of a vector in it read uninitialised.
  LiftRange open;
  bool is_open = false;
  auto close = [&](size_t k) {
    open.end = k;
    open.end_has_motion = blocks[k].has_motion;
    position[static_cast<size_t>(open.command.axis)] = open.command.pos;  // where the next part starts
    ranges.push_back(open);
    is_open = false;
  };
  for (size_t k = 0; k < blocks.size(); ++k) {
    const Block& block = blocks[k];
    if (block.lift_start) {
      const bool flush = is_open;  // #FLUSH: LIFT_END and LIFT_START here (LIFT-5)
      if (flush) close(k);
      open = LiftRange{};
      is_open = true;
      open.start = k;
      open.command = *block.lift_start;
      open.z0 = position[static_cast<size_t>(block.lift_start->axis)];
      if (block.lift_end && !flush) {  // the single-block Z[LIFT ..]
        if (block.has_motion) position = block.motion.end;
        close(k);
        continue;
      }
    } else if (block.lift_end && is_open) {
      if (block.has_motion) position = block.motion.end;
      close(k);
      continue;
    }
    if (block.has_motion) position = block.motion.end;
  }
  if (is_open) close(blocks.size() - 1);  // program end without LIFT_END (LIFT-5)

  const double override_max = machine.override_max_percent / 100.0;
  for (LiftRange& range : ranges) {
    const AxisConfig& axis = machine.axes[static_cast<size_t>(range.command.axis)];
    const size_t n = range.end - range.start + 1;
    std::vector<double> programmed(n, 0.0);
    double v_programmed = 0;
    for (size_t k = range.start; k <= range.end; ++k) {
      const Block& block = blocks[k];
      if (block.has_motion || !block.m_functions.empty()) ++range.internal_blocks;
      if (!block.has_motion) continue;
      const PathSegment segment(block.motion, machine);
      range.length += segment.covered_distance();
      programmed[k - range.start] = segment.programmed_velocity();
      v_programmed = std::max(v_programmed, segment.programmed_velocity());
    }
    range.suppressed = machine.lift_min_dist_mm > 0 && range.length < machine.lift_min_dist_mm;
    const double z0 = range.z0, pos = range.command.pos, limit = range.command.pos_limit;
    if (range.command.down) range.peak = range.suppressed ? std::min(z0, pos) : std::min({limit, z0, pos});
    else range.peak = range.suppressed ? std::max(z0, pos) : std::max({limit, z0, pos});

    Limits caps = Limits::none();
    if (range.length < no_path_mm || !(v_programmed > 0)) {
      range.positioning = true;
      blocks[range.start].lift_positioning = pos != z0;
    } else if (machine.lift_method == LiftMethod::time_based) {
      // The path may not reach the end before the lift axis could land even
      // by the direct move, at the highest override (LIFT-2); the lift
      // starts at the end of the cycle the path reaches the range in, and
      // lands on a cycle: two cycles more.
      const double direct = positioning_time(z0, pos, advanced_lifting_limits(axis, machine.cycle_time_s()));
      if (direct > 0) caps.v = range.length / ((direct + 2 * machine.cycle_time_s()) * override_max);
    } else {
      const double factor = range.suppressed ? 1.0 : overload_factor(axis);
      plan_lifting(range, axis, factor, v_programmed);
      caps = caps_for_lifting(range, axis, factor);
    }
    range.v_ahead.assign(n, 0.0);
    double ahead = 0;
    for (size_t i = n; i-- > 0;) {
      ahead = std::max(ahead, std::min(programmed[i], caps.v));
      range.v_ahead[i] = ahead;
    }
    // Lifting: no contouring inside the range either, whose caps hold for
    // the blocks' own segments.
    for (size_t k = range.start; k <= range.end; ++k) {
      Block& block = blocks[k];
      if (!block.has_motion) continue;
      if (machine.lift_method == LiftMethod::path_based && block.transition == BlockTransition::contour)
        block.transition = BlockTransition::standard;
      block.hsc.on = false;  // KRN-9: a spline would not keep the range's caps per block
      block.motion.path_caps = capped(block.motion.path_caps, caps);
      block.motion.in_lift_range = true;
    }
  }
  suppress_contouring_at_ends(blocks, ranges, next_motion, machine);
  return ranges;
}

}  // namespace hil::cnc
