/// @file program/heidenhain/lexer.hpp
/// The first stage of the Heidenhain reader: physical lines joined into blocks (a line ending in
/// `~` continues on the next, also when the `~` ends a `;` comment: that comment ends before the
/// `~`), and the text of a block split into words — address letters with a value or a lone sign
/// (`X+34.983`, `DR-`, `FMAX`, `F MAX`, `TX-0.6`), a Q parameter as a value (`FQ1`, `F Q1`,
/// `X+Q2`), bare numbers, and the comment after `;` — each at its offset in the joined text,
/// which `where` turns back into a line and column. What a word means is the reader's.
#pragma once

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "../block.hpp"
#include "../dwell.hpp"
#include "../interp/parameter_store.hpp"
#include "../lexing.hpp"
#include "../number.hpp"
#include "../text.hpp"

namespace kin5::program::heidenhain {

/// One word of a motion, M or TOOL CALL line: address letters, then a value or a lone sign.
struct word {
  std::string key;                ///< upper-case letters; empty for a bare number
  std::optional<double> value;    ///< the number after the letters
  char sign = 0;                  ///< `+` or `-` written with no digits (`DR+`)
  std::string written;            ///< the whole word, upper case, blanks removed
  std::size_t pos = 0;            ///< offset of its first byte in the block's text
  bool bad = false;               ///< already reported
  bool expression = false;        ///< `X=…`, `X+Q1*2`: more than a parameter
  /// `FQ1`, `F Q1`, `X+Q1`, `X-QL2`, `Y+QR3`: the value is (minus) this parameter's
  std::optional<interp::parameter_key> parameter;
  bool parameter_negated = false; ///< `X-Q1`
  number_error error = number_error::none;
  std::string malformed;          ///< a number with a second point (`+1.2.3`), as written
};

/// The text of one block: its physical lines joined at `~`, with the way back to line and column.
struct block_text {
  std::string content;   ///< the lines joined with a blank, `~` and comments before a `~` removed
  std::vector<std::string> inner_comments;  ///< the comments that ended before a `~`, in order
  std::string upper;     ///< `content` in upper case
  std::string raw;       ///< the source lines as written, joined with `\n`
  lexing::line_map lines;
  file_name file;
  bool continued_past_end = false;  ///< its last line ends in `~` and is the file's last line

  source_location where(std::size_t pos) const {
    const auto [line, column] = lines.locate(pos);
    return {file, line, column};
  }
};

/// Where the text of a comment ends, from `begin` on, once the `~`s it ends in and the blanks
/// around them are cut (`text.size()` when it does not end in `~`). The rule for every comment
/// read or written: none ends in `~`, which at the end of a line continues the block onto the
/// next one.
inline std::size_t end_without_continuation(std::string_view text, std::size_t begin = 0) {
  std::size_t end = text.size();
  for (bool cut = false;;) {
    std::size_t e = end;
    while (e > begin && is_space(text[e - 1])) --e;
    if (e == begin || text[e - 1] != '~') return cut ? e : end;
    end = e - 1, cut = true;
  }
}

/// `text` as the end of a line after `;`: without the `~`s it ends in (and the blanks around
/// them), which would read as a continuation of the block onto the next line.
inline std::string without_continuation(std::string text) {
  text.resize(end_without_continuation(text));
  return text;
}

namespace detail {

/// The most decimals of a feed or spindle speed (F, S) the TNC reads (TNC 640 User's Manual
/// DIN/ISO 1/2015, §19.3 p. 631): the writer's finest, and the reader refuses a rate these
/// cannot write back (`unwritable_rate`).
inline constexpr int finest_rate_decimals = 3;

/// The dwells Cycle 9 takes: 0 to 3600 s in steps of 0.001 s (TNC 640 User's Manual DIN/ISO
/// 1/2015, §19.3 p. 631).
inline constexpr dwell_input dwell_steps{3, 3600.0};

inline bool is_axis_letter(char c) { return c == 'X' || c == 'Y' || c == 'Z' || c == 'A' || c == 'B' || c == 'C'; }

inline bool starts_number(std::string_view s, std::size_t i) {
  if (i >= s.size()) return false;
  if (is_digit(s[i]) || s[i] == '.') return true;
  return (s[i] == '+' || s[i] == '-') && i + 1 < s.size() && (is_digit(s[i + 1]) || s[i + 1] == '.');
}

/// Joins line `li` and the lines that continue it (`~`) into `out`; returns the index of the
/// block's last line.
inline std::size_t join_block(const std::vector<text_line>& lines, std::size_t li, block_text& out) {
  const std::size_t first = li;
  for (;;) {
    const std::string_view t = lines[li].text;
    std::size_t end = t.size();
    while (end > 0 && is_space(t[end - 1])) --end;
    const bool continued = end > 0 && t[end - 1] == '~';
    const std::size_t semicolon = t.find(';');
    if (li != first) out.raw += '\n';
    out.raw += t;
    out.lines.add(out.content.size(), lines[li].number, 1);
    // The continuing `~` is cut, and so are the `~`s (and blanks) before it (`;NOTE~~`,
    // `* - NOTE ~ ~`): a comment never ends in `~` (end_without_continuation).
    if (continued && semicolon < end - 1) {  // `Q200=3 ;SET-UP CLEARANCE~`: the comment ends at the `~`
      const std::size_t comment_end = end_without_continuation(t.substr(0, end), semicolon + 1);
      out.inner_comments.emplace_back(t.substr(semicolon + 1, comment_end - semicolon - 1));
      out.content += t.substr(0, semicolon);
    } else if (continued) {
      out.content += t.substr(0, end_without_continuation(t.substr(0, end)));
    } else {
      out.content += t;
    }
    if (continued && li + 1 >= lines.size()) out.continued_past_end = true;
    if (!continued || li + 1 >= lines.size()) break;
    out.content += ' ';
    ++li;
  }
  out.upper = lexing::upper(out.content);
  return li;
}

}  // namespace detail

/// Scanning over one block's text: blanks, letter runs, keyword sequences, and words.
class scanner {
 public:
  explicit scanner(const block_text& text) : s_(text.content), up_(text.upper) {}

  std::size_t skip_spaces(std::size_t k) const { return lexing::skip_blanks(s_, k); }

  /// The upper-case letters starting at `k`.
  std::string letters(std::size_t k) const {
    std::size_t e = k;
    while (e < s_.size() && is_letter(s_[e])) ++e;
    return up_.substr(k, e - k);
  }

  /// Matches upper-case words separated by blanks at `k`; the position after them, if they match.
  std::optional<std::size_t> keywords(std::size_t k, std::initializer_list<std::string_view> ws) const {
    for (std::string_view w : ws) {
      k = skip_spaces(k);
      if (letters(k) != w) return std::nullopt;
      k += w.size();
    }
    return k;
  }

  /// The end of the blank-free, `;`-free run starting at `k`.
  std::size_t run_end(std::size_t k) const {
    while (k < s_.size() && !is_space(s_[k]) && s_[k] != ';') ++k;
    return k;
  }

  /// Whether an axis word (`X+1`, `IX5`, `X=…`) follows `k` before any `;`.
  bool has_axis_word(std::size_t k) const {
    for (; k < s_.size() && s_[k] != ';'; ++k) {
      if (!is_letter(s_[k]) || (k > 0 && is_letter(s_[k - 1]))) continue;
      const std::string run = letters(k);
      std::string w = run;
      if (w.size() == 2 && w[0] == 'I') w.erase(0, 1);
      const std::size_t after = k + run.size();
      if (w.size() == 1 && detail::is_axis_letter(w[0]) &&
          (detail::starts_number(up_, after) || (after < s_.size() && s_[after] == '=')))
        return true;
    }
    return false;
  }

  /// The words from `k` to the end or to `;` (whose text, after it, goes to `comment`). Bytes
  /// that start no word go to `stray` (control bytes are the reader's: reported already).
  std::vector<word> words(std::size_t k, std::optional<std::string>& comment, std::vector<std::size_t>& stray) const {
    std::vector<word> ws;
    for (;;) {
      k = skip_spaces(k);
      if (k >= s_.size()) break;
      if (s_[k] == ';') {
        comment = s_.substr(k + 1);
        break;
      }
      word w;
      w.pos = k;
      if (is_letter(s_[k])) {
        k = lettered(w, k);
      } else if (detail::starts_number(s_, k)) {
        k = bare_number(w, k);
      } else {
        stray.push_back(k);
        ++k;
        while (k < s_.size() && !is_space(s_[k]) && s_[k] != ';' && !is_letter(s_[k])) ++k;
        continue;
      }
      for (std::size_t e = w.pos; e < k; ++e)
        if (!is_space(s_[e])) w.written += to_upper(s_[e]);
      ws.push_back(std::move(w));
    }
    return ws;
  }

 private:
  const std::string& s_;
  const std::string& up_;

  /// A parameter reference `Q12`, `+QL12`, `-QR12` at `v` that ends the word: its end (0 if none).
  std::size_t parameter_at(word& w, std::size_t v) const {
    std::size_t q = v;
    const bool negated = q < s_.size() && s_[q] == '-';
    if (q < s_.size() && (s_[q] == '+' || s_[q] == '-')) ++q;
    if (q >= s_.size() || to_upper(s_[q]) != 'Q') return 0;
    std::string prefix = "Q";
    std::size_t d = q + 1;
    if (d < s_.size() && (to_upper(s_[d]) == 'L' || to_upper(s_[d]) == 'R')) prefix += to_upper(s_[d++]);
    std::size_t e = d;
    while (e < s_.size() && is_digit(s_[e])) ++e;
    if (e == d || e - d > 4 || (e < s_.size() && !is_space(s_[e]) && s_[e] != ';')) return 0;
    long n = 0;
    for (std::size_t k = d; k < e; ++k) n = n * 10 + (s_[k] - '0');
    w.parameter = interp::parameter_key{std::move(prefix), n};
    w.parameter_negated = negated;
    return e;
  }

  /// Whether the value at `v` of an axis word is an expression: `=`, `(`, `Q…`, `+Q…`, `-(`.
  bool expression_at(std::size_t v) const {
    if (v >= s_.size()) return false;
    const char c = s_[v];
    return c == '=' || c == '(' || to_upper(c) == 'Q' ||
           ((c == '+' || c == '-') && v + 1 < s_.size() && (to_upper(s_[v + 1]) == 'Q' || s_[v + 1] == '('));
  }

  /// A word starting with letters at `k`; returns the position after it.
  std::size_t lettered(word& w, std::size_t k) const {
    w.key = letters(k);
    if (w.key.size() >= 2 && (detail::is_axis_letter(w.key[0]) || w.key[0] == 'F') && w.key[1] == 'Q')
      w.key.resize(1);  // `XQ1`, `FQ1`: the letter, then a parameter
    k += w.key.size();
    const std::size_t v = skip_spaces(k);
    if (w.key == "F" && letters(v) == "MAX") {  // `F MAX`, hyperMILL's spelling of FMAX
      w.key = "FMAX";
      return v + 3;
    }
    if ((w.key == "F" || (w.key.size() == 1 && detail::is_axis_letter(w.key[0]))))
      if (const std::size_t e = parameter_at(w, v)) return e;
    if (!w.expression && expression_at(v)) w.expression = detail::is_axis_letter(w.key.back());
    if (w.expression) return run_end(k);
    if (detail::starts_number(s_, v)) return valued(w, v);
    if (v < s_.size() && (s_[v] == '+' || s_[v] == '-')) {
      w.sign = s_[v];
      k = v + 1;
      const std::size_t d = skip_spaces(k);
      if (d > k && detail::starts_number(s_, d)) {  // `X+ 5`: a sign must touch its digits
        w.sign = 0;
        w.error = number_error::not_a_number;
        k = d + std::max<std::size_t>(read_number(std::string_view(s_).substr(d)).length, 1);
      }
    }
    return k;
  }

  /// The number at `v` after a word's letters; returns the position after it.
  std::size_t valued(word& w, std::size_t v) const {
    const parsed_number n = read_number(std::string_view(s_).substr(v));
    if (n.error != number_error::none) {
      w.error = n.error;
      return run_end(v);
    }
    if (v + n.length < s_.size() && s_[v + n.length] == '.') {  // `X+1.2.3`
      std::size_t k = v + n.length;
      while (k < s_.size() && (is_digit(s_[k]) || s_[k] == '.')) ++k;
      w.malformed = s_.substr(v, k - v);
      w.error = number_error::not_a_number;
      return k;
    }
    w.value = n.value;
    return v + n.length;
  }

  /// A number with no letters before it at `k`; returns the position after it.
  std::size_t bare_number(word& w, std::size_t k) const {
    const parsed_number n = read_number(std::string_view(s_).substr(k));
    if (n.error != number_error::none) {
      w.error = n.error;
      return run_end(k);
    }
    w.value = n.value;
    return k + n.length;
  }
};

}  // namespace kin5::program::heidenhain
