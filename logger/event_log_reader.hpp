#pragma once
// Reads an LCM event log (the format event_log_writer.hpp writes, and LCM's
// lcm_eventlog) without trusting its length fields (RIG-4, RIG-9). LCM
// 1.3.1's reader allocates what a record's header claims (datalen + 1 as a
// signed int: 2^31 - 1 overflows, calloc fails, fread writes through NULL)
// and ends the log silently at the first damaged record. This one allocates
// no more than the file holds, skips to the next sync word past bytes that
// are no record (as LCM's reader does before a record), and says where the
// file is damaged, so that a reader can fail a damaged log instead of
// judging the part it happened to read.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace hil::logger {

struct LogRecord {
  int64_t offset = 0;  // of its sync word in the file
  int64_t event_number = 0;
  int64_t timestamp = 0;  // µs, as written
  std::string channel;
  std::vector<uint8_t> data;
};

// Where a file is not a sequence of whole records.
struct LogDamage {
  int64_t skipped_bytes = 0;     // bytes that are no record, skipped to the next sync word
  int64_t skipped_stretches = 0;
  int64_t first_offset = -1;     // where the first such stretch begins
  std::string first;             // what is wrong there, for people

  bool any() const { return skipped_stretches > 0; }
  // "" if none, else e.g. "40 byte(s) in 1 place(s) are no LCM event, the
  // first at byte 1234 (a record claims 2147483647 data bytes, 12 are left)".
  std::string describe() const;
};

class EventLogReader {
 public:
  // Throws std::runtime_error ("cannot open LCM log PATH") if it cannot be read.
  explicit EventLogReader(const std::string& path);
  ~EventLogReader();
  EventLogReader(const EventLogReader&) = delete;
  EventLogReader& operator=(const EventLogReader&) = delete;

  // The next whole record, nullptr at the end of the file. The record is
  // overwritten by the next call.
  const LogRecord* next();

  const LogDamage& damage() const { return damage_; }
  int64_t file_size() const { return size_; }
  int64_t records() const { return records_; }

  // LCM's own limit on a record's channel name (lcm_eventlog refuses longer).
  static constexpr int32_t max_channel_length = 999;

 private:
  bool read_at(int64_t offset, void* out, size_t n);
  // The offset of the next sync word after `from`, or the file's size.
  int64_t next_sync_word(int64_t from);
  void skip(int64_t from, int64_t to, const std::string& why);

  std::FILE* file_ = nullptr;
  int64_t size_ = 0;
  int64_t pos_ = 0;  // where the next record should begin
  int64_t records_ = 0;
  LogRecord record_;
  LogDamage damage_;
};

}  // namespace hil::logger
