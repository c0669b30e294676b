#pragma once
// Writes an LCM event log (the format of LCM's lcm_eventlog, which reads
// it: lcm-logplayer, lcm-spy, lcm::LogFile). LCM 1.3.1's own writer makes
// nine fwrite calls per event, a fifth of an in-process run's time (issue
// 17); this one makes one, through a large buffer.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace hil::logger {

class EventLogWriter {
 public:
  // Throws if `path` cannot be written.
  explicit EventLogWriter(const std::string& path);
  ~EventLogWriter();
  EventLogWriter(const EventLogWriter&) = delete;
  EventLogWriter& operator=(const EventLogWriter&) = delete;

  // Throws if the file cannot take it.
  void write(const std::string& channel, const void* data, uint32_t size, int64_t timestamp_us);
  void flush();

 private:
  std::FILE* file_;
  int64_t event_number_ = 0;
  std::vector<uint8_t> record_;
};

}  // namespace hil::logger
