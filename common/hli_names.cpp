#include "hli_names.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace hil {
namespace {

template <typename>
constexpr bool no_tf5200_type = false;

// The TF5200 type of a field's C++ type.
template <typename T>
constexpr const char* tf5200_type() {
  if constexpr (std::is_same_v<T, bool>) return "BOOL";
  else if constexpr (std::is_same_v<T, int32_t>) return "DINT";
  else if constexpr (std::is_same_v<T, uint32_t>) return "UDINT";
  else if constexpr (std::is_same_v<T, uint16_t>) return "UINT";
  else if constexpr (std::is_same_v<T, int64_t>) return "LINT";
  else if constexpr (std::is_same_v<T, double>) return "LREAL";
  else static_assert(no_tf5200_type<T>, "a named HLI field must be bool, int32_t, uint32_t, uint16_t, int64_t or double");
}

// An LREAL of a unit (0.1 um lengths of the insert command) is named with
// whole values: read rounded to the nearest 0.1 um.
constexpr int64_t lreal_limit = int64_t{1} << 53;

// `reach` takes a Record (const or not) to the field.
template <typename Record, typename Leaf, typename Reach>
HliField<Record> make_field(std::string name, Reach reach) {
  if constexpr (std::is_same_v<Leaf, double>)
    return {std::move(name),
            tf5200_type<Leaf>(),
            -lreal_limit,
            lreal_limit,
            [reach](const Record& record) {
              const double v = reach(record);
              return std::isfinite(v) ? std::llround(std::clamp(v, -1e18, 1e18)) : int64_t{0};
            },
            [reach](Record& record, int64_t value) { reach(record) = static_cast<double>(value); }};
  else
  return {std::move(name),
          tf5200_type<Leaf>(),
          std::numeric_limits<Leaf>::min(),
          static_cast<int64_t>(std::numeric_limits<Leaf>::max()),
          [reach](const Record& record) { return static_cast<int64_t>(reach(record)); },
          [reach](Record& record, int64_t value) { reach(record) = static_cast<Leaf>(value); }};
}

// Walks the table from Root down to `Struct` (reached by `reach`); every
// whole-number field gets its dotted name. The others (doubles, the channel
// state, the axis arrays) have keys of their own in scenarios.
template <typename T>
struct is_std_array : std::false_type {};
template <typename T, size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};

template <typename Root, typename Struct, typename Reach>
void add_fields(std::vector<HliField<Root>>& out, const std::string& prefix, Reach reach) {
  Struct::fields([&](const char* name, auto member) {
    using Leaf = member_t<decltype(member)>;
    auto reach_leaf = [reach, member](auto& root) -> auto& { return reach(root).*member; };
    if constexpr (is_record_v<Leaf>) {
      add_fields<Root, Leaf>(out, prefix + name + ".", reach_leaf);
    } else if constexpr (is_std_array<Leaf>::value) {  // position_at_next_stop[0] ...
      using Element = typename Leaf::value_type;
      for (size_t i = 0; i < std::tuple_size_v<Leaf>; ++i)
        out.push_back(make_field<Root, Element>(prefix + name + "[" + std::to_string(i) + "]",
                                                [reach_leaf, i](auto& root) -> auto& { return reach_leaf(root)[i]; }));
    } else if constexpr (std::is_integral_v<Leaf>) {
      out.push_back(make_field<Root, Leaf>(prefix + name, reach_leaf));
    } else if constexpr (std::is_same_v<Leaf, double>) {
      // A unit's LREAL, and the record's own but dist_prog_start and
      // path_velocity, which have keys of their own (s_function_value_r, rpm).
      const std::string own(name);
      if (!std::is_same_v<Struct, Root> || (own != "dist_prog_start" && own != "path_velocity"))
        out.push_back(make_field<Root, Leaf>(prefix + name, reach_leaf));
    }
  });
}

}  // namespace

template <typename Record>
std::string HliField<Record>::type_text() const {
  if (std::string(type) == "BOOL") return "a BOOL (true or false)";
  return std::string("a ") + type + " (" + std::to_string(min) + " .. " + std::to_string(max) + ")";
}

template <typename Record>
const std::vector<HliField<Record>>& hli_fields() {
  static const std::vector<HliField<Record>> fields = [] {
    std::vector<HliField<Record>> out;
    add_fields<Record, Record>(out, "", [](auto& record) -> auto& { return record; });
    return out;
  }();
  return fields;
}

template <typename Record>
const HliField<Record>* find_hli_field(const std::string& name) {
  for (const HliField<Record>& field : hli_fields<Record>())
    if (field.name == name) return &field;
  return nullptr;
}

template <typename Record>
std::optional<int64_t> read_hli_field(const Record& record, const std::string& name) {
  const HliField<Record>* field = find_hli_field<Record>(name);
  if (!field) return std::nullopt;
  return field->read(record);
}

template <typename Record>
bool write_hli_field(Record& record, const std::string& name, int64_t value) {
  const HliField<Record>* field = find_hli_field<Record>(name);
  if (!field || !field->holds(value)) return false;
  field->write(record, value);
  return true;
}

template <typename Record>
std::string hli_field_names() {
  std::string names;
  for (const HliField<Record>& field : hli_fields<Record>()) {
    names += (names.empty() ? "" : ", ") + field.name;
    if (std::string(field.type) != "BOOL") names += std::string(" (") + field.type + ")";
  }
  return names;
}

const std::vector<HliAxisFlag>& hli_axis_flags() {
  static const std::vector<HliAxisFlag> flags = [] {
    std::vector<HliAxisFlag> out;
    HliState::fields([&](const char* name, auto member) {
      if constexpr (std::is_same_v<member_t<decltype(member)>, std::vector<bool>>)
        out.push_back({name, [member](const HliState& s, const std::string& axis) -> std::optional<bool> {
                         const std::vector<bool>& values = s.*member;
                         for (size_t i = 0; i < s.axis_name.size() && i < values.size(); ++i)
                           if (s.axis_name[i] == axis) return values[i];
                         return std::nullopt;
                       }});
    });
    return out;
  }();
  return flags;
}

const HliAxisFlag* find_hli_axis_flag(const std::string& name) {
  for (const HliAxisFlag& flag : hli_axis_flags())
    if (flag.name == name) return &flag;
  return nullptr;
}

// The two records that have names.
#define HIL_NAMED(Record)                                                                        \
  template struct HliField<Record>;                                                              \
  template const std::vector<HliField<Record>>& hli_fields<Record>();                            \
  template const HliField<Record>* find_hli_field<Record>(const std::string& name);              \
  template std::optional<int64_t> read_hli_field(const Record& record, const std::string& name); \
  template bool write_hli_field(Record& record, const std::string& name, int64_t value);         \
  template std::string hli_field_names<Record>();
HIL_NAMED(HliControl)
HIL_NAMED(HliState)
#undef HIL_NAMED

}  // namespace hil
