#include "insert_stop.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <string>

#include "axis_crossing.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

constexpr double mm_per_hli = 1.0 / hli_units_per_mm;
// A mark beyond every block lands at the end of the program (ISC-6).
constexpr double beyond_the_program = std::numeric_limits<double>::max() / 4;

}  // namespace

bool InsertStop::take(const InsertCmdUnit& unit, HliState& hli) {
  hli.insert_cmd.semaphor_rw = unit.semaphor_rw && !unit.enable_w;  // not read while disabled
  if (!unit.semaphor_rw || !unit.enable_w) return false;
  const InsertCmdCommand& c = unit.command_w;
  InsertCommand command;
  command.dist_or_pos = std::isfinite(c.dist_or_pos) ? c.dist_or_pos : 0.0;
  command.rel_abs_mode = c.rel_abs_mode;
  command.axis_nr = c.axis_nr;
  command.m_function_nr = c.m_function_nr;
  command.add_nr = c.add_nr;
  if (disabled_) return false;  // #INSERT CMD OFF: read, not used
  pending_ = command;
  return true;
}

void InsertStop::program_command(const InsertCmdLine& line) {
  if (line.off) {
    disabled_ = true;
    pending_ = InsertCommand{};  // DIST=0 REL: clears the mark
    return;
  }
  disabled_ = false;
  if (line.command) pending_ = line.command;
}

void InsertStop::place(PathInterpolator& path, double t, Mark mark, double along, bool rebuild) {
  path.stop_after(t, std::max(along, 0.0), rebuild);
  mark_ = mark;
}

bool InsertStop::set_pending(PathInterpolator& path, double t, double distance_mm, ChannelEvents& events) {
  const InsertCommand c = *pending_;
  pending_.reset();
  const double d = c.dist_or_pos * mm_per_hli, sign = path.direction_sign();
  const bool clears = c.rel_abs_mode == 0 && c.dist_or_pos == 0;
  if (clears || c.rel_abs_mode > 2) {
    if (c.rel_abs_mode > 2) {
      Event e = events.at_block(Severity::warning, "insert stop: rel_abs_mode " + std::to_string(c.rel_abs_mode) +
                                                       " is not 0, 1 or 2; the command is ignored");
      events.raise(e);
      return false;
    }
    // ISC-3: a mark not yet reached is cleared; at a mark, no next one follows.
    if (mark_ && !mark_->reached) {
      mark_.reset();
      path.release_stop();
    } else if (mark_) {
      mark_->iterative = false;
    }
    path.restart(t);
    return true;
  }
  Mark mark;
  mark.command = c;
  mark.base_mm = distance_mm;
  mark.sign = sign;
  if (c.axis_nr > 0) {
    if (static_cast<size_t>(c.axis_nr) > machine_.axes.size()) {
      events.raise(events.at_block(Severity::warning, "insert stop: axis_nr " + std::to_string(c.axis_nr) +
                                                          " names no axis of the channel; the command is ignored"));
      return false;
    }
    const size_t axis = static_cast<size_t>(c.axis_nr - 1);
    const double now = path.setpoints()[axis].position;
    mark.iterative = c.rel_abs_mode == 0;
    // KRN-7: absolute on a modulo axis is shifted into its range (the next
    // time it gets there: at most a revolution); relative counts the
    // axis' travel (several revolutions if asked).
    mark.axis_target = c.rel_abs_mode == 1 ? machine_.axes[axis].in_modulo_range(d) : now + d;
    set_position_mark(path, t, mark, events);
    return true;
  }
  // DISTANCE mode, the text's table (ISC-3).
  double target = distance_mm;
  switch (c.rel_abs_mode) {
    case 0:
      mark.iterative = d > 0;
      target = d > 0 ? distance_mm + sign * d : distance_mm;
      break;
    case 1: target = sign * (d - distance_mm) > 0 ? d : distance_mm; break;
    default: target = d > 0 ? distance_mm + sign * d : distance_mm; break;
  }
  mark.target_mm = target;
  place(path, t, mark, std::abs(target - distance_mm));
  return true;
}

void InsertStop::set_position_mark(PathInterpolator& path, double t, Mark mark, ChannelEvents& events) {
  const size_t axis = static_cast<size_t>(mark.command.axis_nr - 1);
  const bool any_revolution = machine_.axes[axis].modulo && mark.command.rel_abs_mode == 1;
  const std::optional<double> along =
      covered_until_axis_reaches(path.path_ahead(), axis, mark.axis_target, machine_, any_revolution);
  if (!along)
    events.raise(events.at_block(Severity::info, "insert stop: the axis does not reach the position in this "
                                                 "program; the stop lies at its end"));
  place(path, t, mark, along.value_or(beyond_the_program));
}

bool InsertStop::reached(const PathInterpolator& path, double t) const {
  return mark_ && !at_mark_ && path.placed_stop() && path.at_stop(t);
}

bool InsertStop::leave(PathInterpolator& path, double t, double distance_mm) {
  at_mark_ = false;
  if (!mark_ || !mark_->reached) return false;  // a new mark was set meanwhile: it stays
  if (!mark_->iterative) {
    mark_.reset();
    path.release_stop();
    return false;
  }
  // The next relative stop, from this one (ISC-3, ISC-4).
  Mark next = *mark_;
  next.reached = false;
  const double d = next.command.dist_or_pos * mm_per_hli;
  next.base_mm = distance_mm;
  if (next.command.axis_nr > 0) {
    next.axis_target = path.setpoints()[static_cast<size_t>(next.command.axis_nr - 1)].position + d;
    ChannelEvents quiet;
    set_position_mark(path, t, next, quiet);
  } else {
    next.target_mm = distance_mm + next.sign * d;
    place(path, t, next, d);
  }
  // At the end of the program (or of the stored contour) no next one follows.
  if (path.placed_stop() && path.placed_stop()->covered <= tolerance::length_mm) {
    mark_.reset();
    path.release_stop();
  }
  return true;
}

void InsertStop::before_turn(PathInterpolator& path, double t, double distance_mm) {
  pending_.reset();
  if (!mark_ || !mark_->iterative || mark_->command.axis_nr > 0 || at_mark_) {
    if (!at_mark_) mark_.reset();  // ISC-9: cleared on a reversal
    path.release_stop();
    return;
  }
  // A relative iterative DISTANCE mark: set again, the new way, from here.
  Mark next = *mark_;
  const double d = next.command.dist_or_pos * mm_per_hli;
  next.sign = -path.direction_sign();
  next.base_mm = distance_mm;
  next.target_mm = distance_mm + next.sign * d;
  place(path, t, next, d, false);
}

void InsertStop::before_short_cut(PathInterpolator& path, double t, double distance_mm) {
  if (!mark_ || at_mark_) return;
  if (mark_->command.axis_nr > 0) {
    // Searched again on the new path, once it stands: as an absolute mark.
    InsertCommand again = mark_->command;
    again.rel_abs_mode = 1;
    again.dist_or_pos = mark_->axis_target * hli_units_per_mm;
    path.release_stop();
    mark_.reset();
    pending_ = again;
    return;
  }
  place(path, t, *mark_, mark_->sign * (mark_->target_mm - distance_mm), false);
}

void InsertStop::program_end() {
  pending_.reset();
  mark_.reset();
  at_mark_ = false;
}

void InsertStop::write(HliState& hli, const PathInterpolator& path) const {
  InsertCmdState& s = hli.insert_cmd.state_r;
  const bool commanded = pending_ && !(pending_->rel_abs_mode == 0 && pending_->dist_or_pos == 0);
  s.state = (mark_ && !mark_->reached) || commanded ? 1 : 0;
  s.distance_of_next_stop = -1;
  s.position_at_next_stop = {0, 0, 0};
  const auto& placed = path.placed_stop();
  if (!mark_ || !placed || commanded) return;  // ISC-2: -1 while the stop is not found in the program
  const bool landed_at_end =
      mark_->command.axis_nr == 0 && placed->covered < std::abs(mark_->target_mm - mark_->base_mm) - tolerance::no_length_mm;
  const double distance = mark_->command.axis_nr == 0 && !landed_at_end
                              ? mark_->target_mm
                              : mark_->base_mm + mark_->sign * placed->covered;
  s.distance_of_next_stop = std::round(distance * hli_units_per_mm * 1e3) / 1e3;
  auto hli_position = [](double mm) {
    return static_cast<int32_t>(std::clamp<long long>(std::llround(mm * hli_units_per_mm), INT32_MIN, INT32_MAX));
  };
  if (mark_->command.axis_nr > 0) {
    const size_t axis = static_cast<size_t>(mark_->command.axis_nr - 1);
    s.position_at_next_stop[0] = hli_position(machine_.axes[axis].in_modulo_range(placed->position[axis]));
  } else {
    for (size_t i = 0; i < 3 && i < placed->position.size(); ++i) s.position_at_next_stop[i] = hli_position(placed->position[i]);
  }
}

}  // namespace hil::cnc
