#include "delete_distance_to_go.hpp"

#include <algorithm>
#include <string>

#include "short_cut_target.hpp"

namespace hil::cnc {

bool DeleteDistanceToGo::apply(const HliControl& control, bool channel_active, HliState& hli, ChannelEvents& events) {
  const ControlUnitBool& unit = control.delete_distance_to_go;
  const bool commanded = unit.command_w && unit.enable_w;
  hli.delete_distance_to_go.request_r = commanded;
  const bool rising = command_(unit.command_w);
  bool changed = false;
  if (requested_ && !commanded) {  // DDTG-3
    requested_ = false;
    changed = true;
  } else if (rising && commanded && channel_active && !requested_) {
    if (machine_.fb_storage_size > 0) {
      requested_ = true;
      changed = true;
    } else {  // DDTG-11
      Event refused = events.at_block(Severity::warning,
                                      "delete distance to go ignored: it needs P-STUP-00033 fb_storage_size > 0");
      refused.parameter = "P-STUP-00033";
      events.raise(refused);
    }
  }
  // The end marker mask, in force from the next short cut on.
  const ControlUnitUns32& activation = control.delete_distance_to_go_activation;
  activation_enabled_ = activation.enable_w;
  activation_ = activation.enable_w ? activation.command_w : 0;
  return changed;
}

void DeleteDistanceToGo::write(HliState& hli) const {
  hli.delete_distance_to_go.state_r = requested_ || active_;
  hli.delete_distance_to_go_active_r = active_;
  hli.delete_distance_to_go_activation.request_r = activation_enabled_;
  hli.delete_distance_to_go_activation.state_r = activation_;
}

DeleteDistanceToGo::Outcome DeleteDistanceToGo::start_short_cut(PathInterpolator& path, double t,
                                                               ChannelEvents& events) {
  requested_ = false;
  if (path.empty()) {  // DDTG-6: standing with nothing ahead (after 50810, at the start of the stored contour)
    Event none = events.at_block(Severity::warning, "delete distance to go: no motion block left to short-cut to; "
                                                    "the path stays where it stands");
    none.id = 50810;
    events.raise(none);
    return Outcome::no_target;
  }
  const bool rapid = active_ ? rapid_ : path.front_block().motion.type == MotionType::rapid;
  active_ = false;
  const StopPoint stop = path.leave_front(t);
  return path.direction() == TravelDirection::backward ? backward_short_cut(path, stop, rapid, events)
                                                       : forward_short_cut(path, stop, rapid, events);
}

DeleteDistanceToGo::Outcome DeleteDistanceToGo::forward_short_cut(PathInterpolator& path, const StopPoint& stop,
                                                                  bool rapid, ChannelEvents& events) {
  // What lies between the stop and the target (non-motion blocks) runs at
  // the stop position, before the short cut (DDTG-7).
  const BlockWindow& blocks = path.blocks();
  const uint32_t mask = activation_;
  const ShortCutTarget found = short_cut_target(blocks, stop.block, mask);
  path.mark_run_through(stop.block);
  const std::string here = "delete distance to go in line " + std::to_string(events.nc_line());
  if (found.not_skippable) {  // DDTG-8: the path stays where it stopped
    const Block& command = blocks[*found.not_skippable];
    Event refused = events.at_block(Severity::error, here + " must not skip the command in line " +
                                                         std::to_string(command.nc_line) + "; program aborted");
    refused.id = 51016;
    refused.nc_line = command.nc_line;
    refused.block_nr = command.block_nr;
    events.raise(refused);
    path.abort_program();
    return Outcome::aborted;
  }
  if (found.channel_initialisation) {  // DDTG-8: the short cut ends before it
    const Block& command = blocks[*found.channel_initialisation];
    Event ended = events.at_block(Severity::warning, here + ": the command in line " + std::to_string(command.nc_line) +
                                                         " needs channel initialisation; the short cut ends before it");
    ended.id = 51036;
    ended.nc_line = command.nc_line;
    ended.block_nr = command.block_nr;
    events.raise(ended);
  }
  if (!found.target) {  // DDTG-6: no motion block left to short-cut to
    // The program is streamed: the search reads ahead so far at most (issue 17).
    const std::string limit =
        " within the next " + std::to_string(short_cut_search_blocks) + " blocks (how far the search reads ahead)";
    Event none = events.at_block(
        Severity::warning, mask == 0 ? "delete distance to go: no further motion block" +
                                           (found.search_limit ? limit : std::string()) +
                                           "; motion ends at the stop position"
                                     : "delete distance to go: no #DEL DIST2GO end marker valid for activation " +
                                           std::to_string(mask) + (found.search_limit ? limit : " before program end") +
                                           "; motion ends at the stop position");
    none.id = 50810;
    events.raise(none);
    path.end_motion_here();
    return Outcome::no_target;
  }
  path.look_ahead_after(*found.target);
  push(path, stop, *found.target, blocks[*found.target].motion.end, rapid);
  return Outcome::short_cut;
}

// DDTG-10: in backward direction the next block is the one before; the
// short cut goes to its start point, and backward motion goes on from there.
DeleteDistanceToGo::Outcome DeleteDistanceToGo::backward_short_cut(PathInterpolator& path, const StopPoint& stop,
                                                                   bool rapid, ChannelEvents& events) {
  const BlockWindow& blocks = path.blocks();
  size_t target = stop.block;
  while (target > path.lowest_stored_block() && !blocks[--target].has_motion) {
  }
  if (target == stop.block || !blocks[target].has_motion) {  // DDTG-6: nothing stored before it
    Event none = events.at_block(Severity::warning,
                                 "delete distance to go in backward motion: no stored motion block before this one; "
                                 "motion ends at the stop position");
    none.id = 50810;
    events.raise(none);
    path.stand_in_block(stop.block);
    return Outcome::no_target;
  }
  path.look_back_below(target);
  push(path, stop, target, blocks[target].motion.start, rapid);
  return Outcome::short_cut;
}

void DeleteDistanceToGo::push(PathInterpolator& path, const StopPoint& stop, size_t target,
                              const std::vector<double>& end, bool rapid) {
  const BlockWindow& blocks = path.blocks();
  Motion cut;
  // DDTG-2: linear, at the target block's feed (the F in force there, for a
  // G00 block too), G00 if the interrupted block was; with no F programmed
  // at all (G00 blocks only) at rapid.
  cut.feed = blocks[target].motion.feed > 0 ? blocks[target].motion.feed : blocks[stop.block].motion.feed;
  cut.type = rapid || !(cut.feed > 0) ? MotionType::rapid : MotionType::linear;
  cut.start = stop.position;
  cut.end = end;
  if (!path.push_short_cut(target, cut)) return;
  target_ = target;
  rapid_ = rapid;
  active_ = true;
}

}  // namespace hil::cnc
