#include "fuzz_golden_trace.hpp"

#include "cycle_messages.hpp"
#include "event_log_reader.hpp"

namespace hil::fuzz {

void FuzzGoldenRecorder::attach(FuzzOptions& options) {
  options.observer = [this](int64_t k, const cnc::Channel& channel, const HliControl&,
                            const std::vector<Event>& events) {
    logger::LogRecord record;
    for (cnc_node::EncodedMessage& m : cnc_node::cycle_messages(channel, channel.machine(), events, k, 0)) {
      record.channel = std::move(m.channel);
      record.data = std::move(m.bytes);
      trace_.add(record);
    }
  };
}

logger::GoldenTrace FuzzGoldenRecorder::take(const FuzzRun& run) {
  logger::GoldenTrace out = std::move(trace_);
  trace_ = {};
  out.finish();
  out.comment = "channel_fuzz --seed " + std::to_string(run.seed) + " --runs 1 --program-kind " + to_string(run.kind);
  return out;
}

std::string fuzz_golden_path(const std::string& dir, ProgramKind kind, uint64_t seed) {
  return dir + "/" + to_string(kind) + "/seed_" + std::to_string(seed) + ".trace.xz";
}

}  // namespace hil::fuzz
