#include "messages.hpp"

#include <iterator>
#include <limits>
#include <type_traits>
#include <vector>

namespace hil::lcm_support {
namespace {

// Whether every value of From fits To (LCM has no unsigned types: a UDINT
// is an int64_t in the .lcm); non-numbers must be the same type.
template <typename From, typename To>
constexpr bool holds_every_value() {
  if constexpr (std::is_enum_v<From>) return holds_every_value<std::underlying_type_t<From>, To>();
  else if constexpr (std::is_arithmetic_v<From> && std::is_arithmetic_v<To>)
    return std::is_integral_v<From> == std::is_integral_v<To> &&
           (std::is_signed_v<To> || !std::is_signed_v<From>) &&
           std::numeric_limits<To>::digits >= std::numeric_limits<From>::digits;
  else return std::is_same_v<From, To>;
}

template <typename T>
struct is_vector : std::false_type {};
template <typename T>
struct is_vector<std::vector<T>> : std::true_type {};

// LCM arrays carry their length in a field of their own; the per-axis
// arrays all have n_axes elements (LCM would encode past a shorter one).
template <typename Message>
void set_lengths(Message&) {}
void set_lengths(hil::hli_state_t& m) {
  m.n_axes = static_cast<int16_t>(m.axis_name.size());
  m.axis_position_r.resize(m.axis_name.size());
  m.lift_active.resize(m.axis_name.size());
  m.lift_suppressed.resize(m.axis_name.size());
}

// Copies a record of the table (hli_table.hpp) to its LCM twin or back,
// member by member, by name; records within recurse.
template <typename From, typename To>
void copy(const From& from, To& to) {
  if constexpr (is_record_v<From>) {
    From::template fields<To>([&](const char*, auto record, auto twin) { copy(from.*record, to.*twin); });
    set_lengths(to);
  } else if constexpr (is_record_v<To>) {
    To::template fields<From>([&](const char*, auto record, auto twin) { copy(from.*twin, to.*record); });
  } else if constexpr (is_vector<From>::value && is_vector<To>::value &&
                       !std::is_same_v<From, To>) {  // std::vector<bool> <-> LCM boolean[] (int8_t)
    to.resize(from.size());
    for (size_t i = 0; i < from.size(); ++i) {
      typename To::value_type element{};
      copy(static_cast<typename From::value_type>(from[i]), element);
      to[i] = element;
    }
  } else if constexpr (std::is_array_v<From> || std::is_array_v<To>) {  // std::array <-> a fixed LCM array
    static_assert(std::size(From{}) == std::size(To{}), "an HLI array and its LCM twin must have one length");
    for (size_t i = 0; i < std::size(from); ++i) copy(from[i], to[i]);
  } else {
    static_assert(holds_every_value<From, To>() || holds_every_value<To, From>(),
                  "an HLI field and its LCM twin must hold the same values: see common/hli_table.hpp");
    to = static_cast<To>(from);  // towards the library: a value the library sent
  }
}

}  // namespace

hil::event_t to_message(const Event& e, int64_t cycle, int64_t utime, const std::string& source) {
  hil::event_t m;
  m.utime = utime;
  m.cycle = cycle;
  m.severity = static_cast<int8_t>(e.severity);
  m.verdict = static_cast<int8_t>(e.verdict);
  m.id = e.id;
  m.parameter = e.parameter;
  m.source = source;
  m.axis = e.axis;
  m.nc_line = e.nc_line;
  m.block_nr = e.block_nr;
  m.value = e.value;
  m.limit = e.limit;
  m.message = e.message;
  return m;
}

Event from_message(const hil::event_t& m) {
  return {static_cast<Severity>(m.severity), m.id, m.parameter, m.axis, m.nc_line, m.block_nr,
          m.value, m.limit, m.message, static_cast<Verdict>(m.verdict)};
}

hil::hli_state_t to_message(const HliState& s, int64_t utime) {
  hil::hli_state_t m;
  m.utime = utime;
  m.cycle = s.cycle;
  copy(s, m);
  return m;
}

HliState from_message(const hil::hli_state_t& m) {
  HliState s;
  s.cycle = m.cycle;
  copy(m, s);
  return s;
}

hil::hli_control_t to_message(const HliControl& c, int64_t utime) {
  hil::hli_control_t m;
  m.utime = utime;
  m.cycle = c.cycle;
  copy(c, m);
  return m;
}

HliControl from_message(const hil::hli_control_t& m) {
  HliControl c;
  c.cycle = m.cycle;
  copy(m, c);
  return c;
}

std::string monitor_names(int32_t bits) {
  static const std::pair<int32_t, const char*> names[] = {
      {hil::axis_state_t::MONITOR_ACCELERATION, "acceleration P-AXIS-00442"},
      {hil::axis_state_t::MONITOR_VELOCITY, "velocity P-AXIS-00440"},
      {hil::axis_state_t::MONITOR_FOLLOWING_ERROR, "following error P-AXIS-00168/00169"},
      {hil::axis_state_t::MONITOR_SOFTWARE_LIMIT, "software limit switch P-AXIS-00177/00178"},
      {hil::axis_state_t::MONITOR_NOT_FINITE, "setpoint not finite"}};
  std::string out;
  for (const auto& [bit, name] : names)
    if (bits & bit) out += (out.empty() ? "" : ", ") + std::string(name);
  return out.empty() ? "monitoring" : out;
}

}  // namespace hil::lcm_support
