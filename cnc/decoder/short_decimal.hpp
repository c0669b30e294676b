#pragma once
// The number of a word read in one pass (issue 17: decode speed): where
// its digits and '.' end and, for most NC numbers (X12.345: few digits),
// its value. The double nearest to such a decimal is one exact division,
// digits / 10^k (Clinger's fast path: both are exact doubles and IEEE
// division rounds correctly): the same double std::from_chars gives, in a
// fraction of its time. The other numbers go to std::from_chars.
#include <cstdint>
#include <optional>

namespace hil::cnc::decoding {

struct DecimalDigits {
  const char* end;              // after the last digit or '.' from the start
  bool has_digit;               // a '.' alone is no number
  std::optional<double> value;  // none: more than 15 digits, "5.", ".5", "1.2.3" (from_chars decides)
};

// The digits and '.' from `begin` (no sign) up to `end` or the first other character.
inline DecimalDigits read_decimal_digits(const char* begin, const char* end) {
  // 10^k, k <= 15: every one an exact double.
  static constexpr double powers_of_ten[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                             1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  uint64_t digits = 0;  // wraps beyond 19 digits: then no value anyway
  int count = 0, points = 0, after_point = 0;
  const char* p = begin;
  for (; p != end; ++p) {
    const unsigned digit = static_cast<unsigned>(static_cast<unsigned char>(*p)) - '0';
    if (digit < 10) {
      digits = digits * 10 + digit;
      ++count;
      after_point += points;
    } else if (*p == '.') {
      ++points;
    } else {
      break;
    }
  }
  DecimalDigits read{p, count > 0, std::nullopt};
  // At most 15 digits: below 2^53, so the digits are an exact double.
  if (count > 0 && count <= 15 && points <= 1 && *begin != '.' && p[-1] != '.')
    read.value = static_cast<double>(digits) / powers_of_ten[after_point];
  return read;
}

}  // namespace hil::cnc::decoding
