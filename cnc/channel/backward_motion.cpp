// KRN-5: backward motion on the path, and delete distance to go on it
// (DDTG-10). The stored contour is the original one: the programmed motion
// blocks run so far, never a short cut (a short cut's skipped blocks count
// as stored). Commands (M functions, dwell, #DISTANCE PROG START) run once:
// not backward, and not again when the path goes forward over blocks it
// ran before.
#include <algorithm>

#include "channel.hpp"
#include "motion_parts.hpp"

namespace hil::cnc {
namespace {

// A rest shorter than this is not moved (10 nm): a shorter arc could not be
// told from a full circle.
constexpr double shortest_rest_mm = 1e-5;

// How many motion blocks P-STUP-00033 holds.
size_t stored_blocks(const MachineConfig& machine) {
  return static_cast<size_t>(machine.fb_storage_size) / sizeof(Block);
}

}  // namespace

void Channel::change_direction(double t, bool standing) {
  if (!direction_change_pending()) {
    reversal_refused_warned_ = false;
    return;
  }
  if (!on_short_cut()) {
    if (standing && !ddtg_requested_ && machine_.fb_storage_size > 0) reverse_direction(t);
    return;
  }
  // DDTG-10: not on a short cut; it stands until the request is taken back.
  if (reversal_refused_warned_) return;
  Event held = event_at_block(Severity::warning, backward_ ? "forward motion is not possible on a backward delete "
                                                             "distance to go short cut; held until backward motion "
                                                             "is requested again"
                                                           : "backward motion is not possible on a delete distance "
                                                             "to go short cut; held until withdrawn");
  held.id = 50729;
  raise(held);
  reversal_refused_warned_ = true;
}

void Channel::reverse_direction(double t) {
  if (look_ahead_.empty()) {
    // Standing where the stored contour begins: forward from that block's
    // start. (Forward with nothing left to move, the program is about to
    // end: it cannot turn there.)
    if (backward_) {
      backward_ = false;
      update_velocity_factor();
      next_to_look_ahead_ = last_finished_block_;
      go_on_from_standstill(t);
    }
    return;
  }
  const StopPoint stop = leave_front(t);
  const size_t k = stop.block;
  backward_ = !backward_;
  update_velocity_factor();
  // What is left of block k the new way: back to its start, or on to its end.
  const Motion motion = backward_ ? reversed(motion_until(blocks_[k].motion, stop.position))
                                  : motion_from(blocks_[k].motion, stop.position);
  if (backward_) {
    // The stored contour: as many motion blocks below the furthest one run as P-STUP-00033 holds.
    size_t i = blocks_begun_, counted = 0;
    while (i > 0 && counted < stored_blocks(machine_))
      if (blocks_[--i].has_motion) ++counted;
    lowest_stored_ = i;
    next_backward_ = k;
  } else {
    next_to_look_ahead_ = k + 1;
  }
  // The front segment ends where block k ends in the old direction, so the
  // way back over block k is what it had covered before the front and on it.
  const double back_over_k = PathSegment(blocks_[k].motion, machine_).length() - stop.front_length + stop.s;
  if (back_over_k > shortest_rest_mm) look_ahead_.push(k, PathSegment(motion, machine_), blocks_[k].slope);
  last_finished_block_ = k;  // where the path stands if nothing follows: at block k's start
  refill_look_ahead();
  if (look_ahead_.empty() && backward_)
    raise(event_at_block(Severity::warning, "backward motion: the stored contour begins here; it stands"));
  go_on_from_standstill(t);
}

void Channel::refill_backward() {
  while (!look_ahead_.full() && next_backward_ > lowest_stored_) {
    const size_t i = --next_backward_;
    if (!blocks_[i].has_motion) continue;
    look_ahead_.push(i, PathSegment(reversed(blocks_[i].motion), machine_), blocks_[i].slope);
  }
}

// DDTG-10: in backward direction the next block is the one before; the
// short cut goes to its start point, and backward motion goes on from there.
void Channel::start_backward_short_cut(double t) {
  ddtg_requested_ = false;
  const StopPoint stop = leave_front(t);
  size_t target = stop.block;
  while (target > lowest_stored_ && !blocks_[--target].has_motion) {
  }
  if (target == stop.block || !blocks_[target].has_motion) {  // DDTG-6: nothing stored before it
    Event none = event_at_block(Severity::warning,
                                "delete distance to go in backward motion: no stored motion block before this one; "
                                "motion ends at the stop position");
    none.id = 50810;
    raise(none);
    next_backward_ = lowest_stored_;
    return;
  }
  next_backward_ = target;
  run_short_cut(stop, target, blocks_[target].motion.start, t);
}

}  // namespace hil::cnc
