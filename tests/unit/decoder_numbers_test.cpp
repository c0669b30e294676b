// KRN-1 / KRN-2 fuzzing: bad input never crashes the decoder, never
// escapes as an exception, and never yields a block with a number outside
// the ranges of value_ranges.hpp; every error names its line.
// HIL_DECODER_FUZZ_INPUTS=<n> runs n inputs of each kind (default 100,000),
// HIL_DECODER_FUZZ_SEED=<s> other ones.
#include <catch2/catch.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <random>
#include <sstream>

#include "decoder.hpp"
#include "short_decimal.hpp"
#include "test_machine.hpp"
#include "value_ranges.hpp"

using namespace hil;
using namespace hil::cnc;
using namespace hil::cnc::decoding;

namespace {

// Valid programs to mutate: every construct the decoder knows.
const char* const seeds[] = {
    "%prog\nN10 G00 X10 Y20 Z5 ; rapid\nN20 G01 X20 F600 (feed 10 mm/s)\nN30 G91 Y-5\nN40 G90 Z0\nN50 M30\n",
    "G01 X10 F1000\nG03 X20 Y10 I0 J10\nG02 X10 Y20 I-10 J0\nG03 I-5\n",
    "N10 #DISTANCE PROG START OFF\nN20 G01 X0 Y0 F1000\nN30 G92 X33 Y55 M7\nN40 X0 Y0\n#distance prog start  on\n"
    "N50 #SLOPE [TYPE=SIN2]\nN60 G91 X100\nN70 #DISTANCE PROG START CLEAR\n",
    "N040 X130 F1000\nN041 #DEL DIST2GO\nN051 #DEL DIST2GO [END='16#01']\nN071 #DEL DIST2GO [END='16#0105']\n"
    "N081 #del dist2go [ END = 8 ]\nN101 #DEL DIST2GO [END='2#1010']\n",
    "N005 X0 Y0 Z0 F1000\nN010 X100\nN015 M48\nN016 P1=1\nN017 #TIME 10\nN020 Y100 M7 M8\n"
    "N025 P2 = [P1 + 2] * -1.5 / 3 (comment)\nN026 #TIME -P2\nN030 X90 Y110\nN040 M30\n",
    "N010 G01 X0 Y0 F1000\nN020 $FOR P1 = 1, 3, 1\nN030 G91 X10\nN040 $FOR P2 = 2, 1, 1\nN050 Y99\nN060 $ENDFOR\n"
    "N070 $ENDFOR\nN080 G90 X0 Y5\nN090 M30\n",
    "N10 G01 X100 Y60 F1000\nN20 G02 X150 Y10 J-50\nN30 G161 G03 X100 Y60 I100 J10\n"
    "N40 G162 G165 G02 X150 Y10 I1 J-50\n",
    "N10 G01 X10 Y0 F1000\nN20 #CS ON [100,50,5,0,0,90]\nN30 X10 Y0 Z0\nN40 G91 Y10\nN50 G90 G03 X0 Y20 I-10 J0\n"
    "N60 #CS OFF\nN70 G01 X0 Y0 Z0\nN80 #CS ON [,,-2]\nN90 Z0\nN95 #CS OFF\nN100 #channel init [ cmdpos ]\n",
    "N10 G1 X10 F1000 M7 M8\nN20 V.G.M_FCT[8].PRE_OUTP_PATH = 4\nN30 X20 M8\n",
};

// Numbers and pieces that have broken decoders.
const std::string nasty_numbers[] = {
    "1e308", "-0", "nan", "inf", "-inf", "99999999999", "4294967296", "4294967295", "2147483648", "1000000",
    "1000001", "-1000000.5", "1e-308", "0", "0.0000001", "1e999", "-", ".", "1.2.3", "0x10", "16#FF", "2#",
    "1" + std::string(308, '0')};  // 1e308 without an exponent
const char* const odd_pieces[] = {"[", "]", "#", "$", "=", "(", ")", ";", ",", "'", "*", "/", "-", "+", " ", "\t",
                                  "\r", "\n", "%", "P1", "P99999", "P100000", "$FOR P1 = 1, 3", "$ENDFOR", "#CS ON [",
                                  "#CS OFF", "#TIME", "G92", "G91", "G90", "G02", "G161", "G165", "M30", "N", "X",
                                  "I", "J", "F", "e", "[[[[", "]]]]", "P1 = 1e300 * 1e300"};

class Mutator {
 public:
  explicit Mutator(uint32_t seed) : random_(seed) {}

  size_t below(size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(random_); }

  std::string random_bytes() {
    std::string text(below(120), '\0');
    for (char& c : text) c = static_cast<char>(below(256));
    return text;
  }
  std::string random_nc_text() {
    static const std::string alphabet = "NGXYZIJFMP0123456789.-+*/[]#$=();, \n\n\n%eE'";
    std::string text(below(200), ' ');
    for (char& c : text) c = alphabet[below(alphabet.size())];
    return text;
  }
  std::string mutated(std::string text) {
    for (size_t k = 1 + below(4); k > 0; --k) mutate(text);
    return text;
  }

 private:
  template <typename T, size_t N>
  const T& any(const T (&table)[N]) { return table[below(N)]; }

  void mutate(std::string& text) {
    const size_t at = below(text.size() + 1);
    switch (below(6)) {
      case 0: {  // a number there becomes a nasty one
        auto in_number = [&](size_t k) { return std::isdigit(static_cast<unsigned char>(text[k])) || text[k] == '.'; };
        size_t begin = at, end = at;
        while (begin > 0 && in_number(begin - 1)) --begin;
        while (end < text.size() && in_number(end)) ++end;
        text.replace(begin, end - begin, any(nasty_numbers));
        break;
      }
      case 1: text.insert(at, any(odd_pieces)); break;
      case 2: text.erase(at, below(10)); break;
      case 3: text[std::min(at, text.size() - 1)] = static_cast<char>(below(256)); break;
      case 4: {  // a line again, somewhere else
        const size_t begin = text.rfind('\n', at == 0 ? 0 : at - 1);
        const size_t from = begin == std::string::npos ? 0 : begin + 1;
        const std::string line = text.substr(from, text.find('\n', from) - from) + "\n";
        text.insert(below(text.size() + 1), line);
        break;
      }
      default: text.insert(at, std::to_string(static_cast<int64_t>(below(1u << 31)) - (1 << 30))); break;
    }
  }

  std::mt19937 random_;
};

bool in_range(double value, double max) { return std::isfinite(value) && std::abs(value) <= max; }

bool positions_in_range(const std::vector<double>& position, size_t axes) {
  return position.size() == axes &&
         std::all_of(position.begin(), position.end(), [](double x) { return in_range(x, max_length_mm); });
}

// What is wrong with the decoding of a program of `lines` lines, "" if nothing.
std::string violation(const DecodedProgram& p, int64_t lines, size_t axes) {
  std::vector<double> position(axes, 0.0);
  for (const Block& b : p.blocks) {
    if (b.nc_line < 1 || b.nc_line > lines) return "block nc_line " + std::to_string(b.nc_line);
    if (b.block_nr < 0 || b.block_nr > max_block_nr) return "block_nr " + std::to_string(b.block_nr);
    if (!(b.dwell_s >= 0 && b.dwell_s <= max_dwell_s)) return "dwell";
    for (const MFunction& m : b.m_functions)
      if (m.nr < 0 || !(m.pre_output_mm >= 0 && m.pre_output_mm <= max_length_mm)) return "M function";
    if (!b.has_motion) continue;
    const Motion& m = b.motion;
    if (!positions_in_range(m.start, axes) || !positions_in_range(m.end, axes)) return "start/end out of range";
    if (m.start != position) return "start is not the end of the block before";  // nothing moves unless decoded
    position = m.end;
    if (!in_range(m.center[0], max_length_mm) || !in_range(m.center[1], max_length_mm)) return "centre";
    // G00 carries the F in force, if any (DDTG-2: a short cut to it runs at it).
    const bool feed_ok = (m.type == MotionType::rapid && m.feed == 0) ||
                         (m.feed >= min_feed_mm_min / 60 && m.feed <= max_feed_mm_min / 60);
    if (!feed_ok) return "feed";
  }
  if (!p.error) return "";
  const Event& e = *p.error;
  if (e.nc_line < 1 || e.nc_line > lines) return "error nc_line " + std::to_string(e.nc_line);
  if (e.block_nr < 0 || e.block_nr > max_block_nr) return "error block_nr";
  if (e.message.empty() || e.message.find("decoder fault") != std::string::npos) return "message: " + e.message;
  if (std::any_of(e.message.begin(), e.message.end(), [](char c) { return c != '\t' && (c >= 0 && c < 0x20); }))
    return "control character in the message";
  return "";
}

std::string escaped(const std::string& text) {
  std::ostringstream out;
  for (const unsigned char c : text.substr(0, 2000)) {
    if (c >= 0x20 && c < 0x7f) out << c;
    else if (c == '\n') out << "\\n";
    else out << "\\x" << std::hex << static_cast<int>(c) << std::dec;
  }
  return out.str();
}

}  // namespace

TEST_CASE("KRN-1 KRN-2 decoder fuzz: random bytes and mutated programs never crash, every number in range",
          "[decoder][fuzz]") {
  const MachineConfig machine = test::xyz_machine();
  const char* env = std::getenv("HIL_DECODER_FUZZ_INPUTS");
  const int inputs = env ? std::atoi(env) : 100000;
  const char* seed = std::getenv("HIL_DECODER_FUZZ_SEED");
  Mutator mutator(seed ? static_cast<uint32_t>(std::strtoul(seed, nullptr, 10)) : 20240611);
  int errors[3] = {}, decoded_blocks = 0;
  for (int i = 0; i < 3 * inputs; ++i) {
    const std::string text = i % 3 == 0   ? mutator.random_bytes()
                             : i % 3 == 1 ? mutator.random_nc_text()
                                          : mutator.mutated(seeds[mutator.below(std::size(seeds))]);
    DecodedProgram p;
    try {
      p = decode_program(text, machine, {0, 0, 0}, 20000);  // loops end early
    } catch (const std::exception& e) {
      FAIL("exception " << e.what() << " from '" << escaped(text) << "'");
    }
    const std::string wrong = violation(p, std::count(text.begin(), text.end(), '\n') + 1, machine.axes.size());
    if (!wrong.empty()) FAIL(wrong << " from '" << escaped(text) << "'");
    errors[i % 3] += p.error ? 1 : 0;
    decoded_blocks += static_cast<int>(p.blocks.size());
  }
  WARN(3 * inputs << " inputs (random bytes, random NC text, mutated programs: " << inputs << " each); refused: "
               << errors[0] << ", " << errors[1] << ", " << errors[2] << "; " << decoded_blocks << " blocks decoded");
  CHECK(errors[2] < inputs);  // the mutations reach past the first error, too
}

TEST_CASE("KRN-1 issue 17: a word's number read the short way is the double std::from_chars gives, bit for bit",
          "[decoder][numbers]") {
  std::mt19937_64 random(17);
  auto below = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(random); };
  int short_way = 0;
  for (int i = 0; i < 2000000; ++i) {
    // Digits and '.' (sometimes two, or at either end), then a character that ends the number.
    std::string text;
    const size_t digits = 1 + below(i % 4 == 0 ? 25 : 16);
    for (size_t k = 0; k < digits; ++k) text += static_cast<char>('0' + (below(4) == 0 ? 9 : below(10)));
    for (size_t points = below(8) == 0 ? 2 : 1; points > 0; --points)
      if (below(10) > 0) text.insert(below(text.size() + 1), ".");
    const std::string line = text + (below(2) ? " X1" : "");
    const DecimalDigits read = read_decimal_digits(line.data(), line.data() + line.size());
    INFO(line);
    REQUIRE(read.end == line.data() + text.size());
    REQUIRE(read.has_digit == (text.find_first_of("0123456789") != std::string::npos));
    if (!read.value) continue;
    ++short_way;
    double expected = 0;
    const std::from_chars_result parsed = std::from_chars(text.data(), text.data() + text.size(), expected);
    REQUIRE(parsed.ptr == text.data() + text.size());
    REQUIRE(std::memcmp(&*read.value, &expected, sizeof expected) == 0);
  }
  CHECK(short_way > 1000000);
  // Through the decoder: every word's value, the short way or not.
  const MachineConfig machine = test::xyz_machine();
  for (const char* number : {"0.1", "1234567.125", "999999.9999999999", "0.000000000000001", "0.0000000000000001",
                             "123456789012345", "1234567890123456", "000000000000000000001.5", "5.", ".5", "-.25",
                             "+12.5", "-0"}) {
    const DecodedProgram p = decode_program(std::string("G01 F") + number + "\n", machine, {0, 0, 0});
    std::string_view digits(number);
    const bool negative = digits[0] == '-';
    if (digits[0] == '+' || digits[0] == '-') digits.remove_prefix(1);
    double expected = 0;
    std::from_chars(digits.data(), digits.data() + digits.size(), expected);
    if (negative) expected = -expected;
    INFO(number);
    const bool in_range = expected >= min_feed_mm_min && expected <= max_feed_mm_min;
    REQUIRE(p.error.has_value() != in_range);
    if (!in_range) continue;
    const DecodedProgram q = decode_program(std::string("G01 X0.001 F") + number + "\n", machine, {0, 0, 0});
    REQUIRE(q.blocks.size() == 1);
    CHECK(q.blocks[0].motion.feed == expected / 60.0);
  }
}
