#pragma once
// The channel's errors and warnings (KRN-2) and the block they are about:
// the block in the interpolator gives every event its NC line and N number,
// and the HLI its block_nr_r and block_count_r (DDTG-4).
#include <vector>

#include "block.hpp"
#include "event.hpp"

namespace hil::cnc {

class ChannelEvents {
 public:
  // The interpolator reached this block (or ran its commands).
  void set_block(const Block& block) {
    nc_line_ = block.nc_line;
    block_nr_ = block.block_nr;
    block_count_ = block.block_count;
  }
  int64_t block_nr() const { return block_nr_; }
  int64_t block_count() const { return block_count_; }
  int64_t nc_line() const { return nc_line_; }

  // An event about the block in the interpolator.
  Event at_block(Severity severity, std::string message) const {
    Event e;
    e.severity = severity;
    e.nc_line = nc_line_;
    e.block_nr = block_nr_;
    e.message = std::move(message);
    return e;
  }
  void raise(Event event) {
    if (event.severity == Severity::error) last_error_id_ = event.id;
    events_.push_back(std::move(event));
  }
  int32_t last_error_id() const { return last_error_id_; }
  // Events raised since the last call.
  std::vector<Event> take() {
    std::vector<Event> out;
    out.swap(events_);
    return out;
  }

 private:
  int64_t nc_line_ = 0, block_nr_ = 0, block_count_ = 0;
  int32_t last_error_id_ = 0;
  std::vector<Event> events_;
};

}  // namespace hil::cnc
