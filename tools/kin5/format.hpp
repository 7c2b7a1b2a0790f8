// Helpers shared by the kin5 subcommands: reading numbers and axis values from arguments,
// writing angles and vectors, and the ids of the catalog machines.
//
// Arguments are read strictly: a whole argument must be one finite decimal number (an exponent
// is allowed, `inf` and `nan` are not), and a length in mm lies within ±1e9 (`parse_length_mm`).
// Angles are written in degrees with 6 decimals, tool axes with 12 significant digits, and `-0`
// never appears in the output.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <kin5/machines/catalog.hpp>
#include <kin5/program/number.hpp>

namespace kin5::tool {

/// The finite number that is the whole of `s` (leading `+` allowed), or nothing.
inline std::optional<double> parse_real(std::string_view s) {
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) return std::nullopt;  // "+-1", "++1"
  }
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v, std::chars_format::general);
  if (r.ec != std::errc{} || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

/// A length in mm an option gives (a tool length, a work offset's coordinate): a whole argument
/// that is one finite number within ±1e9 mm (what an NC program can hold, `program::writable`),
/// and 0 or more when `non_negative`; nothing otherwise (`nan`, `inf`, `1e400` included). The
/// one check of every command's lengths.
inline std::optional<double> parse_length_mm(std::string_view s, bool non_negative = false) {
  const auto v = parse_real(s);
  if (!v || !kin5::program::writable(*v) || (non_negative && !(*v >= 0.0))) return std::nullopt;
  return v;
}

/// `s` split at every `separator` (empty fields kept).
inline std::vector<std::string_view> split(std::string_view s, char separator) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == separator) {
      out.push_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

/// Three lengths X,Y,Z in mm separated by commas, each as `parse_length_mm`, or nothing.
inline std::optional<std::array<double, 3>> parse_point_mm(std::string_view s) {
  const auto fields = split(s, ',');
  if (fields.size() != 3) return std::nullopt;
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto v = parse_length_mm(fields[i]);
    if (!v) return std::nullopt;
    out[i] = *v;
  }
  return out;
}

/// An angle in degrees with 6 decimals ("60.000000"); a value that rounds to zero is "0.000000".
inline std::string format_degrees(double value_deg) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", value_deg);
  std::string s(buf);
  if (s == "-0.000000") s.erase(0, 1);
  return s;
}

/// A tool-axis component with 12 significant digits; |x| < 1e-15 (round-off of an exact zero)
/// is written "0".
inline std::string format_component(double x) {
  if (std::fabs(x) < 1e-15) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", x);
  return buf;
}

/// The ids of every catalog machine, in catalog order.
inline std::vector<std::string_view> machine_ids() {
  std::vector<std::string_view> ids;
  kin5::machines::for_each_machine([&]<class M>() { ids.push_back(M::id); });
  return ids;
}

/// "a, b, c" from a list of names.
inline std::string join(const std::vector<std::string_view>& names, std::string_view separator = ", ") {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) out += separator;
    out += names[i];
  }
  return out;
}

/// The lookup of a catalog machine by id (machines/catalog.hpp), the one the whole tool uses.
using kin5::machines::with_machine;

}  // namespace kin5::tool
