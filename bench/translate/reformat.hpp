/// @file bench/translate/reformat.hpp
/// The floor the translation benchmarks measure `kin5 translate` against: an NC program read
/// and written back with every number parsed and formatted again, and nothing else: no
/// kinematics, no program model. Written for speed only: one pass over the bytes, numbers
/// through std::from_chars and std::to_chars, one output buffer.
///
/// Every word `LETTER NUMBER` becomes `LETTER` and the number, integers as integers, others with
/// 3 decimals (trailing zeros kept: the cheapest correct form); comments and words without
/// numbers are copied unchanged.
/// @code
///   std::string out;
///   const unsigned long long numbers = kin5_bench::reformat_numbers(text, out);
/// @endcode
#pragma once

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>

namespace kin5_bench {

/// Writes `text` reformatted (see the file comment) to `out`; returns how many numbers it read.
inline unsigned long long reformat_numbers(std::string_view text, std::string& out) {
  out.resize(text.size() + text.size() / 2 + 64);
  char* w = out.data();
  const char* p = text.data();
  const char* const end = p + text.size();
  unsigned long long numbers = 0;
  while (p < end) {
    if (static_cast<std::size_t>(w - out.data()) + 64 > out.size()) {  // room for one number
      const std::size_t used = static_cast<std::size_t>(w - out.data());
      out.resize(out.size() * 2);
      w = out.data() + used;
    }
    const char c = *p;
    if (c == ';') {  // comment to the end of the line
      const char* nl = p;
      while (nl < end && *nl != '\n') ++nl;
      const std::size_t used = static_cast<std::size_t>(w - out.data());
      if (used + static_cast<std::size_t>(nl - p) + 64 > out.size()) {
        out.resize(2 * (used + static_cast<std::size_t>(nl - p)) + 64);
        w = out.data() + used;
      }
      while (p < nl) *w++ = *p++;
      continue;
    }
    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    if (letter && p + 1 < end && (p[1] == '-' || p[1] == '+' || p[1] == '.' || (p[1] >= '0' && p[1] <= '9'))) {
      double v = 0;
      const char* q = p + 1;
      if (*q == '+') ++q;
      const auto r = std::from_chars(q, end, v);
      if (r.ec == std::errc{}) {
        bool integer = true;  // N10, G1, M30: written back as integers
        for (const char* d = q; d < r.ptr; ++d) integer = integer && *d != '.';
        *w++ = c;
        w = integer ? std::to_chars(w, w + 40, static_cast<long long>(v)).ptr
                    : std::to_chars(w, w + 40, v, std::chars_format::fixed, 3).ptr;
        p = r.ptr;
        ++numbers;
        continue;
      }
    }
    *w++ = *p++;
  }
  out.resize(static_cast<std::size_t>(w - out.data()));
  return numbers;
}

}  // namespace kin5_bench
