/// @file program/heidenhain.hpp
/// Heidenhain conversational (Klartext) programs: `read` into the block model, `write` back.
///
/// Read: `15 L X+34.983 Y+118.526 Z+9.1 B+17.067 C+87.479 R0 F1137 M128` (L, LN, C, CC, CR),
/// `TOOL CALL 5 Z S6000`, M lines, `BEGIN PGM`/`END PGM … MM`, `;` and `*` comments,
/// `FUNCTION TCPM`/`FUNCTION RESET TCPM`, `~` continuation lines. `BLK FORM`, cycles and other
/// lines without axis words pass through. Rejected: Q parameters in axis words, incremental `IX`…,
/// INCH programs, active frame changes (`PLANE SPATIAL`…, `CYCL DEF 7/8/10/11/19/26`, `TRANS`).
/// Block numbers are kept in `block::number` as written (repeated or missing is fine).
///
/// Write: one line per block (a `TOOL CALL` or `CC` line first when another dialect's block needs
/// one), numbered 0, 1, 2, … as the control requires; source block numbers are not written.
/// A block without coordinates is never an `L` (the control's L needs its end point): a
/// feed-only block's F goes to the next move without an F, a rapid-only block's FMAX to the next
/// move; a block left with nothing Heidenhain can say (APT `UNITS/MM`, `RAPID`, a read `L F800`)
/// becomes a comment carrying its source text. Round trip: `read(write(p))` equals `p` except
/// `where`, `text` and `number`, for programs whose L blocks all have coordinates.
/// The full description, with examples, is docs/dialects/heidenhain.md.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "block.hpp"
#include "number.hpp"
#include "text.hpp"

namespace kin5::program::heidenhain {

/// Decimals written for each kind of number.
struct write_options {
  int linear_decimals = 3;  ///< X Y Z, CC, CR radius (mm)
  int angle_decimals = 3;   ///< A B C (degrees)
  int feed_decimals = 1;    ///< F (mm/min) and S (1/min)
  int vector_decimals = 7;  ///< TX TY TZ
};

namespace detail {

inline std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = to_upper(c);
  return u;
}

inline bool is_axis_letter(char c) {
  return c == 'X' || c == 'Y' || c == 'Z' || c == 'A' || c == 'B' || c == 'C';
}

inline bool starts_number(std::string_view s, std::size_t i) {
  if (i >= s.size()) return false;
  if (is_digit(s[i]) || s[i] == '.') return true;
  return (s[i] == '+' || s[i] == '-') && i + 1 < s.size() && (is_digit(s[i + 1]) || s[i + 1] == '.');
}

inline std::string hex_byte(unsigned char c) {
  const char* digits = "0123456789ABCDEF";
  return std::string("0x") + digits[c >> 4] + digits[c & 15];
}

/// A control byte: not allowed outside comments.
inline bool is_control(unsigned char c) { return (c < 0x20 && !is_space(static_cast<char>(c))) || c == 0x7F; }

/// The text of one block (physical lines joined at `~`), with the way back to line and column.
struct block_text {
  std::string content;  ///< the lines joined with a space, `~` removed
  struct piece {
    std::size_t offset, line, column;  ///< content offset ↔ 1-based line and column of that byte
  };
  std::vector<piece> pieces;

  std::pair<std::size_t, std::size_t> locate(std::size_t pos) const {
    const piece* p = &pieces.front();
    for (const piece& q : pieces)
      if (q.offset <= pos) p = &q;
    return {p->line, p->column + (pos - p->offset)};
  }
};

/// One word of a motion, M or TOOL CALL line: address letters, then a value or a lone sign.
struct word {
  std::string key;                ///< upper-case letters; empty for a bare number
  std::optional<double> value;    ///< the number after the letters
  char sign = 0;                  ///< `+` or `-` written with no digits (`DR+`)
  std::string written;            ///< the whole word, upper case, spaces removed
  std::size_t pos = 0;            ///< content offset of its first byte
  bool bad = false;               ///< already reported
  bool expression = false;        ///< `X+Q1`, `XQ1`, `X=…`
  number_error error = number_error::none;
  std::string malformed;          ///< a number with a second point (`+1.2.3`), as written
};

inline std::string fmt_signed(double v, int decimals) {
  std::string s = format_number(v, decimals);
  return s.front() == '-' ? s : "+" + s;
}

}  // namespace detail

/// Reads a Heidenhain conversational program block by block: `on_block` receives each block in
/// file order as soon as it is read; errors and warnings go to `out` (its `parsed` is not
/// touched).
inline void read_blocks(std::string_view text, const std::string& file_path, read_result& out,
                        const block_sink& on_block) {
  using namespace detail;
  const file_name file(file_path);  // one string for every location in the file

  // Modal state the reader needs: last position (CC's missing axes), working plane, last CC.
  std::optional<double> last[3];
  arc_plane plane = arc_plane::xy;
  std::optional<vec3> centre;
  std::optional<std::string> begin_name;

  const std::vector<text_line> lines = split_lines(text);
  for (std::size_t li = 0; li < lines.size(); ++li) {
    auto blank = [](std::string_view s) { return std::all_of(s.begin(), s.end(), [](char c) { return is_space(c); }); };
    if (blank(lines[li].text)) continue;

    // Join `~` continuation lines into one block.
    block_text src;
    std::string raw;
    std::size_t first = li;
    for (;;) {
      std::string_view t = lines[li].text;
      std::size_t end = t.size();
      while (end > 0 && is_space(t[end - 1])) --end;
      const bool continued = end > 0 && t[end - 1] == '~' && t.find(';') == std::string_view::npos;
      if (li != first) raw += '\n';
      raw += t;
      src.pieces.push_back({src.content.size(), lines[li].number, 1});
      src.content += continued ? t.substr(0, end - 1) : t;
      if (!continued || li + 1 >= lines.size()) break;
      src.content += ' ';
      ++li;
    }
    const std::string& s = src.content;
    const std::string up = upper(s);

    block b;
    b.text = raw;
    std::size_t i = 0;
    while (i < s.size() && is_space(s[i])) ++i;
    {
      auto [l, c] = src.locate(i);
      b.where = {file, l, c};
    }
    auto where = [&](std::size_t pos) {
      auto [l, c] = src.locate(pos);
      return source_location{file, l, c};
    };
    auto error = [&](std::size_t pos, std::string message) { out.errors.push_back({where(pos), std::move(message)}); };
    auto warning = [&](std::size_t pos, std::string message) { out.warnings.push_back({where(pos), std::move(message)}); };

    // Control bytes outside comments, one diagnostic each.
    const bool section = [&] {
      std::size_t k = i;
      while (k < s.size() && is_digit(s[k])) ++k;
      while (k < s.size() && is_space(s[k])) ++k;
      return k < s.size() && s[k] == '*';
    }();
    if (!section) {
      for (std::size_t k = 0; k < s.size() && s[k] != ';'; ++k)
        if (is_control(static_cast<unsigned char>(s[k]))) error(k, "unexpected byte " + hex_byte(static_cast<unsigned char>(s[k])));
    }

    // Block number.
    if (i < s.size() && is_digit(s[i])) {
      std::size_t k = i;
      while (k < s.size() && is_digit(s[k])) ++k;
      long long n = 0;
      const auto r = std::from_chars(s.data() + i, s.data() + k, n);
      if (r.ec != std::errc{}) error(i, "block number out of range");
      else b.number = n;
      i = k;
      while (i < s.size() && is_space(s[i])) ++i;
    }

    auto skip_spaces = [&](std::size_t k) {
      while (k < s.size() && is_space(s[k])) ++k;
      return k;
    };
    auto letters = [&](std::size_t k) {
      std::size_t e = k;
      while (e < s.size() && is_letter(s[e])) ++e;
      return up.substr(k, e - k);
    };
    // Matches upper-case words separated by spaces at `k`; returns the position after them.
    auto keywords = [&](std::size_t k, std::initializer_list<std::string_view> ws) -> std::optional<std::size_t> {
      for (std::string_view w : ws) {
        k = skip_spaces(k);
        if (letters(k) != w) return std::nullopt;
        k += w.size();
      }
      return k;
    };
    auto has_axis_word = [&](std::size_t k) {
      for (; k < s.size() && s[k] != ';'; ++k) {
        if (!is_letter(s[k]) || (k > 0 && is_letter(s[k - 1]))) continue;
        std::string w = letters(k);
        if (w.size() == 2 && w[0] == 'I') w.erase(0, 1);
        if (w.size() == 1 && is_axis_letter(w[0]) &&
            (starts_number(up, k + letters(k).size()) ||
             (k + letters(k).size() < s.size() && s[k + letters(k).size()] == '=')))
          return true;
      }
      return false;
    };
    auto passthrough = [&] { b.passthrough = true; };
    std::vector<diagnostic> stray;  // bytes that start no word: errors unless the block passes through

    // Splits the rest of the line into words; reports bytes that start no word. Stops at `;`.
    auto lex = [&](std::size_t k) {
      std::vector<word> ws;
      for (;;) {
        k = skip_spaces(k);
        if (k >= s.size()) break;
        if (s[k] == ';') {
          b.comment = s.substr(k + 1);
          break;
        }
        word w;
        w.pos = k;
        if (is_letter(s[k])) {
          w.key = letters(k);
          k += w.key.size();
          if (w.key.size() >= 2 && is_axis_letter(w.key[0]) && w.key[1] == 'Q') w.expression = true;
          std::size_t v = skip_spaces(k);
          if (!w.expression && v < s.size() && (s[v] == '=' || s[v] == '(' ||
                                                ((s[v] == '+' || s[v] == '-') && v + 1 < s.size() &&
                                                 (to_upper(s[v + 1]) == 'Q' || s[v + 1] == '(')) ||
                                                to_upper(s[v]) == 'Q'))
            w.expression = is_axis_letter(w.key.back());
          if (w.expression) {
            while (k < s.size() && !is_space(s[k]) && s[k] != ';') ++k;
          } else if (starts_number(s, v)) {
            const parsed_number n = read_number(std::string_view(s).substr(v));
            if (n.error != number_error::none) {
              w.error = n.error;
              k = v;
              while (k < s.size() && !is_space(s[k]) && s[k] != ';') ++k;
            } else if (v + n.length < s.size() && s[v + n.length] == '.') {  // `X+1.2.3`
              k = v + n.length;
              while (k < s.size() && (is_digit(s[k]) || s[k] == '.')) ++k;
              w.malformed = s.substr(v, k - v);
              w.error = number_error::not_a_number;
            } else {
              w.value = n.value;
              k = v + n.length;
            }
          } else if (v < s.size() && (s[v] == '+' || s[v] == '-')) {
            w.sign = s[v];
            k = v + 1;
            const std::size_t d = skip_spaces(k);
            if (d > k && starts_number(s, d)) {  // `X+ 5`: a sign must touch its digits
              w.sign = 0;
              w.error = number_error::not_a_number;
              k = d + std::max<std::size_t>(read_number(std::string_view(s).substr(d)).length, 1);
            }
          }
        } else if (starts_number(s, k)) {
          const parsed_number n = read_number(std::string_view(s).substr(k));
          if (n.error != number_error::none) {
            w.error = n.error;
            while (k < s.size() && !is_space(s[k]) && s[k] != ';') ++k;
          } else {
            w.value = n.value;
            k += n.length;
          }
        } else {
          const unsigned char c = static_cast<unsigned char>(s[k]);
          if (!is_control(c))  // control bytes were reported above
            stray.push_back({where(k), c >= 0x80 ? "unexpected byte " + hex_byte(c)
                                                 : std::string("unexpected character '") + s[k] + "'"});
          ++k;
          while (k < s.size() && !is_space(s[k]) && s[k] != ';' && !is_letter(s[k])) ++k;
          continue;
        }
        for (std::size_t e = w.pos; e < k; ++e)
          if (!is_space(s[e])) w.written += to_upper(s[e]);
        ws.push_back(std::move(w));
      }
      return ws;
    };
    // Reports a word's number problem; true when the word is usable.
    auto value_ok = [&](word& w) {
      if (w.bad) return false;
      if (w.expression) {
        error(w.pos, "expressions and parameters in axis words are not supported");
      } else if (w.error == number_error::too_large) {
        error(w.pos, "value out of range");
      } else if (!w.malformed.empty()) {
        error(w.pos, "malformed number '" + w.malformed + "'");
      } else if (w.error != number_error::none) {
        error(w.pos, "word '" + w.key + "' has a malformed value");
      } else if (!w.value) {
        error(w.pos, "word '" + w.key + "' has no value");
      } else {
        return true;
      }
      w.bad = true;
      return false;
    };
    auto integer_word = [&](word& w, long long& n) {
      if (!value_ok(w)) return false;
      if (*w.value != static_cast<double>(static_cast<long long>(*w.value)) || *w.value < 0) {
        error(w.pos, "word '" + w.key + "' needs a whole number");
        return false;
      }
      n = static_cast<long long>(*w.value);
      return true;
    };
    auto set_m = [](block& t, long long m) {
      if (m == 128) t.tcp = true;
      else if (m == 129) t.tcp = false;
      else {
        if (m == 91 || m == 92) t.machine_coordinates = true;
        t.m_codes.push_back(static_cast<int>(m));
      }
    };

    const std::string head = letters(i);
    if (i >= s.size()) {
      // a block number alone
    } else if (s[i] == ';') {
      b.comment = s.substr(i + 1);
    } else if (s[i] == '*') {
      b.comment = s.substr(i + 1);
    } else if (auto bp = keywords(i, {"BEGIN", "PGM"}); bp || keywords(i, {"END", "PGM"})) {
      const bool begin = bp.has_value();
      std::size_t p = *(begin ? bp : keywords(i, {"END", "PGM"}));
      p = skip_spaces(p);
      std::size_t e = p;
      while (e < s.size() && !is_space(s[e]) && s[e] != ';') ++e;
      const std::string name = s.substr(p, e - p);
      const std::size_t u = skip_spaces(e);
      std::size_t ue = u;
      while (ue < s.size() && !is_space(s[ue]) && s[ue] != ';') ++ue;
      const std::string unit = up.substr(u, ue - u);
      if (name.empty() || unit.empty()) {
        error(i, std::string(begin ? "BEGIN" : "END") + " PGM needs a name and a unit");
      } else if (unit == "INCH") {
        error(u, "inch programs are not supported");
        b.metric = false;
      } else if (unit != "MM") {
        error(u, "unknown unit '" + s.substr(u, ue - u) + "'");
      } else {
        b.metric = true;
      }
      if (!name.empty()) {
        if (begin) {
          b.program_begin = name;
          begin_name = name;
        } else {
          b.program_end = name;
          if (begin_name && *begin_name != name)
            warning(p, "END PGM name '" + name + "' differs from BEGIN PGM '" + *begin_name + "'");
        }
      }
      const std::size_t c = skip_spaces(ue);
      if (c < s.size() && s[c] == ';') b.comment = s.substr(c + 1);
    } else if (auto tc = keywords(i, {"TOOL", "CALL"})) {
      std::vector<word> ws = lex(*tc);
      bool understood = !ws.empty();
      block t = b;
      for (word& w : ws) {
        if (w.key.empty() && w.value && !t.tool && !t.spindle_rpm && t.kept_words.empty()) {
          long long n = 0;
          if (!integer_word(w, n)) understood = false;
          t.tool = n;
        } else if (w.key.size() == 1 && (w.key == "X" || w.key == "Y" || w.key == "Z") && !w.value && !w.sign &&
                   !w.expression && w.error == number_error::none) {
          t.kept_words.push_back(w.key);
        } else if (w.key == "S" && w.value && !t.spindle_rpm) {
          t.spindle_rpm = *w.value;
        } else if (w.key == "F" && w.value && !t.feed) {
          t.feed = *w.value;
        } else if ((w.key == "DL" || w.key == "DR" || w.key == "DR2") && w.value) {
          t.kept_words.push_back(w.written);
        } else {
          understood = false;
        }
      }
      if (understood && (t.tool || t.spindle_rpm)) {
        b = std::move(t);
        for (const std::string& w : b.kept_words)  // the tool axis sets the working plane
          if (w == "X" || w == "Y" || w == "Z") plane = w == "Z" ? arc_plane::xy : w == "Y" ? arc_plane::zx : arc_plane::yz;
      } else {
        b.comment.reset();
        passthrough();
      }
    } else if (head == "L" || head == "LN" || head == "C" || head == "CC" || head == "CR") {
      std::vector<word> ws = lex(i + head.size());
      const bool arc = head == "C" || head == "CR";
      if (head != "CC") b.motion = motion_kind::linear;
      std::optional<double> radius;
      char direction = 0;
      std::optional<double> axis[6], tool_axis[3];
      std::vector<std::size_t> axis_pos;
      for (word& w : ws) {
        const std::string& key = w.key;
        if (w.expression) {
          value_ok(w);
        } else if (key.empty()) {
          if (w.error == number_error::too_large) error(w.pos, "value out of range");
          else error(w.pos, "number without an address letter");
        } else if (key.size() == 1 && is_axis_letter(key[0])) {
          if (!value_ok(w)) continue;
          const std::size_t a = static_cast<std::size_t>(std::string_view("XYZABC").find(key[0]));
          if (axis[a]) {
            error(w.pos, "axis '" + key + "' given twice");
            continue;
          }
          axis[a] = *w.value;
        } else if (key.size() == 2 && key[0] == 'I' && is_axis_letter(key[1])) {
          error(w.pos, "incremental positioning (" + key + ") is not supported");
        } else if (head == "LN" && key.size() == 2 && key[0] == 'T' && (key[1] == 'X' || key[1] == 'Y' || key[1] == 'Z')) {
          if (!value_ok(w)) continue;
          const std::size_t a = static_cast<std::size_t>(key[1] - 'X');
          if (tool_axis[a]) error(w.pos, "word '" + key + "' given twice");
          else tool_axis[a] = *w.value;
        } else if (head == "LN" && key.size() == 2 && key[0] == 'N' && (key[1] == 'X' || key[1] == 'Y' || key[1] == 'Z')) {
          if (value_ok(w)) b.kept_words.push_back(w.written);
        } else if (head == "CC") {
          error(w.pos, "unknown word '" + w.written + "'");
        } else if (key == "R" && head == "CR" && !radius && !w.sign) {
          if (value_ok(w)) radius = *w.value;
        } else if (key == "R" && w.value && *w.value == 0 && w.error == number_error::none) {
          b.kept_words.push_back("R0");
        } else if ((key == "RL" || key == "RR") && !w.value && !w.sign && w.error == number_error::none) {
          b.kept_words.push_back(key);
        } else if (key == "DR" && arc && w.sign && !direction) {
          direction = w.sign;
        } else if (key == "F") {
          if (value_ok(w)) b.feed = *w.value;
        } else if (key == "FMAX" && !w.value && !w.sign) {
          b.feed_rapid = true;
          b.motion = arc ? b.motion : motion_kind::rapid;
        } else if (key == "FAUTO" && !w.value && !w.sign) {
          b.kept_words.push_back(key);
        } else if (key == "M") {
          long long m = 0;
          if (integer_word(w, m)) set_m(b, m);
        } else {
          error(w.pos, "unknown word '" + (w.written.empty() ? key : w.written) + "'");
        }
      }
      axis_words& ax = b.axes;
      if (head == "CC") {
        // Two coordinates give the plane; missing ones come from the last position.
        const int given = (axis[0] ? 1 : 0) + (axis[1] ? 1 : 0) + (axis[2] ? 1 : 0);
        if (axis[3] || axis[4] || axis[5]) error(i, "CC takes linear axes only");
        if (given == 3) error(i, "CC takes at most two coordinates");
        if (given == 2) plane = !axis[2] ? arc_plane::xy : !axis[1] ? arc_plane::zx : arc_plane::yz;
        vec3 c{};
        double* cs[3] = {&c.x, &c.y, &c.z};
        for (std::size_t a = 0; a < 3; ++a) {
          if (axis[a]) *cs[a] = *axis[a];
          else if (last[a]) *cs[a] = *last[a];
          else if (given < 3) warning(i, std::string("CC: last ") + "XYZ"[a] + " position unknown, 0 assumed");
        }
        b.arc = arc_words{plane, c, std::nullopt};
        centre = c;
      } else {
        if (axis[0]) ax.x_mm = axis[0];
        if (axis[1]) ax.y_mm = axis[1];
        if (axis[2]) ax.z_mm = axis[2];
        if (axis[3]) ax.a_deg = axis[3];
        if (axis[4]) ax.b_deg = axis[4];
        if (axis[5]) ax.c_deg = axis[5];
        if (tool_axis[0] || tool_axis[1] || tool_axis[2])
          ax.tool_axis = vec3{tool_axis[0].value_or(0.0), tool_axis[1].value_or(0.0), tool_axis[2].value_or(0.0)};
        if (arc) {
          b.motion = direction == '-' ? motion_kind::arc_cw : motion_kind::arc_ccw;
          if (!direction) error(i, "arc needs a direction (DR+ or DR-)");
          if (head == "CR") {
            if (!radius) error(i, "CR needs a radius (R)");
            b.arc = arc_words{plane, std::nullopt, radius};
          } else {
            if (!centre) error(i, "arc C needs a circle centre (CC) before it");
            b.arc = arc_words{plane, centre, std::nullopt};
          }
        }
      }
      if (b.feed && b.feed_rapid) error(i, "F and FMAX in one block");
    } else if (head == "M" && i + 1 < s.size() && (is_digit(s[i + 1]) || is_space(s[i + 1]))) {
      std::vector<word> ws = lex(i);
      block m = b;
      bool understood = true;
      for (word& w : ws) {
        long long n = 0;
        if (w.key == "M" && w.value && *w.value >= 0 && *w.value <= 9999 &&
            *w.value == static_cast<double>(static_cast<long long>(*w.value)) && integer_word(w, n)) {
          set_m(m, n);
        } else {
          understood = false;
        }
      }
      if (understood) b = std::move(m);
      else {
        for (const word& w : ws)
          if (!w.key.empty() && w.key.size() <= 2 && is_axis_letter(w.key.back()) && (w.key.size() == 1 || w.key[0] == 'I') &&
              (w.value || w.expression || w.error != number_error::none)) {
            error(w.pos, "axis word '" + w.key + "' without a motion keyword");
            break;
          }
        b.comment.reset();
        passthrough();
      }
    } else if (auto f = keywords(i, {"FUNCTION", "TCPM"})) {
      b.tcp = true;
      std::vector<std::string> tokens;
      std::vector<std::size_t> at;
      std::size_t k = *f;
      for (;;) {
        k = skip_spaces(k);
        if (k >= s.size()) break;
        if (s[k] == ';') {
          b.comment = s.substr(k + 1);
          break;
        }
        std::size_t e = k;
        while (e < s.size() && !is_space(s[e]) && s[e] != ';') ++e;
        tokens.push_back(up.substr(k, e - k));
        at.push_back(k);
        k = e;
      }
      for (std::size_t t = 0; t < tokens.size(); t += 2) {
        std::string kw = tokens[t] + (t + 1 < tokens.size() ? " " + tokens[t + 1] : "");
        if (kw == "AXIS SPAT") error(at[t], "FUNCTION TCPM AXIS SPAT is not supported");
        b.kept_words.push_back(std::move(kw));
      }
    } else if (keywords(i, {"FUNCTION", "RESET", "TCPM"})) {
      b.tcp = false;
      const std::size_t c = skip_spaces(*keywords(i, {"FUNCTION", "RESET", "TCPM"}));
      if (c < s.size() && s[c] == ';') b.comment = s.substr(c + 1);
      else if (c < s.size()) passthrough(), b.tcp.reset();
    } else if (head == "PLANE") {
      const std::size_t k = skip_spaces(i + head.size());
      const std::string kind = letters(k);
      if (kind != "RESET") error(i, "PLANE " + kind + " changes the working frame; kin5 does not model frame changes");
      passthrough();
    } else if (auto cy = keywords(i, {"CYCL", "DEF"})) {
      std::size_t k = skip_spaces(*cy);
      std::size_t e = k;
      while (e < s.size() && is_digit(s[e])) ++e;
      const std::string number = s.substr(k, e - k);
      std::string part;
      if (e < s.size() && s[e] == '.') {
        std::size_t p = e + 1;
        while (p < s.size() && is_digit(s[p])) ++p;
        part = s.substr(e + 1, p - e - 1);
        e = p;
      }
      passthrough();
      const bool frame = number == "7" || number == "8" || number == "10" || number == "11" || number == "19" ||
                         number == "26";
      if (number == "247") warning(i, "CYCL DEF 247 selects a datum preset; passed through unchanged");
      if (frame && !part.empty() && part != "0") {
        // Values of the cycle: active unless all are the identity (0, or scale 1).
        const double identity = (number == "11" || number == "26") ? 1.0 : 0.0;
        bool active = false;
        std::size_t p = e;
        while (p < s.size() && s[p] != ';') {
          if (is_letter(s[p]) && (p == 0 || !is_letter(s[p - 1]))) {
            const std::string key = letters(p);
            std::size_t v = p + key.size();
            if (key == "F" || key == "ABST" || key == "DATUM" || key == "SHIFT" || key == "WORKING" ||
                key == "PLANE" || key == "ROTATION" || key == "SCALING" || key == "IROT") {
              p = v;
              continue;
            }
            if (starts_number(s, v)) {
              const parsed_number n = read_number(std::string_view(s).substr(v));
              if (n.error != number_error::none || n.value != identity) active = true;
              p = v + std::max<std::size_t>(n.length, 1);
              continue;
            }
            active = true;  // a mirrored axis, or a parameter
            p = v;
            continue;
          }
          if (s[p] == '#' || s[p] == 'Q') active = true;
          ++p;
        }
        if (active) error(i, "CYCL DEF " + number + " changes the working frame; kin5 does not model frame changes");
      }
    } else if (head == "TRANS") {
      const std::size_t k = skip_spaces(i + head.size());
      const std::string kind = letters(k);
      const std::size_t r = skip_spaces(k + kind.size());
      if (letters(r) != "RESET")
        error(i, "TRANS " + kind + " changes the working frame; kin5 does not model frame changes");
      passthrough();
    } else if (head == "BLK") {
      passthrough();
    } else if (head == "CT" || head == "CP" || head == "LP" || head == "CTP" || head == "RND" || head == "CHF" ||
               head == "APPR" || head == "DEP" || head == "FL" || head == "FLT" || head == "FC" || head == "FCT" ||
               head == "FPOL" || head == "CCA") {
      error(i, "'" + head + "' is not supported");
    } else if (head.size() == 1 && is_axis_letter(head[0]) && has_axis_word(i)) {
      error(i, "axis word '" + head + "' without a motion keyword");
    } else if (head.size() == 2 && head[0] == 'I' && is_axis_letter(head[1]) && has_axis_word(i)) {
      error(i, "incremental positioning (" + head + ") is not supported");
    } else if (has_axis_word(i)) {
      std::size_t e = i;
      while (e < s.size() && !is_space(s[e]) && s[e] != ';') ++e;
      error(i, "unknown keyword '" + up.substr(i, e - i) + "' in a block with axis words");
      passthrough();
    } else {
      passthrough();
    }

    if (!b.passthrough) {
      out.errors.insert(out.errors.end(), stray.begin(), stray.end());
      if (b.axes.x_mm) last[0] = b.axes.x_mm;
      if (b.axes.y_mm) last[1] = b.axes.y_mm;
      if (b.axes.z_mm) last[2] = b.axes.z_mm;
    }
    on_block(std::move(b));
  }
}

/// Reads a Heidenhain conversational program. Never throws on bad input: problems are in
/// `errors` (and `warnings`), each at the offending word's line and column.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(dialect::heidenhain, text, std::move(file_name), &read_blocks);
}

/// Writes blocks as Heidenhain conversational text one at a time, numbering them from 0 and
/// remembering the working plane, the last circle centre and the program name, so a program of
/// any length is written in constant memory. `write(program)` below is this writer applied to
/// every block.
class writer {
 public:
  /// A writer for blocks read from `source` (another dialect's passthrough text and kept words
  /// go into comments); `file` names the program in messages for blocks without a location.
  explicit writer(dialect source, std::string file = {}, const write_options& chosen = {})
      : same(source == dialect::heidenhain), program_file(std::move(file)), options(chosen) {}

  /// Appends the lines of block `b` to `out`. Throws `std::invalid_argument` naming the block
  /// (`file:line`) when it cannot be written in Heidenhain.
  void write(std::string& out, const block& b) {
    using namespace detail;
    const std::size_t bi = index++;
    auto fail = [&](const std::string& what) {
      const std::string at = b.where.line ? b.where.file + ":" + std::to_string(b.where.line)
                                          : (program_file.empty() ? "block " : program_file + ": block ") +
                                                std::to_string(bi);
      throw std::invalid_argument(at + ": block cannot be written in heidenhain: " + what);
    };
    // The block's lines, in strings reused from block to block so that their capacity stays.
    std::size_t line_count = 0;
    auto add = [&](std::string_view text) {
      if (line_count == lines_.size()) lines_.emplace_back();
      lines_[line_count++].assign(text);
    };

    if (b.passthrough) {
      std::string body = b.text;
      if (same) {
        std::size_t k = 0;
        while (k < body.size() && is_space(body[k])) ++k;
        std::size_t d = k;
        while (d < body.size() && is_digit(body[d])) ++d;
        if (d > k) {
          while (d < body.size() && is_space(body[d])) ++d;
          k = d;
        }
        body.erase(0, k);
      } else {
        std::replace(body.begin(), body.end(), '\n', ' ');
        std::replace(body.begin(), body.end(), '\r', ' ');
        body = ";" + body;
      }
      out += std::to_string(number++) + " " + body + "\n";
      return;
    }

    if (b.metric && !*b.metric) fail("inch units");
    if (b.feed_mode == feed_unit::inverse_time) fail("inverse-time feed (G93)");
    auto pgm_name = [&](const std::optional<std::string>& n) {
      // `program_end` of a G-code dialect may hold its end word, which is no name
      const bool named = n && !n->empty() && *n != "M2" && *n != "M30";
      std::string name = named ? *n : begin_name.value_or("");
      if (name.empty()) name = "PGM";
      for (char& c : name)  // a name is one word: blanks and `;` become `_`
        if (is_space(c) || c == ';' || is_control(static_cast<unsigned char>(c))) c = '_';
      return name;
    };
    if (b.program_begin) {
      begin_name = pgm_name(b.program_begin);
      add("BEGIN PGM " + *begin_name + " MM");
    }

    // An L needs end-point coordinates: a feed-only or rapid-only block (APT `FEDRAT/…`, `RAPID`;
    // a lone G0 or F; a read `L F800`) is not written as `L F…` / `L FMAX`. Its F, modal here
    // too, goes to the next move without one; its rapid to the next move as FMAX.
    const bool coordless = b.axes.empty() && !b.arc;
    const bool dropped_move = coordless && (b.motion || b.feed_rapid || (b.feed && !(b.tool || b.spindle_rpm)));
    if (coordless) {
      if (b.feed && !(b.tool || b.spindle_rpm)) pending_feed = b.feed;
      if (b.motion == motion_kind::rapid || b.feed_rapid) pending_rapid = true;
      else if (b.motion || b.feed) pending_rapid = false;
    }
    const bool moves = !coordless && (b.motion || !b.axes.empty() || b.feed_rapid || (b.feed && !(b.tool || b.spindle_rpm)));
    std::vector<std::string> kept = b.kept_words;  // written verbatim (same dialect) or into the comment
    std::vector<std::string> foreign;
    if (!same) foreign.swap(kept);

    if (b.tool || b.spindle_rpm) {
      std::string l = "TOOL CALL";
      if (b.tool) {
        if (*b.tool < 0) fail("tool number " + std::to_string(*b.tool) + " cannot be written");
        l += " " + std::to_string(*b.tool);
      }
      if (!moves) {
        for (const std::string& w : kept) {
          l += " " + w;
          if (w == "Z") plane = arc_plane::xy;
          if (w == "Y") plane = arc_plane::zx;
          if (w == "X") plane = arc_plane::yz;
        }
        kept.clear();
      }
      if (b.spindle_rpm) l += " S" + format_number(*b.spindle_rpm, options.feed_decimals);
      if (b.feed && !moves) l += " F" + format_number(*b.feed, options.feed_decimals);
      add(l);
    }

    // Appends ` X+1.5` to a line.
    auto put = [](std::string& l, std::string_view letters, double v, int decimals) {
      l += ' ';
      l.append(letters.data(), letters.size());
      append_number(l, v, decimals, true);
    };
    auto coord = [&](std::string_view letters, double v, int decimals) {
      std::string w;
      put(w, letters, v, decimals);
      return w;
    };
    auto cc_line = [&](const arc_words& a) {
      const vec3& c = *a.centre_mm;
      std::string l = "CC";
      if (a.plane != arc_plane::yz) l += coord("X", c.x, options.linear_decimals);
      if (a.plane != arc_plane::zx) l += coord("Y", c.y, options.linear_decimals);
      if (a.plane != arc_plane::xy) l += coord("Z", c.z, options.linear_decimals);
      plane = a.plane;
      centre = c;
      return l;
    };

    std::string m_words;
    for (int m : b.m_codes)
      if (!(m == 6 && b.tool && !same)) m_words += " M" + std::to_string(m);  // TOOL CALL is the change: no M6 twice
    if (b.machine_coordinates &&
        std::find_if(b.m_codes.begin(), b.m_codes.end(), [](int m) { return m == 91 || m == 92; }) == b.m_codes.end())
      m_words += " M91";
    if (b.tcp) m_words += *b.tcp ? " M128" : " M129";

    const bool arc = b.motion == motion_kind::arc_cw || b.motion == motion_kind::arc_ccw;
    if (b.arc && b.arc->centre_mm && !b.motion && b.axes.empty()) {
      add(cc_line(*b.arc));
    } else if (moves) {
      std::string& l = line_;
      l.clear();
      if (arc) {
        if (!b.arc || (!b.arc->centre_mm && !b.arc->radius_mm)) fail("arc has neither a centre nor a radius");
        if (b.axes.tool_axis) fail("an arc cannot carry a tool-axis vector");
        if (b.arc->radius_mm) {
          if (b.arc->plane != plane) fail("radius arc outside the working plane");
          l = "CR";
        } else {
          if (!centre || !(*centre == *b.arc->centre_mm) || plane != b.arc->plane) add(cc_line(*b.arc));
          l = "C";
        }
      } else {
        const bool normal = std::any_of(kept.begin(), kept.end(), [](const std::string& w) { return !w.empty() && to_upper(w[0]) == 'N'; });
        l = b.axes.tool_axis || normal ? "LN" : "L";
      }
      const axis_words& a = b.axes;
      if (a.x_mm) put(l, "X", *a.x_mm, options.linear_decimals);
      if (a.y_mm) put(l, "Y", *a.y_mm, options.linear_decimals);
      if (a.z_mm) put(l, "Z", *a.z_mm, options.linear_decimals);
      if (a.a_deg) put(l, "A", *a.a_deg, options.angle_decimals);
      if (a.b_deg) put(l, "B", *a.b_deg, options.angle_decimals);
      if (a.c_deg) put(l, "C", *a.c_deg, options.angle_decimals);
      for (const std::string& w : kept)
        if (!w.empty() && to_upper(w[0]) == 'N') l += " " + w;
      if (a.tool_axis) {
        l += coord("TX", a.tool_axis->x, options.vector_decimals);
        l += coord("TY", a.tool_axis->y, options.vector_decimals);
        l += coord("TZ", a.tool_axis->z, options.vector_decimals);
      }
      if (arc && b.arc->radius_mm) l += coord("R", *b.arc->radius_mm, options.linear_decimals);
      if (arc) l += b.motion == motion_kind::arc_cw ? " DR-" : " DR+";
      for (const std::string& w : kept)
        if (w.empty() || to_upper(w[0]) != 'N') l += " " + w;
      kept.clear();
      if (b.feed && (b.feed_rapid || b.motion == motion_kind::rapid)) fail("block has both a feed and rapid traverse");
      const bool rapid = b.feed_rapid || b.motion == motion_kind::rapid || (pending_rapid && !b.motion && !b.feed);
      if (b.feed) l += " F", append_number(l, *b.feed, options.feed_decimals);
      else if (rapid) l += " FMAX";
      else if (pending_feed) l += " F", append_number(l, *pending_feed, options.feed_decimals);
      if (!rapid) pending_feed.reset();
      pending_rapid = false;
      l += m_words;
      add(l);
    } else if (b.tcp && *b.tcp && same && !kept.empty() && b.m_codes.empty() && !b.machine_coordinates) {
      std::string l = "FUNCTION TCPM";
      for (const std::string& w : kept) l += " " + w;
      kept.clear();
      add(l);
    } else if (!m_words.empty()) {
      add(m_words.substr(1));
    }
    if (b.arc && b.arc->centre_mm && !arc && (b.motion || !b.axes.empty())) fail("circle centre on a block that is not an arc");

    if (b.program_end) add("END PGM " + pgm_name(b.program_end) + " MM");

    std::string comment = b.comment.value_or("");
    std::replace(comment.begin(), comment.end(), '\n', ' ');
    std::replace(comment.begin(), comment.end(), '\r', ' ');
    kept.insert(kept.end(), foreign.begin(), foreign.end());
    if (!kept.empty()) {
      std::string k;
      for (const std::string& w : kept) k += (k.empty() ? "" : " ") + w;
      comment += (b.comment ? " " : "") + std::string("kept: ") + k;
    }
    bool has_comment = b.comment || !kept.empty();
    // A block that says something (units, a feed mode, a move without coordinates) with nothing
    // Heidenhain can write for it — APT `UNITS/MM`, a lone `RAPID` — becomes its source text as a
    // comment; a translated program's blocks keep their source text, whatever the dialect.
    const bool unsaid = !same || dropped_move || b.metric || b.feed_mode;
    if (line_count == 0 && !has_comment && unsaid && !b.text.empty()) {
      std::size_t k = 0;  // without a Heidenhain block number
      if (same)
        while (k < b.text.size() && (is_digit(b.text[k]) || is_space(b.text[k]))) ++k;
      comment = b.text.substr(k);
      std::replace(comment.begin(), comment.end(), '\n', ' ');
      std::replace(comment.begin(), comment.end(), '\r', ' ');
      has_comment = true;
    }
    if (line_count == 0) add("");
    for (std::size_t k = 0; k < line_count; ++k) {
      char digits[24];
      out.append(digits, std::to_chars(digits, digits + sizeof digits, number++).ptr);
      if (!lines_[k].empty()) out += ' ', out += lines_[k];
      if (k + 1 == line_count && has_comment) out += " ;", out += comment;
      out += '\n';
    }
  }

 private:
  bool same;  // the blocks were read as Heidenhain
  std::string program_file;
  write_options options;
  std::size_t index = 0;  // of the next block, for messages about blocks without a location
  long long number = 0;   // the next block number written
  arc_plane plane = arc_plane::xy;
  std::optional<vec3> centre;
  std::optional<std::string> begin_name;
  // From a coordinate-less block of another dialect, for the next move that has no F of its own.
  std::optional<double> pending_feed;
  bool pending_rapid = false;
  std::vector<std::string> lines_;  // see `add`
  std::string line_;                // the motion line being built
};

/// Writes `p` as a Heidenhain conversational program, blocks numbered from 0.
/// Throws std::invalid_argument naming the block (`file:line`) when a block cannot be written.
inline std::string write(const program& p, const write_options& options = {}) {
  writer w(p.language, p.file, options);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  return out;
}

}  // namespace kin5::program::heidenhain
