/// @file program/haas/reader.hpp
/// The Haas mill reader: ISO's reader (iso/reader.hpp) with the words a Haas control reads
/// otherwise (`own_words`), read first. Where the grammar is Fanuc's (G0–G3, G17–G19, G20/G21,
/// G40–G43, G49, G54–G59, G90, G93/G94, T, M6, M3–M5, M8/M9, M30, `( … )` comments, `%`) the ISO
/// reader reads it. The Haas words (docs/dialects/haas.md, with the manual's sections):
/// | words | read as |
/// |---|---|
/// | `G234 H n` | tool center point control (TCPC) on, with the length of offset n (`tcp`, `length_register`) |
/// | `G49` | TCPC and length compensation off (as ISO reads it) |
/// | `G43 H n` after `G234` | TCPC off, length n on (G43 replaces G234 in group 08, as ISO reads G43.4) |
/// | `G154 P n` (n = 1 … 99), `G110` … `G129` | additional work offset n (`work_offset`, family `extended`; G110 … G129 are P1 … P20) |
/// | `G04 P t` | a dwell: t seconds with a decimal point, t milliseconds without one (`state.dwell_s`) |
/// | `G255` | dynamic work offset off: kept (G254, which switches it on, is refused) |
/// Refused at the word: `G43.4`, `G43.5` and `G54.1` (Fanuc's codes, not a Haas control's),
/// `G254` (dynamic work offset: the work offset turns with the rotary axes), `G234` without H,
/// `G154` without P or with P outside 1 … 99, two work offsets in a block, `G04` with X or
/// without P, and a dwell with other words. Everything else is ISO's (reader.hpp's file comment).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../dwell.hpp"
#include "../iso/reader.hpp"
#include "../iso/reader_state.hpp"
#include "../iso/vocabulary.hpp"
#include "../lexing.hpp"
#include "../transmission.hpp"
#include "../work_offsets.hpp"
#include "vocabulary.hpp"

namespace kin5::program::haas::detail {

using iso::detail::g_code;
using iso::word;

/// The words a Haas control reads otherwise than a Fanuc one (see the file comment). Parameters,
/// whole addresses and decimal points are ISO's (`iso::detail::no_own_words`).
class own_words : public iso::detail::no_own_words {
 public:
  /// FANUC macro statements with Haas's `M97 P n` and M98's whole P (iso/statements.hpp).
  using syntax = iso::basic_macro_statements<true>;

  /// Reads and removes from `words` the Haas words; rewrites `G234` and `G154` as the ISO codes
  /// the ISO reader reads with their H and P (their text stays as written, for messages).
  template <class Error>
  void take(std::vector<word>& words, block& b, Error&& error) {
    const word* offset = nullptr;  // the work-offset word of the line
    const word* g4 = nullptr;      // the dwell
    word* g154 = nullptr;
    bool g234 = false, h = false;
    for (word& w : words) {
      if (w.letter == 'H') h = true;
      if (w.letter != 'G') continue;
      const int g = g_code(w.value);
      if (g == 434 || g == 435 || g == 541)
        return error(w.column, std::string(w.text) + " is not a Haas G code" +
                                   (g == 541 ? " (its additional work offsets are G154 P1 … P99)"
                                             : " (tool center point control is G234 H n)"));
      if (g == 2540)
        return error(w.column, "G254: dynamic work offset is not supported (the work offset turns with the rotary "
                               "axes: a tilted setup)");
      if (g == 2550) continue;  // G255, dynamic work offset off: kept below
      if (g == 40) g4 = &w;
      if (g == 2340) g234 = true, w.value = 43.4;  // the ISO reader's G43.4: H, TCP on
      const bool extended = g == 1540 || (g >= 1100 && g <= 1290 && g % 10 == 0);
      if (extended || (g >= 540 && g <= 590 && g % 10 == 0)) {
        if (offset) return error(w.column, "two work offsets in one block");
        offset = &w;
        if (g == 1540) g154 = &w;
      }
    }
    keep_g255(words, b);
    if (g234 && !h) return error(column_of(words, 434), "G234 needs H n, the length offset TCPC applies");
    if (g4 && offset) return error(g4->column, "G04: a dwell takes a block of its own (N, P and a comment)");
    if (g4) return dwell(words, *g4, b, error);
    if (g154) return additional_offset(words, *g154, b, error);
    if (offset && g_code(offset->value) >= 1100) {  // G110 … G129: G154 P1 … P20
      b.state.work_offset = work_offset{work_offset_family::extended, g_code(offset->value) / 10 - 109};
      erase(words, offset);
    }
  }

  /// A dwell with other words: refused (every dialect writes it in a block of its own).
  template <class Error>
  void check(const block& b, Error&& error) {
    if (b.state.dwell_s && !b.only_dwell())
      error(b.where.column, "G04: a dwell is read in a block of its own (N, P and a comment): every other dialect "
                            "writes it so");
  }

 private:
  static std::size_t column_of(const std::vector<word>& words, int g) {
    for (const word& w : words)
      if (w.letter == 'G' && g_code(w.value) == g) return w.column;
    return 1;
  }

  /// `G255` (dynamic work offset off) is kept as written: it does nothing while `G254`, refused,
  /// was never on.
  static void keep_g255(std::vector<word>& words, block& b) {
    for (std::size_t k = 0; k < words.size(); ++k)
      if (words[k].letter == 'G' && g_code(words[k].value) == 2550) {
        b.kept_words.emplace_back(words[k].text);
        words.erase(words.begin() + static_cast<std::ptrdiff_t>(k));
        return;
      }
  }

  static void erase(std::vector<word>& words, const word* w) { words.erase(words.begin() + (w - words.data())); }

  /// Erases words `a` and `b` of `words`, the later first (erasing moves the words after it).
  static void erase_both(std::vector<word>& words, const word* a, const word* b) {
    erase(words, a < b ? b : a);
    erase(words, a < b ? a : b);
  }

  /// `G154 P n`: additional work offset n, 1 … 99 (read here: ISO's G54.1 takes 1 … 300).
  template <class Error>
  static void additional_offset(std::vector<word>& words, const word& g154, block& b, Error&& error) {
    const word* p = nullptr;
    for (const word& w : words)
      if (w.letter == 'P') p = &w;
    if (!p) return error(g154.column, "G154 needs P n, the additional work offset (1 … 99)");
    if (!lexing::is_whole(p->value) || p->value < 1 || p->value > 99)
      return error(p->column, "G154 " + std::string(p->text) + ": the additional work offset is a whole number from 1 "
                                                                "to 99");
    b.state.work_offset = work_offset{work_offset_family::extended, static_cast<int>(p->value)};
    erase_both(words, &g154, p);
  }

  /// `G04 P t`: t seconds with a decimal point, t milliseconds without (`dwell_steps`).
  template <class Error>
  static void dwell(std::vector<word>& words, const word& g4, block& b, Error&& error) {
    const word* p = nullptr;
    for (const word& w : words) {
      if (w.letter == 'X') return error(w.column, "G04 X: a Haas dwell is G04 P (seconds with a decimal point)");
      if (w.letter == 'P') p = &w;
    }
    if (!p) return error(g4.column, "G04 needs P, the dwell (seconds with a decimal point, milliseconds without)");
    const std::string written(p->text);
    if (p->value < 0) return error(p->column, "G04 " + written + ": a dwell time cannot be negative");
    if (p->substituted)
      return error(p->column, "G04 " + written + ": a parameter's dwell is not read (whether it is seconds or "
                                                 "milliseconds depends on a decimal point it does not have)");
    const bool seconds = p->digits.find('.') != std::string_view::npos;
    const double s = seconds ? p->value : p->value / 1000.0;
    if (!seconds && !lexing::is_whole(p->value))
      return error(p->column, "G04 " + written + ": without a decimal point P is whole milliseconds");
    if (const std::string why = dwell_refusal(dwell_steps, s); !why.empty())
      return error(p->column, "G04 " + written + ": " + why);
    b.state.dwell_s = s;
    erase_both(words, &g4, p);
  }
};

}  // namespace kin5::program::haas::detail

namespace kin5::program::haas {

/// Reads Haas mill G code block by block: `on_block` receives each block in file order as soon
/// as it is read; errors and warnings go to `diagnostics` (its `parsed` is not touched).
inline void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                        const block_sink& on_block) {
  read_transmitted(text, file_name, diagnostics, on_block, [&](std::string_view body, const block_sink& sink) {
    iso::detail::basic_reader<detail::own_words>(file_name, diagnostics, sink).run(body);
  });
}

}  // namespace kin5::program::haas
