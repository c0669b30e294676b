#include "retimed_log.hpp"

#include <hil/run_manifest_t.hpp>

#include <algorithm>
#include <optional>

#include "csv_export.hpp"
#include "event_log_reader.hpp"
#include "event_log_writer.hpp"
#include "untrusted_decode.hpp"

namespace hil::logger {
namespace {

constexpr int64_t max_cycle_span = 1'000'000'000'000;  // 31 years of 1 ms cycles

std::optional<int64_t> cycle_us_of(const std::string& path) {
  EventLogReader file(path);
  while (const LogRecord* e = file.next()) {
    const std::optional<MessageColumns> m = message_columns(*e);
    if (!m || m->type != "run_manifest_t") continue;
    hil::run_manifest_t manifest{};
    if (lcm_support::decode_untrusted(e->data.data(), e->data.size(), manifest) && manifest.cycle_us > 0)
      return manifest.cycle_us;
  }
  return std::nullopt;
}

}  // namespace

RetimedLog retime_to_simulated(const std::string& in, const std::string& out) {
  RetimedLog result;
  const std::optional<int64_t> cycle_us = cycle_us_of(in);
  result.retimed = cycle_us.has_value();
  EventLogReader file(in);
  EventLogWriter writer(out);
  std::optional<int64_t> first_recorded, first_cycle;
  int64_t last_recorded = 0, stamp = 0, last_cycle = 0;
  while (const LogRecord* e = file.next()) {
    ++result.messages;
    if (!first_recorded) first_recorded = stamp = e->timestamp;
    last_recorded = e->timestamp;
    if (cycle_us) {
      const std::optional<MessageColumns> m = message_columns(*e);
      // A crafted cycle far beyond any run's must not overflow the stamp.
      if (m && m->simulated_time && m->cycle >= 0 && (!first_cycle || m->cycle - *first_cycle <= max_cycle_span)) {
        if (!first_cycle) first_cycle = m->cycle;
        last_cycle = std::max(last_cycle, m->cycle);
        stamp = std::max(stamp, *first_recorded + (m->cycle - *first_cycle) * *cycle_us);
      }
    } else {
      stamp = e->timestamp;
    }
    writer.write(e->channel, e->data.data(), static_cast<uint32_t>(e->data.size()), stamp);
  }
  writer.flush();
  if (first_recorded) result.recorded_s = static_cast<double>(last_recorded - *first_recorded) * 1e-6;
  if (first_cycle && cycle_us) result.simulated_s = static_cast<double>((last_cycle - *first_cycle) * *cycle_us) * 1e-6;
  return result;
}

}  // namespace hil::logger
