#include "event_log_writer.hpp"

#include <stdio_ext.h>

#include <stdexcept>

namespace hil::logger {
namespace {

constexpr uint32_t sync_word = 0xEDA1DA01;  // LCM's event marker

void put_big_endian(std::vector<uint8_t>& out, uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

}  // namespace

EventLogWriter::EventLogWriter(const std::string& path) : file_(std::fopen(path.c_str(), "wb")) {
  if (!file_) throw std::runtime_error("cannot write log " + path);
  __fsetlocking(file_, FSETLOCKING_BYCALLER);  // one thread writes
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 20);
}

EventLogWriter::~EventLogWriter() { std::fclose(file_); }

void EventLogWriter::write(const std::string& channel, const void* data, uint32_t size, int64_t timestamp_us) {
  record_.clear();
  put_big_endian(record_, sync_word, 4);
  put_big_endian(record_, static_cast<uint64_t>(event_number_), 8);
  put_big_endian(record_, static_cast<uint64_t>(timestamp_us), 8);
  put_big_endian(record_, channel.size(), 4);
  put_big_endian(record_, size, 4);
  record_.insert(record_.end(), channel.begin(), channel.end());
  const auto* bytes = static_cast<const uint8_t*>(data);
  record_.insert(record_.end(), bytes, bytes + size);
  if (std::fwrite(record_.data(), 1, record_.size(), file_) != record_.size())
    throw std::runtime_error("writing the log failed");
  ++event_number_;
}

void EventLogWriter::flush() { std::fflush(file_); }

}  // namespace hil::logger
