#pragma once
// An LCM message through LCM's own encoding and back, as the nodes see it.
// g++ 12 inlines lcm-gen's decode() here and sees a false
// -Wmaybe-uninitialized on its hash (set whenever decoding succeeded).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

namespace hil::test {

template <typename Message>
std::vector<uint8_t> encoded(const Message& m) {
  std::vector<uint8_t> bytes(m.getEncodedSize());
  REQUIRE(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())) == static_cast<int>(bytes.size()));
  return bytes;
}

template <typename Message>
Message through_the_wire(const Message& m) {
  std::vector<uint8_t> bytes = encoded(m);
  Message back;
  REQUIRE(back.decode(bytes.data(), 0, static_cast<int>(bytes.size())) == static_cast<int>(bytes.size()));
  return back;
}

}  // namespace hil::test
