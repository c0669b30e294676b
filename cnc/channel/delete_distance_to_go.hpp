#pragma once
// Delete distance to go (DDTG-1 .. DDTG-11, TF5200_delete_distance_to_go.txt).
// A rising edge of command_w while enable_w holds the path (DDTG-1);
// standing, the rest of the front block and the contour up to the target
// (short_cut_target: the next motion block's end, or the last one before a
// valid end marker, DDTG-5) are replaced by a linear short cut, G00 if the
// interrupted block was G00 (DDTG-2). command_w cleared before the short
// cut starts cancels it (DDTG-3). In backward motion the short cut goes to
// the start of the block before (DDTG-10). Needs P-STUP-00033 (DDTG-11).
// Reads: delete_distance_to_go.command_w/enable_w,
//        delete_distance_to_go_activation.command_w/enable_w (DDTG-5 mask).
// Writes: delete_distance_to_go.request_r/state_r, the activation's
//        request_r/state_r, delete_distance_to_go_active_r (DDTG-4).
#include <cstddef>
#include <cstdint>

#include "channel_events.hpp"
#include "hli.hpp"
#include "machine_config.hpp"
#include "path_interpolator.hpp"
#include "rising_edge.hpp"

namespace hil::cnc {

class DeleteDistanceToGo {
 public:
  explicit DeleteDistanceToGo(const MachineConfig& machine) : machine_(machine) {}
  // True if a short cut became pending or was cancelled.
  bool apply(const HliControl& control, bool channel_active, HliState& hli, ChannelEvents& events);
  // Stopping for the short cut.
  bool pending() const { return requested_; }
  // A short cut runs (DDTG-4).
  bool on_short_cut() const { return active_; }

  enum class Outcome {
    short_cut,  // the short cut (or nothing, if it has no length) is in the look-ahead: go on from standstill
    no_target,  // DDTG-6 (50810): motion ends where the path stands
    aborted,    // DDTG-8 (51016): the path stays, the program is aborted
  };
  // The path stands: leaves the front block and puts the short cut in its place.
  Outcome start_short_cut(PathInterpolator& path, double t, ChannelEvents& events);
  // The path finished a block: the short cut is done with its target (DDTG-4).
  void finish_block(size_t index) {
    if (active_ && index == target_) active_ = false;
  }
  void write(HliState& hli) const;
  // A reset: no short cut pending or running; the PLC's edge and mask stay.
  void abort() {
    requested_ = active_ = rapid_ = false;
    target_ = 0;
  }

 private:
  Outcome forward_short_cut(PathInterpolator& path, const StopPoint& stop, bool rapid, ChannelEvents& events);
  Outcome backward_short_cut(PathInterpolator& path, const StopPoint& stop, bool rapid, ChannelEvents& events);
  // A linear short cut from `stop` to `end`, a point of block `target`.
  void push(PathInterpolator& path, const StopPoint& stop, size_t target, const std::vector<double>& end, bool rapid);

  const MachineConfig& machine_;
  RisingEdge command_;
  bool requested_ = false;
  bool active_ = false;
  size_t target_ = 0;   // while a short cut runs: the block it goes to
  bool rapid_ = false;  // the running short cut is G00 (DDTG-2)
  bool activation_enabled_ = false;
  uint32_t activation_ = 0;  // end marker mask in force (DDTG-5), a UDINT
};

}  // namespace hil::cnc
