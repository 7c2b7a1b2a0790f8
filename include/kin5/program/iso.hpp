/// @file program/iso.hpp
/// ISO / Fanuc G code (and LinuxCNC's dialect of it) read into, and written from, the block model.
///
/// Reading: one block per line; words with or without spaces (`G1X10Y20`, `X 10`), `( … )` and
/// `;` comments, `%` lines, `O1234` program numbers, `N` numbers. G0–G3 with `I J K` (incremental
/// centre) or `R`, G17/G18/G19, `G43.4` / `G43.5` (tool-tip tracking; under G43.5 `I J K` in
/// G0/G1 blocks are the tool-axis vector), `G49`, G93/G94, G21, `G53` / `G28` / `G30` (machine
/// coordinates), M30/M2. Errors: G91 (except in `G91 G28`/`G30` homing blocks), G95, G20,
/// active frames (G68, G68.2, G51, G52 with offsets), `#` parameters and `[ ]` expressions.
/// Harmless modal words (G40, G54, G90, G05.1 Q1, H1, D1, …) are kept as written.
/// docs/dialects/iso.md lists every word.
///
/// ```cpp
/// namespace iso = kin5::program::iso;
/// auto r = iso::read("N10 G1 X-34.983 Y9.1 Z118.5 B3.5 C-77.9 F1091\n", "part.nc");
/// if (r.ok()) std::string text = iso::write(r.parsed);  // "N10 G1 X-34.983 Y9.1 … F1091\n"
/// ```
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "block.hpp"
#include "number.hpp"
#include "text.hpp"

namespace kin5::program::iso {

/// Decimals written for each kind of number. Spindle speeds use `feed_decimals`.
struct write_options {
  int linear_decimals = 3;   ///< X Y Z, arc I J K, R (mm)
  int angle_decimals = 3;    ///< A B C (degrees)
  int feed_decimals = 1;     ///< F (mm/min or 1/min) and S (1/min)
  int vector_decimals = 7;   ///< tool-axis I J K under G43.5
};

namespace detail {

/// One address word as written: `X-450.` is letter 'X', value -450, text "X-450.".
struct word {
  char letter = 0;  ///< upper case
  double value = 0;
  std::string_view text;     ///< as written, letter to last digit
  std::string_view digits;   ///< the number as written
  std::size_t column = 0;
};

/// G code as ten times its value (G43.4 → 434), or -1 if not a multiple of 0.1.
inline int g_code(double v) {
  const double t = std::round(v * 10);
  return (std::abs(v * 10 - t) < 1e-6 && t >= 0 && t < 100000) ? static_cast<int>(t) : -1;
}

inline bool is_whole(double v) { return v >= 0 && v == std::floor(v); }

inline std::string byte_message(unsigned char u) {
  static constexpr char hex[] = "0123456789ABCDEF";
  return std::string("unexpected byte 0x") + hex[u >> 4] + hex[u & 15];
}

/// G codes kept as written: they change no geometry (times ten).
inline bool kept_g(int g) {
  switch (g) {
    case 40: case 50: case 51: case 80: case 131: case 150: case 170: case 180: case 190: case 400: case 430:
    case 500: case 501: case 540: case 541: case 550: case 560: case 570: case 580: case 590:
    case 610: case 611: case 640: case 690: case 800: case 900: case 980: case 990:
      return true;
    default:
      return false;
  }
}

class reader {
 public:
  reader(const std::string& file, read_result& result, const block_sink& on_block)
      : file_(file), result_(result), on_block_(on_block) {}

  void run(std::string_view text) {
    for_each_line(text, [&](const text_line& line) { read_line(line); });
  }

 private:
  file_name file_;  // one string for every location in the file
  read_result& result_;
  const block_sink& on_block_;
  // The reader's own record, needed to read I J K: motion mode, plane, G43.5, last point.
  std::optional<motion_kind> motion_;
  arc_plane plane_ = arc_plane::xy;
  bool vector_tcp_ = false;  // G43.5 active
  bool incremental_ = false;  // G91 from a homing block, until G90
  std::size_t incremental_line_ = 0;
  std::optional<double> last_[3];

  std::size_t line_ = 0;
  bool failed_ = false;

  void error(std::size_t column, std::string message) {
    result_.errors.push_back({{file_, line_, column}, std::move(message)});
    failed_ = true;
  }

  void read_line(const text_line& line) {
    const std::string_view s = line.text;
    std::size_t first = 0;
    while (first < s.size() && is_space(s[first])) ++first;
    if (first == s.size()) return;
    std::size_t end = s.size();
    while (end > first && is_space(s[end - 1])) --end;
    line_ = line.number;
    failed_ = false;
    block b;
    b.where = {file_, line.number, first + 1};
    b.text = std::string(s.substr(first, end - first));
    if (s[first] == '%') {
      b.passthrough = true;
      on_block_(std::move(b));
      return;
    }
    std::vector<word> words;
    lex(s, first, end, b, words);
    if (!failed_) interpret(b, words);
    on_block_(std::move(b));
  }

  void add_comment(block& b, std::string_view c) {
    while (!c.empty() && is_space(c.front())) c.remove_prefix(1);
    while (!c.empty() && is_space(c.back())) c.remove_suffix(1);
    if (b.comment && !b.comment->empty() && !c.empty()) *b.comment += ' ';
    b.comment = b.comment.value_or("") + std::string(c);
  }

  /// Splits the line into words and comments; the first problem stops the line.
  void lex(std::string_view s, std::size_t i, std::size_t end, block& b, std::vector<word>& words) {
    while (i < end && !failed_) {
      const char c = s[i];
      const auto u = static_cast<unsigned char>(c);
      if (is_space(c)) {
        ++i;
      } else if (c == '(') {
        const std::size_t close = s.find(')', i);
        if (close == std::string_view::npos || close >= end) return error(i + 1, "comment is not closed");
        add_comment(b, s.substr(i + 1, close - i - 1));
        i = close + 1;
      } else if (c == ';') {
        add_comment(b, s.substr(i + 1, end - i - 1));
        i = end;
      } else if (is_letter(c)) {
        word w;
        w.letter = to_upper(c);
        w.column = i + 1;
        std::size_t k = i + 1;
        while (k < end && is_space(s[k])) ++k;
        if (k < end && (s[k] == '#' || s[k] == '[')) {
          const bool axis = std::string_view("XYZABCIJKR").find(w.letter) != std::string_view::npos;
          return error(w.column, axis ? "expressions and parameters in axis words are not supported"
                                      : "expressions and parameters are not supported");
        }
        const parsed_number n = read_number(s.substr(k, end - k));
        if (n.error == number_error::too_large) return error(w.column, "value out of range");
        if (n.error != number_error::none) return error(w.column, std::string("word '") + w.letter + "' has no value");
        if (k + n.length < end && s[k + n.length] == '.') {  // `1.2.3`
          std::size_t e = k + n.length;
          while (e < end && (is_digit(s[e]) || s[e] == '.')) ++e;
          return error(w.column, "malformed number '" + std::string(s.substr(k, e - k)) + "'");
        }
        w.value = n.value;
        w.digits = s.substr(k, n.length);
        w.text = s.substr(i, k + n.length - i);
        i = k + n.length;
        words.push_back(w);
        if (w.letter == 'O' && words.size() == 1) {  // LinuxCNC `o100 sub`: control flow
          std::size_t j = i;
          while (j < end && is_space(s[j])) ++j;
          if (j + 1 < end && is_letter(s[j]) && is_letter(s[j + 1]))
            return error(w.column, "o-word control flow is not supported");
        }
      } else if (c == '#' || c == '[') {
        return error(i + 1, "expressions and parameters are not supported");
      } else if (is_digit(c) || c == '.' || c == '+' || c == '-') {
        return error(i + 1, "number with no address letter");
      } else if (c == '/' && words.empty()) {
        return error(i + 1, "block delete (/) is not supported");
      } else if (u < 0x20 || u >= 0x7f) {
        return error(i + 1, byte_message(u));
      } else {
        return error(i + 1, std::string("unexpected character '") + c + "'");
      }
    }
  }

  void interpret(block& b, std::vector<word>& words) {
    // A block that turns out to be passthrough must leave the reader's record as it was.
    const auto saved = std::make_tuple(motion_, plane_, vector_tcp_, incremental_, incremental_line_, last_[0], last_[1], last_[2]);
    // First pass: what kind of block this is.
    bool homing = false, g43_5 = false, uses_pq = false, g52 = false;
    const word* motion_word = nullptr;
    for (const word& w : words) {
      if (w.letter != 'G') continue;
      const int g = g_code(w.value);
      if (g == 280 || g == 300) homing = true;
      if (g == 435) g43_5 = true;
      if (g == 40 || g == 50 || g == 51 || g == 80 || g == 541) uses_pq = true;
      if (g == 520) g52 = true;
      if (g >= 0 && g <= 30 && g % 10 == 0) {
        if (motion_word) return error(w.column, "two motion words in one block");
        motion_word = &w;
      }
    }
    if (motion_word) {
      const int g = g_code(motion_word->value) / 10;
      b.motion = g == 0 ? motion_kind::rapid : g == 1 ? motion_kind::linear : g == 2 ? motion_kind::arc_cw : motion_kind::arc_ccw;
    }
    bool g52_reset = g52;
    if (g52)
      for (const word& w : words)
        if (std::string_view("XYZABC").find(w.letter) != std::string_view::npos && w.value != 0) g52_reset = false;

    std::optional<double> ijk[3];
    const word* ijk_word[3] = {};
    std::optional<double> radius;
    bool unknown_found = false, suppress = false;
    std::size_t unknown_column = 0;
    std::string unknown_text;
    auto unknown = [&](const word& w) {
      if (!unknown_found) unknown_found = true, unknown_column = w.column, unknown_text = std::string(w.text);
    };
    auto keep = [&](const word& w) { b.kept_words.emplace_back(w.text); };
    auto whole = [&](const word& w, const char* what) {
      if (!is_whole(w.value)) {
        error(w.column, std::string(what) + " must be a whole number");
        return false;
      }
      return true;
    };

    for (const word& w : words) {
      switch (w.letter) {
        case 'G': {
          const int g = g_code(w.value);
          if (g >= 0 && g <= 30 && g % 10 == 0) break;  // motion, done above
          if (g == 170 || g == 180 || g == 190) {
            plane_ = g == 170 ? arc_plane::xy : g == 180 ? arc_plane::zx : arc_plane::yz;
            keep(w);
          } else if (g == 900) {
            incremental_ = false;
            keep(w);
          } else if (kept_g(g)) {
            keep(w);
          } else if (g == 910) {
            if (!homing) error(w.column, "incremental positioning (G91) is not supported");
            else incremental_ = true, incremental_line_ = line_, keep(w);
          } else if (g == 200) {
            error(w.column, "inch programs are not supported");
          } else if (g == 210) {
            b.metric = true;
          } else if (g == 930) {
            b.feed_mode = feed_unit::inverse_time;
          } else if (g == 940) {
            b.feed_mode = feed_unit::per_minute;
          } else if (g == 950) {
            error(w.column, "feed per revolution (G95) is not supported");
          } else if (g == 434 || g == 435) {
            b.tcp = true;
            vector_tcp_ = g == 435;
          } else if (g == 490) {
            b.tcp = false;
            vector_tcp_ = false;
          } else if (g == 530 || g == 280 || g == 300) {
            b.machine_coordinates = true;
            keep(w);
          } else if (g == 520 && g52_reset) {
            keep(w);
          } else if (g == 730 || g == 740 || g == 760 || (g >= 810 && g <= 890 && g % 10 == 0)) {
            error(w.column, "canned cycle G" + std::to_string(g / 10) + " is not supported");
            suppress = true;  // its R, P, Q words are the cycle's: no further diagnostics
          } else if (g == 680 || g == 682 || g == 683 || g == 684 || g == 510 || g == 511 || g == 520) {
            const std::string name = "G" + std::to_string(g / 10) + (g % 10 ? "." + std::to_string(g % 10) : "");
            error(w.column, name + " changes the working frame; kin5 does not model frame changes");
            suppress = true;  // its I J K R P words are the frame's
          } else {
            unknown(w);
          }
          break;
        }
        case 'X': case 'Y': case 'Z': case 'A': case 'B': case 'C': {
          std::optional<double>* slot = w.letter == 'X' ? &b.axes.x_mm : w.letter == 'Y' ? &b.axes.y_mm
                                      : w.letter == 'Z' ? &b.axes.z_mm : w.letter == 'A' ? &b.axes.a_deg
                                      : w.letter == 'B' ? &b.axes.b_deg : &b.axes.c_deg;
          if (*slot) {
            error(w.column, std::string("word '") + w.letter + "' appears twice");
            break;
          }
          if (g52_reset) {
            keep(w);
            break;
          }
          *slot = w.value;
          break;
        }
        case 'I': case 'J': case 'K': {
          const int axis = w.letter - 'I';
          if (ijk[axis]) {
            error(w.column, std::string("word '") + w.letter + "' appears twice");
            break;
          }
          ijk[axis] = w.value;
          ijk_word[axis] = &w;
          break;
        }
        case 'R':
          if (radius) error(w.column, "word 'R' appears twice");
          radius = w.value;
          break;
        case 'F':
          b.feed = w.value;
          break;
        case 'S':
          b.spindle_rpm = w.value;
          break;
        case 'T':
          if (whole(w, "tool number")) b.tool = static_cast<long long>(w.value);
          break;
        case 'N':
          if (whole(w, "block number")) b.number = static_cast<long long>(w.value);
          break;
        case 'O':
          if (w.digits.empty() || w.digits.find_first_not_of("0123456789") != std::string_view::npos)
            error(w.column, "program number must be a whole number");
          else
            b.program_begin = std::string(w.digits);
          break;
        case 'M': {
          if (!is_whole(w.value) || w.value > 99999) {
            unknown(w);
            break;
          }
          const int m = static_cast<int>(w.value);
          if (m == 30 || m == 2) b.program_end = "M" + std::to_string(m);
          else b.m_codes.push_back(m);
          break;
        }
        case 'H': case 'D':
          keep(w);
          break;
        case 'P': case 'Q': case 'L':
          if (uses_pq) keep(w);
          else unknown(w);
          break;
        default:
          unknown(w);
      }
    }

    // Machine-coordinate and homing blocks: the axis words are not workpiece positions.
    if (b.machine_coordinates) {
      if (b.axes.x_mm) last_[0].reset();
      if (b.axes.y_mm) last_[1].reset();
      if (b.axes.z_mm) last_[2].reset();
    } else if (incremental_ && b.moves()) {
      // Posts write `G91 G28 Z0` to home and mean the following moves as absolute; say so once.
      result_.warnings.push_back({b.where, "G91 of line " + std::to_string(incremental_line_) +
                                               " not cancelled by G90: axis words read as absolute"});
      incremental_ = false;
    }

    // I J K and R: arc data, or the G43.5 tool-axis vector.
    if (b.motion) motion_ = b.motion;
    const bool arc = !g43_5 && !b.machine_coordinates && (motion_ == motion_kind::arc_cw || motion_ == motion_kind::arc_ccw);
    const bool any_ijk = ijk[0] || ijk[1] || ijk[2];
    if (suppress) {
    } else if (any_ijk && !arc && !(vector_tcp_ || g43_5)) {
      const word* w = ijk_word[0] ? ijk_word[0] : ijk_word[1] ? ijk_word[1] : ijk_word[2];
      error(w->column, std::string("word '") + w->letter + "' needs G2, G3 or G43.5");
    } else if (any_ijk && !arc) {
      if (!ijk[0] || !ijk[1] || !ijk[2]) {
        const word* w = ijk_word[0] ? ijk_word[0] : ijk_word[1] ? ijk_word[1] : ijk_word[2];
        error(w->column, "tool-axis vector needs I, J and K");
      } else {
        b.axes.tool_axis = vec3{*ijk[0], *ijk[1], *ijk[2]};
      }
    } else if (arc && (any_ijk || radius || b.moves())) {
      arc_words a;
      a.plane = plane_;
      const int first = plane_ == arc_plane::xy ? 0 : plane_ == arc_plane::zx ? 2 : 1;
      const int second = plane_ == arc_plane::xy ? 1 : plane_ == arc_plane::zx ? 0 : 2;
      const int normal = 3 - first - second;
      if (radius && any_ijk) {
        const word* w = ijk_word[0] ? ijk_word[0] : ijk_word[1] ? ijk_word[1] : ijk_word[2];
        error(w->column, "arc has both I J K and R");
      } else if (radius) {
        a.radius_mm = radius;
      } else if (any_ijk) {
        if (ijk[normal]) {
          error(ijk_word[normal]->column, std::string("word '") + ijk_word[normal]->letter + "' is not in the arc plane");
        } else if (!last_[0] || !last_[1] || !last_[2]) {
          const word* w = ijk_word[first] ? ijk_word[first] : ijk_word[second];
          error(w->column, "arc centre needs a known start point");
        } else {
          double c[3] = {*last_[0], *last_[1], *last_[2]};
          if (ijk[first]) c[first] += *ijk[first];
          if (ijk[second]) c[second] += *ijk[second];
          a.centre_mm = vec3{c[0], c[1], c[2]};
        }
      } else {
        error(b.where.column, "arc needs I, J, K or R");
      }
      b.arc = a;
    } else if (radius) {
      for (const word& w : words)
        if (w.letter == 'R') unknown(w);
    }
    if (!b.machine_coordinates) {
      if (b.axes.x_mm) last_[0] = b.axes.x_mm;
      if (b.axes.y_mm) last_[1] = b.axes.y_mm;
      if (b.axes.z_mm) last_[2] = b.axes.z_mm;
    }

    // The order the writer uses: G codes first, then the others (H, D, P, Q), each as written.
    std::stable_partition(b.kept_words.begin(), b.kept_words.end(),
                          [](const std::string& k) { return to_upper(k.front()) == 'G'; });

    if (unknown_found) {
      if (suppress) {
      } else if (b.moves() || b.arc) {
        error(unknown_column, "unknown word '" + unknown_text + "'");
      } else if (!failed_) {
        // Not understood and moving nothing: kept verbatim, never interpreted.
        block kept;
        kept.where = b.where;
        kept.text = b.text;
        kept.passthrough = true;
        std::tie(motion_, plane_, vector_tcp_, incremental_, incremental_line_, last_[0], last_[1], last_[2]) = saved;
        b = std::move(kept);
      }
    }
  }
};

/// Whether tool-tip tracking switched on at block `i` is written G43.5 (rather than G43.4): a
/// block from `i` up to the next switch carries a tool-axis vector.
inline bool vector_tcp_from(const std::vector<block>& blocks, std::size_t i) {
  for (std::size_t k = i; k < blocks.size(); ++k) {
    if (k > i && blocks[k].tcp) break;
    if (blocks[k].axes.tool_axis) return true;
  }
  return false;
}

inline std::string as_comment(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  if (text.find_first_of("()") != std::string::npos) return ";" + text;
  return "(" + text + ")";
}

}  // namespace detail

/// Reads ISO / Fanuc G code block by block: `on_block` receives each block in file order as soon
/// as it is read; errors and warnings go to `diagnostics` (its `parsed` is not touched).
inline void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                        const block_sink& on_block) {
  detail::reader(file_name, diagnostics, on_block).run(text);
}

/// Reads ISO / Fanuc G code. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(dialect::iso, text, std::move(file_name), &read_blocks);
}

/// Writes blocks as ISO / Fanuc G code one at a time, remembering the plane, the last point and
/// whether G43.5 is on, so a program of any length is written in constant memory.
/// `write(program)` below is this writer applied to every block.
class writer {
 public:
  /// A writer for blocks read from `source` (another dialect's passthrough text and kept words
  /// go into comments).
  explicit writer(dialect source, const write_options& chosen = {})
      : same(source == dialect::iso), options(chosen) {}

  /// Appends the line of block `b` to `out`. A block that switches tool-tip tracking on is
  /// written G43.5 when `vector_tcp_ahead` (a block before the next switch carries a tool-axis
  /// vector), else G43.4; a tool-axis vector outside G43.5 is an error. Throws
  /// `std::invalid_argument` naming the block's `file:line` when it cannot be written.
  void write(std::string& out, const block& b, bool vector_tcp_ahead = false) {
    auto fail = [&](const std::string& why) {
      throw std::invalid_argument(b.where.file + ":" + std::to_string(b.where.line) +
                                  ": block cannot be written in ISO: " + why);
    };
    if (b.passthrough) {
      out += (same ? b.text : detail::as_comment(b.text)) + '\n';
      return;
    }
    std::vector<std::string> words;
    std::vector<std::string> tail;  // non-G kept words
    std::string notes;              // what another dialect said that ISO cannot: a comment
    auto put = [&](char letter, double v, int decimals) { words.push_back(letter + format_number(v, decimals)); };
    if (b.number) words.push_back("N" + std::to_string(*b.number));
    if (b.program_begin) {
      const std::string& name = *b.program_begin;
      if (!name.empty() && name.find_first_not_of("0123456789") == std::string::npos)
        words.push_back("O" + name);
      else
        notes += (notes.empty() ? "" : " ") + std::string("program ") + name;
    }
    bool machine_word = false;
    if (same) {
      for (const std::string& k : b.kept_words) {
        if (!k.empty() && to_upper(k.front()) == 'G') {
          words.push_back(k);
          std::string_view digits = std::string_view(k).substr(1);
          while (!digits.empty() && is_space(digits.front())) digits.remove_prefix(1);
          const parsed_number n = read_number(digits);
          const int g = n.error == number_error::none ? detail::g_code(n.value) : -1;
          if (g == 170) plane = arc_plane::xy;
          if (g == 180) plane = arc_plane::zx;
          if (g == 190) plane = arc_plane::yz;
          if (g == 530 || g == 280 || g == 300) machine_word = true;
        } else {
          tail.push_back(k);
        }
      }
    } else if (!b.kept_words.empty()) {
      for (const std::string& k : b.kept_words) notes += (notes.empty() ? "" : " ") + k;
    }
    if (b.machine_coordinates && !machine_word) words.push_back("G53");
    if (b.arc && b.arc->plane != plane) {
      plane = b.arc->plane;
      words.push_back(plane == arc_plane::xy ? "G17" : plane == arc_plane::zx ? "G18" : "G19");
    }
    if (b.motion || b.feed_rapid) {
      const motion_kind m = b.feed_rapid ? motion_kind::rapid : *b.motion;
      words.push_back(m == motion_kind::rapid ? "G0" : m == motion_kind::linear ? "G1" : m == motion_kind::arc_cw ? "G2" : "G3");
    }
    if (b.tcp) {
      vector_tcp = *b.tcp && vector_tcp_ahead;
      words.push_back(!*b.tcp ? "G49" : vector_tcp ? "G43.5" : "G43.4");
    }
    if (b.feed_mode) words.push_back(*b.feed_mode == feed_unit::inverse_time ? "G93" : "G94");
    if (b.metric) {
      if (!*b.metric) fail("inch units");
      words.push_back("G21");
    }
    const axis_words& a = b.axes;
    if (a.x_mm) put('X', *a.x_mm, options.linear_decimals);
    if (a.y_mm) put('Y', *a.y_mm, options.linear_decimals);
    if (a.z_mm) put('Z', *a.z_mm, options.linear_decimals);
    if (a.a_deg) put('A', *a.a_deg, options.angle_decimals);
    if (a.b_deg) put('B', *a.b_deg, options.angle_decimals);
    if (a.c_deg) put('C', *a.c_deg, options.angle_decimals);
    if (a.tool_axis) {
      if (!vector_tcp) fail("a tool-axis vector needs G43.5");
      if (b.arc) fail("a tool-axis vector and an arc in one block");
      put('I', a.tool_axis->x, options.vector_decimals);
      put('J', a.tool_axis->y, options.vector_decimals);
      put('K', a.tool_axis->z, options.vector_decimals);
    }
    if (b.arc && b.arc->radius_mm) {
      put('R', *b.arc->radius_mm, options.linear_decimals);
    } else if (b.arc && b.arc->centre_mm) {
      if (!last[0] || !last[1] || !last[2]) fail("arc centre with no known start point");
      const double centre[3] = {b.arc->centre_mm->x, b.arc->centre_mm->y, b.arc->centre_mm->z};
      const int first = plane == arc_plane::xy ? 0 : plane == arc_plane::zx ? 2 : 1;
      const int second = plane == arc_plane::xy ? 1 : plane == arc_plane::zx ? 0 : 2;
      for (int k : {std::min(first, second), std::max(first, second)})
        put(static_cast<char>('I' + k), centre[k] - *last[k], options.linear_decimals);
    }
    if (b.machine_coordinates) {
      if (a.x_mm) last[0].reset();
      if (a.y_mm) last[1].reset();
      if (a.z_mm) last[2].reset();
    } else {
      if (a.x_mm) last[0] = a.x_mm;
      if (a.y_mm) last[1] = a.y_mm;
      if (a.z_mm) last[2] = a.z_mm;
    }
    if (b.feed) put('F', *b.feed, options.feed_decimals);
    if (b.spindle_rpm) put('S', *b.spindle_rpm, options.feed_decimals);
    if (b.tool) words.push_back("T" + std::to_string(*b.tool));
    bool ends = false;  // an M2 / M30 written in this block: never a second one
    for (int m : b.m_codes) {
      // M91 / M92 of another dialect are machine coordinates, already written as G53
      if (!same && b.machine_coordinates && (m == 91 || m == 92)) continue;
      words.push_back("M" + std::to_string(m));
      ends = ends || m == 2 || m == 30;
    }
    // A program end right after an M2 / M30 M function (Heidenhain `M30`, then `END PGM`) says it again.
    const bool end_written = ended && !same;
    ended = ends;
    if (b.program_end && !ends && !end_written) words.push_back(*b.program_end == "M2" ? "M2" : "M30");
    for (std::string& k : tail) words.push_back(std::move(k));
    if (!notes.empty()) words.push_back(detail::as_comment(notes));
    if (b.comment) words.push_back(detail::as_comment(*b.comment));
    if (words.empty() && !same && !b.text.empty()) words.push_back(detail::as_comment(b.text));
    std::string line;
    for (const std::string& w : words) line += (line.empty() ? "" : " ") + w;
    out += line + '\n';
  }

 private:
  bool same;  // the blocks were read as ISO
  write_options options;
  bool vector_tcp = false;
  arc_plane plane = arc_plane::xy;
  std::optional<double> last[3];
  bool ended = false;  // the last block written had an M2 / M30 M function
};

/// Writes `p` as ISO / Fanuc G code, one block per line, words in the order
/// `N  kept G  G0-G3  G43.4/G43.5/G49  G93/G94  G21  X Y Z A B C  I J K  R  F S T M  kept  (comment)`.
/// Throws std::invalid_argument naming the block's `file:line` for inch units, or a tool-axis
/// vector outside G43.5 together with an arc.
inline std::string write(const program& p, const write_options& options = {}) {
  writer w(p.language, options);
  std::string out;
  for (std::size_t k = 0; k < p.blocks.size(); ++k) {
    const block& b = p.blocks[k];
    w.write(out, b, b.tcp && *b.tcp && detail::vector_tcp_from(p.blocks, k));
  }
  return out;
}

}  // namespace kin5::program::iso
