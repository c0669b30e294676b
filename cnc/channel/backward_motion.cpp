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
      refill_look_ahead();
      if (!look_ahead_.empty()) begin_front({}, t);
      replan_ = false;
    }
    return;
  }
  const LookAheadBlock& front = look_ahead_.front();
  const size_t k = front.block_index;
  const double length = front.segment.length();
  const double s = std::clamp(path_state_at(t).p, 0.0, length);
  if (dps_counting_ && length > 0) dps_before_front_ += direction_sign() * front.segment.covered_distance() * s / length;
  backward_ = !backward_;
  update_velocity_factor();
  std::vector<double> here(setpoints_.size());
  for (size_t i = 0; i < here.size(); ++i) here[i] = setpoints_[i].position;
  // What is left of block k the new way: back to its start, or on to its end.
  const Motion motion = backward_ ? reversed(motion_until(blocks_[k].motion, here)) : motion_from(blocks_[k].motion, here);
  look_ahead_.clear();
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
  const double back_over_k = PathSegment(blocks_[k].motion, machine_).length() - length + s;
  if (back_over_k > shortest_rest_mm) look_ahead_.push(k, PathSegment(motion, machine_), blocks_[k].slope);
  last_finished_block_ = k;  // where the path stands if nothing follows: at block k's start
  refill_look_ahead();
  if (look_ahead_.empty()) {
    if (backward_) raise(event_at_block(Severity::warning, "backward motion: the stored contour begins here; it stands"));
    return;
  }
  begin_front({}, t);
  replan_ = false;
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
  const LookAheadBlock& front = look_ahead_.front();
  const size_t k = front.block_index;
  const double length = front.segment.length();
  const double s = std::clamp(path_state_at(t).p, 0.0, length);
  if (dps_counting_ && length > 0) dps_before_front_ -= front.segment.covered_distance() * s / length;
  const bool rapid = on_short_cut() ? short_cut_rapid_ : blocks_[k].motion.type == MotionType::rapid;
  const double interrupted_feed = blocks_[k].motion.feed;
  std::vector<double> stop(setpoints_.size());
  for (size_t i = 0; i < stop.size(); ++i) stop[i] = setpoints_[i].position;
  look_ahead_.clear();
  hli_.delete_distance_to_go_active_r = false;
  update_velocity_factor();
  size_t target = k;
  while (target > lowest_stored_ && !blocks_[--target].has_motion) {
  }
  if (target == k || !blocks_[target].has_motion) {  // DDTG-6: nothing stored before it
    Event none = event_at_block(Severity::warning,
                                "delete distance to go in backward motion: no stored motion block before this one; "
                                "motion ends at the stop position");
    none.id = 50810;
    raise(none);
    next_backward_ = lowest_stored_;
    return;
  }
  Motion cut;
  cut.type = rapid ? MotionType::rapid : MotionType::linear;
  cut.start = stop;
  cut.end = blocks_[target].motion.start;
  cut.feed = blocks_[target].motion.feed > 0 ? blocks_[target].motion.feed : interrupted_feed;
  PathSegment segment(cut, machine_);
  next_backward_ = target;
  if (segment.length() > 0) {
    look_ahead_.push(target, std::move(segment), blocks_[target].slope);
    short_cut_target_ = target;
    short_cut_rapid_ = rapid;
    hli_.delete_distance_to_go_active_r = true;
  }
  refill_look_ahead();
  if (look_ahead_.empty()) return;
  begin_front({}, t);
  replan_ = false;
}

}  // namespace hil::cnc
