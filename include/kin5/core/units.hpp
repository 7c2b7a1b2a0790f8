/// @file units.hpp
/// Angle and length quantities as distinct types: radians inside kin5, degrees only at the NC
/// boundary, millimetres for every length.
///
/// A `radians` never converts silently to a `degrees` or a `double`; the conversion is spelled
/// out (`to_radians`, `to_degrees`, `.value`). Example:
/// @code
///   using namespace kin5::literals;
///   kin5::radians a = kin5::to_radians(-77.954_deg);
/// @endcode
#pragma once

#include <compare>

namespace kin5 {

/// π to double precision.
inline constexpr double pi = 3.14159265358979323846;

/// An angle in radians; the unit of every angle inside kin5.
struct radians {
  double value{};
  constexpr auto operator<=>(const radians&) const = default;
  constexpr radians operator-() const { return {-value}; }
  constexpr radians& operator+=(radians o) { value += o.value; return *this; }
  constexpr radians& operator-=(radians o) { value -= o.value; return *this; }
  friend constexpr radians operator+(radians a, radians b) { return {a.value + b.value}; }
  friend constexpr radians operator-(radians a, radians b) { return {a.value - b.value}; }
  friend constexpr radians operator*(double k, radians a) { return {k * a.value}; }
};

/// An angle in degrees; used only where NC programs, limits and people write angles.
struct degrees {
  double value{};
  constexpr auto operator<=>(const degrees&) const = default;
  constexpr degrees operator-() const { return {-value}; }
  friend constexpr degrees operator+(degrees a, degrees b) { return {a.value + b.value}; }
  friend constexpr degrees operator-(degrees a, degrees b) { return {a.value - b.value}; }
};

/// A length in millimetres.
struct millimetres {
  double value{};
  constexpr auto operator<=>(const millimetres&) const = default;
};

constexpr radians to_radians(degrees d) { return {d.value * (pi / 180.0)}; }
constexpr degrees to_degrees(radians r) { return {r.value * (180.0 / pi)}; }

namespace literals {
constexpr degrees operator""_deg(long double v) { return {static_cast<double>(v)}; }
constexpr degrees operator""_deg(unsigned long long v) { return {static_cast<double>(v)}; }
constexpr radians operator""_rad(long double v) { return {static_cast<double>(v)}; }
constexpr millimetres operator""_mm(long double v) { return {static_cast<double>(v)}; }
constexpr millimetres operator""_mm(unsigned long long v) { return {static_cast<double>(v)}; }
}  // namespace literals

}  // namespace kin5
