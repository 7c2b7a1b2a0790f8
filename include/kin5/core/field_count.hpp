/// @file core/field_count.hpp
/// The number of fields of an aggregate, counted at compile time: the most initialisers
/// `T{…}` accepts. A codec that must handle every field of a struct states the count it handles
/// (`static_assert(field_count<T>() == n)`), so a field added to the struct without its codec
/// stops the build instead of being lost without a word.
/// @code
///   struct p { int a; std::optional<double> b; };
///   static_assert(kin5::field_count<p>() == 2);
/// @endcode
/// Fields must be constructible from a value of their own type (not arrays, not references).
#pragma once

#include <cstddef>

namespace kin5 {

namespace detail {
/// Converts to any type: one initialiser that fits any field.
struct any_field {
  template <class T>
  operator T() const;
};
template <class T, class... Fields>
constexpr std::size_t count_fields() {
  if constexpr (requires { T{Fields{}..., any_field{}}; }) return count_fields<T, Fields..., any_field>();
  else return sizeof...(Fields);
}
}  // namespace detail

/// How many fields aggregate `T` has.
template <class T>
constexpr std::size_t field_count() {
  return detail::count_fields<T>();
}

}  // namespace kin5
