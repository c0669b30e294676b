#pragma once
// Golden traces of channel fuzz runs (issue 35, docs/GOLDEN.md): each
// cycle's outputs encoded as the CNC node publishes them
// (cnc_node::cycle_messages: setpoints, HLI state, events), so that a fuzz
// seed's trace has the channels and columns of a rig log's.
#include <cstdint>
#include <string>

#include "channel_fuzz.hpp"
#include "golden_trace.hpp"

namespace hil::fuzz {

class FuzzGoldenRecorder {
 public:
  // Sets `options.observer` to record into this recorder's current trace.
  void attach(FuzzOptions& options);
  // The run's trace, finished; the next run records into a new one.
  logger::GoldenTrace take(const FuzzRun& run);

 private:
  logger::GoldenTrace trace_;
};

// <dir>/<kind>/seed_<seed>.trace.xz
std::string fuzz_golden_path(const std::string& dir, ProgramKind kind, uint64_t seed);

}  // namespace hil::fuzz
