#include "event_log_reader.hpp"

#include <algorithm>
#include <stdexcept>

namespace hil::logger {
namespace {

constexpr uint8_t sync_word[4] = {0xED, 0xA1, 0xDA, 0x01};  // LCM's event marker, big-endian
constexpr int64_t header_size = 4 + 8 + 8 + 4 + 4;          // sync, event number, timestamp, two lengths

uint64_t big_endian(const uint8_t* b, int bytes) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = v << 8 | b[i];
  return v;
}

}  // namespace

std::string LogDamage::describe() const {
  if (!any()) return "";
  return std::to_string(skipped_bytes) + " byte(s) in " + std::to_string(skipped_stretches) +
         " place(s) are no LCM event, the first at byte " + std::to_string(first_offset) + " (" + first + ")";
}

EventLogReader::EventLogReader(const std::string& path) : file_(std::fopen(path.c_str(), "rb")) {
  if (!file_ || std::fseek(file_, 0, SEEK_END) != 0 || (size_ = ftello(file_)) < 0) {
    if (file_) std::fclose(file_);
    throw std::runtime_error("cannot open LCM log " + path);
  }
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 16);
}

EventLogReader::~EventLogReader() { std::fclose(file_); }

bool EventLogReader::read_at(int64_t offset, void* out, size_t n) {
  return fseeko(file_, offset, SEEK_SET) == 0 && std::fread(out, 1, n, file_) == n;
}

int64_t EventLogReader::next_sync_word(int64_t from) {
  uint8_t buf[1 << 16];
  for (int64_t at = from; at < size_;) {
    const size_t n = static_cast<size_t>(std::min<int64_t>(sizeof buf, size_ - at));
    if (!read_at(at, buf, n)) return size_;
    const uint8_t* end = buf + n;
    const uint8_t* found = std::search(static_cast<const uint8_t*>(buf), end, sync_word, sync_word + 4);
    if (found != end) return at + (found - buf);
    if (n < 4) return size_;
    at += static_cast<int64_t>(n) - 3;  // a sync word across the chunk's end
  }
  return size_;
}

void EventLogReader::skip(int64_t from, int64_t to, const std::string& why) {
  if (damage_.first_offset < 0) {
    damage_.first_offset = from;
    damage_.first = why;
  }
  ++damage_.skipped_stretches;
  damage_.skipped_bytes += to - from;
  pos_ = to;
}

const LogRecord* EventLogReader::next() {
  while (pos_ < size_) {
    const int64_t left = size_ - pos_;
    uint8_t h[header_size];
    const bool whole_header = left >= header_size && read_at(pos_, h, header_size);
    if (!whole_header || !std::equal(h, h + 4, sync_word)) {
      // Not a record here: a cut record header, or bytes between records.
      const int64_t next = whole_header ? next_sync_word(pos_ + 1) : size_;
      skip(pos_, next, whole_header ? "no sync word where a record should begin" : "the file ends inside a record header");
      continue;
    }
    // Lengths as signed 32-bit numbers, as LCM writes them.
    const int64_t channel_length = static_cast<int32_t>(big_endian(h + 20, 4));
    const int64_t data_length = static_cast<int32_t>(big_endian(h + 24, 4));
    std::string why;
    if (channel_length < 1 || channel_length > max_channel_length)
      why = "a record claims a channel name of " + std::to_string(channel_length) + " bytes";
    else if (data_length < 0)
      why = "a record claims " + std::to_string(data_length) + " data bytes";
    else if (channel_length + data_length > left - header_size)
      why = "a record claims " + std::to_string(channel_length + data_length) + " bytes of channel and data, " +
            std::to_string(left - header_size) + " are left";
    if (!why.empty()) {
      skip(pos_, next_sync_word(pos_ + 1), why);
      continue;
    }
    record_.offset = pos_;
    record_.event_number = static_cast<int64_t>(big_endian(h + 4, 8));
    record_.timestamp = static_cast<int64_t>(big_endian(h + 12, 8));
    record_.channel.resize(static_cast<size_t>(channel_length));
    record_.data.resize(static_cast<size_t>(data_length));
    if (std::fread(record_.channel.data(), 1, record_.channel.size(), file_) != record_.channel.size() ||
        std::fread(record_.data.data(), 1, record_.data.size(), file_) != record_.data.size()) {
      skip(pos_, size_, "the file could not be read here");
      return nullptr;
    }
    pos_ += header_size + channel_length + data_length;
    ++records_;
    return &record_;
  }
  return nullptr;
}

}  // namespace hil::logger
