#pragma once
// Decoding bytes nobody vouches for (a log file, a datagram) as an lcm-gen
// type without a throw or a crash (RIG-4, RIG-9). lcm-gen 1.3.1's decoders
// trust the lengths inside a message: a negative array or string length
// throws std::length_error from resize / assign, and a string length of
// -2^31 wraps to 2^31 - 1 in `len - 1`, so the decoder copies 2 GB from
// beyond the buffer and dies of SIGSEGV. No length check of theirs catches
// it (a negative length is never "more than is left").
#include <cstdint>
#include <cstring>
#include <exception>
#include <vector>

namespace hil::lcm_support {

namespace detail {

template <typename Message>
bool decodes(const uint8_t* data, int size, Message& message) {
  try {
    return message.decode(data, 0, size) == size;
  } catch (const std::exception&) {  // a negative length: resize / assign refused it
    return false;
  }
}

// Whether the decoder would read a string length at `at` where the bytes
// are 80 00 00 00 (-2^31, the one length it does not survive). The same
// decoder reads a copy cut right after those four bytes, which hold
// -2^31 + 1 there instead: every field before them decodes as in the
// message, and if the decoder reads a string length there it throws
// (assign of -2^31 bytes) instead of copying 2 GB; any other field there, or
// a field beyond, finds the copy's end and returns -1. The int16 lengths
// those bytes could also hold (00 00, 00 01) stay what they were, or >= 0.
template <typename Message>
bool string_length_at(const uint8_t* data, size_t at) {
  std::vector<uint8_t> probe(data, data + at + 4);
  probe[at + 3] = 0x01;
  Message m{};
  try {
    m.decode(probe.data(), 0, static_cast<int>(probe.size()));
    return false;
  } catch (const std::exception&) {
    return true;
  }
}

}  // namespace detail

// How many 80 00 00 00 stretches a message may hold before it is refused
// unread: each costs one probe decode (a real one holds a few: -0.0 doubles).
constexpr int max_length_probes = 64;

// True if `size` bytes are exactly one Message; false for anything else,
// never a throw, never a read beyond `size`.
template <typename Message>
bool decode_untrusted(const void* bytes, size_t size, Message& message) {
  if (size > static_cast<size_t>(INT32_MAX)) return false;
  const auto* data = static_cast<const uint8_t*>(bytes);
  int probes = 0;
  for (size_t at = 0; at + 4 <= size; ++at) {
    if (data[at] != 0x80 || data[at + 1] != 0 || data[at + 2] != 0 || data[at + 3] != 0) continue;
    if (++probes > max_length_probes || detail::string_length_at<Message>(data, at)) return false;
  }
  return detail::decodes(data, static_cast<int>(size), message);
}

}  // namespace hil::lcm_support
