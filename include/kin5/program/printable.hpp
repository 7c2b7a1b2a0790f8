/// @file program/printable.hpp
/// Input text made safe to print in a diagnostic: a program, its file name or a word quoted
/// from it may hold bytes a terminal acts on (ESC starts an escape sequence, CR rewrites the
/// line, a newline fakes another diagnostic). `printable` writes each such byte as `\xHH`: C0
/// control bytes (TAB, LF and CR too), DEL, the C1 controls U+0080 … U+009F (a terminal may take
/// U+009B as CSI), and any byte that is not part of well-formed UTF-8 (0xFF, a lone 0x80).
/// Well-formed UTF-8 otherwise passes unchanged, kin5's own "°" and "…" included.
/// @code
///   kin5::program::printable("M\x1b[31mX\xff");   // "M\x1B[31mX\xFF" (as text: backslash, x, 1, B …)
/// @endcode
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "lexing.hpp"

namespace kin5::program {

/// The length of the well-formed UTF-8 sequence at the start of `s` (not empty), or 0: no
/// overlong form, surrogate or code point above U+10FFFF.
inline std::size_t utf8_length(std::string_view s) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char c = byte(0);
  const std::size_t n = c < 0x80 ? 1 : c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (n == 0 || s.size() < n) return 0;
  for (std::size_t i = 1; i < n; ++i)
    if ((byte(i) & 0xC0) != 0x80) return 0;
  if (n == 3 && ((c == 0xE0 && byte(1) < 0xA0) || (c == 0xED && byte(1) >= 0xA0))) return 0;  // overlong, surrogate
  if (n == 4 && ((c == 0xF0 && byte(1) < 0x90) || (c == 0xF4 && byte(1) >= 0x90))) return 0;  // overlong, > U+10FFFF
  return n;
}

/// `s` with every byte a terminal may act on written as `\xHH` (see the file comment).
inline std::string printable(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  while (!s.empty()) {
    const std::size_t n = utf8_length(s);
    const auto c = static_cast<unsigned char>(s[0]);
    const bool c1 = n == 2 && c == 0xC2 && static_cast<unsigned char>(s[1]) < 0xA0;  // U+0080 … U+009F
    if (n == 0 || c < 0x20 || c == 0x7f || c1) {
      const std::size_t bytes = n == 0 ? 1 : n;
      for (std::size_t i = 0; i < bytes; ++i) out += '\\', out += lexing::hex_byte(s[i], true).substr(1);
      s.remove_prefix(bytes);
      continue;
    }
    out.append(s.data(), n);
    s.remove_prefix(n);
  }
  return out;
}

}  // namespace kin5::program
