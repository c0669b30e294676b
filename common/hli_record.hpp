#pragma once
// A record: a struct whose members come from an X-macro list X(type, name)
// and which can walk them, so that one list (hli_table.hpp) gives the
// members, the LCM conversion and the names scenarios use.
//
// HIL_RECORD(Name, LIST) inside `struct Name` declares LIST's members
// (value-initialised) and
//   template <typename... Twins, typename F> static void fields(F&& f);
// which calls f("name", &Name::name, &Twins::name...) for each member, in
// the list's order. A twin is a struct with members of the same names: the
// LCM type generated from lcmtypes/*.lcm.
#include <type_traits>

#define HIL_RECORD_MEMBER(type, name) type name{};
#define HIL_RECORD_FIELD(type, name) f(#name, &Self::name, &Twins::name...);
#define HIL_RECORD(Name, LIST)             \
  LIST(HIL_RECORD_MEMBER)                  \
  using is_hil_record = std::true_type;    \
  template <typename... Twins, typename F> \
  static void fields(F&& f) {              \
    using Self = Name;                     \
    LIST(HIL_RECORD_FIELD)                 \
  }

namespace hil {

template <typename T, typename = void>
struct is_record : std::false_type {};
template <typename T>
struct is_record<T, std::void_t<typename T::is_hil_record>> : std::true_type {};
template <typename T>
constexpr bool is_record_v = is_record<T>::value;

// The member type of a pointer to member: member_t<int Foo::*> is int.
template <typename M>
struct member_of;
template <typename C, typename T>
struct member_of<T C::*> {
  using type = T;
};
template <typename M>
using member_t = typename member_of<M>::type;

}  // namespace hil
