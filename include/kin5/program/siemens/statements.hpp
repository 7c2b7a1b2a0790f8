/// @file program/siemens/statements.hpp
/// What each line of an 840D program is to the executor (../interp/statement.hpp): the Siemens
/// spelling of labels, jumps, section repeats and control structures (SINUMERIK 840D sl
/// Programming Manual Job Planning, "Flexible NC programming": "Program jumps and branches",
/// "Repeat program section", "Control structures"; docs/dialects/siemens.md, "Control flow").
/// | line | statement |
/// |---|---|
/// | `N40 MARK: …`, `MARK:` | ordinary, defining labels `MARK` and `N40` (a label: two letters or `_` first); the reader makes no block of a label alone |
/// | `GOTOF l`, `GOTOB l`, `GOTO l`, `GOTOC l` | jump: forward, backward, either; `GOTOC` goes on when `l` is missing |
/// | `IF c GOTOF l` | conditional jump (one line) |
/// | `IF c` … `ELSE` … `ENDIF` | IF branches, nested |
/// | `WHILE c` … `ENDWHILE` | test_first loop |
/// | `REPEAT` … `UNTIL c` | test_last loop, until `c` holds |
/// | `LOOP` … `ENDLOOP` | endless loop (left by a jump) |
/// | `FOR v = a TO b` … `ENDFOR` | counting loop |
/// | `REPEAT l P=n` | the lines from label `l` (before) to this one, `n` more times (`P` absent: 1) |
/// | `REPEAT a b P=n` | the lines from label `a` to the line of label `b`, `n` times |
/// | `REPEATB l P=n` | the line of label `l`, `n` times |
/// | `M2`, `M30`, `M17` | ordinary, ending the program (in a called subprogram's file: the call) |
/// | `L100`, `SUB_1`, `L100 P3`, `SUB P=R1` alone in a block | a call of the subprogram in another file, `P` times (`subprogram_file_names`) |
/// | `CALL "SUB"`, `PCALL SUB` | the same call, the name as a string (`CALL`) or without a path (`PCALL`) |
/// | `RET` in a called subprogram's file | the return from the call |
/// A label `l` is a name or a block number (`N100`). A name alone in a block is a call unless it is
/// a word the reader knows (`TRAORI`, `SOFT`, `TRANS`, …). Refused with the reason: `RET` in the
/// main program, `GOTOS`, `CASE`, `ENDLABEL`, `CALL` of anything but a name in quotes, `PCALL` with
/// a path or arguments, a call with arguments (`SUB(1, 2)`: the reader's), and anything after a
/// jump or a control keyword but a comment. Every other line is ordinary; `statement_of` looks at
/// its first word only, so a line that is neither (`N10 G1 X… Y…`) costs a few byte tests.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../interp/statement.hpp"
#include "../lexing.hpp"
#include "../text.hpp"
#include "expression.hpp"
#include "vocabulary.hpp"

namespace kin5::program::siemens {

namespace detail {

/// A label at the start of a line (after its block number): `MARK:` at bytes [begin, end), the
/// colon included, and its name in upper case.
struct label_at {
  std::string name;
  std::size_t begin = 0, end = 0;
};

/// The block number at `i` (`N40`): its value, and `i` moved past it; none when there is none.
inline std::optional<long long> block_number_at(std::string_view t, std::size_t& i) {
  if (i + 1 >= t.size() || to_upper(t[i]) != 'N' || !is_digit(t[i + 1])) return std::nullopt;
  std::size_t k = i + 1;
  long long n = 0;
  while (k < t.size() && is_digit(t[k])) {
    if (n < 1'000'000'000'000LL) n = n * 10 + (t[k] - '0');
    ++k;
  }
  if (k < t.size() && is_ident_char(t[k]) && !is_letter(t[k])) return std::nullopt;  // `N10_X`
  i = k;
  return n;
}

/// The label at `i`: a name of two letters or underscores and then name characters, with `:`
/// right after it (SINUMERIK 840D sl Fundamentals, "Block format": "Labels").
inline std::optional<label_at> label_name_at(std::string_view t, std::size_t i) {
  if (i + 2 >= t.size()) return std::nullopt;
  const auto starts = [](char c) { return is_letter(c) || c == '_'; };
  if (!starts(t[i]) || !starts(t[i + 1])) return std::nullopt;
  std::size_t k = i + 2;
  while (k < t.size() && is_ident_char(t[k])) ++k;
  if (k >= t.size() || t[k] != ':') return std::nullopt;
  return label_at{lexing::upper(t.substr(i, k - i)), i, k + 1};
}

/// The label of a line, if it has one (after blanks and a block number).
inline std::optional<label_at> line_label(std::string_view t) {
  std::size_t i = lexing::skip_blanks(t, 0);
  if (block_number_at(t, i)) i = lexing::skip_blanks(t, i);
  return label_name_at(t, i);
}

/// Whether `M2`, `M02`, `M30` or `M17` stands in `t` as an M word (outside comments and strings),
/// with blanks or a `+` before its value as the lexer reads them (`M 30`, `M+30`).
inline bool has_end_word(std::string_view t) {
  // Most lines hold no M at all: two memchr calls settle them without the byte loop below.
  if (!std::memchr(t.data(), 'M', t.size()) && !std::memchr(t.data(), 'm', t.size())) return false;
  bool in_string = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '"') in_string = !in_string;
    if (in_string) continue;
    if (c == ';') return false;
    if (c == '(') {
      const std::size_t close = t.find(')', i);
      if (close == std::string_view::npos) return false;
      i = close;
      continue;
    }
    if (to_upper(c) != 'M' || (i > 0 && (is_letter(t[i - 1]) || t[i - 1] == '_' || t[i - 1] == '$'))) continue;
    std::size_t value = lexing::skip_blanks(t, i + 1);
    if (value < t.size() && t[value] == '+') ++value;
    std::size_t k = value;
    while (k < t.size() && t[k] == '0') ++k;
    std::size_t e = k;
    while (e < t.size() && is_digit(t[e])) ++e;
    if (e == value || (e < t.size() && (t[e] == '.' || t[e] == '=' || (is_ident_char(t[e]) && !is_letter(t[e]))))) continue;
    const std::string_view n = t.substr(k, e - k);
    if (n == "2" || n == "30" || n == "17") return true;
  }
  return false;
}

}  // namespace detail

/// The files that may hold subprogram `name` (upper case), in the order tried: `NAME.SPF` as a
/// PC keeps it, `_N_NAME_SPF` as the control does (SINUMERIK 840D sl Programming Manual
/// Fundamentals, "Subprogram technique": program names, "Search path for subprogram call").
inline std::vector<std::string> subprogram_file_names(const std::string& name) {
  return {name + ".SPF", "_N_" + name + "_SPF"};
}

/// Whether `name` (upper case) alone in a block is a word of the language, not a subprogram: one
/// the reader reads or keeps, or one of the control's own modal words it refuses by name
/// (continuous-path, orientation, spline and transformation words).
inline bool is_known_keyword(std::string_view name) {
  static constexpr std::array<std::string_view, 45> language = {
      "TRAORI", "TRAFOOF", "SUPA", "MCALL", "STOPRE", "PROC", "DEF", "CFC", "CFTCP", "CFIN", "FLIN", "FCUB",
      "FPO", "BRISKA", "SOFTA", "DRIVEA", "UPATH", "SPATH", "CPRECON", "CPRECOF", "CDON", "CDOF", "CDOF2",
      "DIAMON", "DIAMOF", "NORM", "KONT", "KONTC", "KONTT", "TRACYL", "TRANSMIT", "TRAANG", "ORIC", "ORID",
      "OSOF", "ORIEULER", "ORIRPY", "ORIPLANE", "ASPLINE", "BSPLINE", "CSPLINE", "POLY", "STOPFIFO",
      "STARTFIFO", "ENDPROC"};
  return std::find(language.begin(), language.end(), name) != language.end() || detail::is_kept_keyword(name) ||
         detail::is_frame_reset_keyword(name) || detail::is_frame_keyword(name);
}

/// The Siemens syntax for the executor (see the file comment).
class statements {
 public:
  /// The statements of a subprogram's file a call runs (its text is the executor's): `RET` and
  /// `M17` end the call.
  statements for_text(std::string_view) const {
    statements called;
    called.called_ = true;
    return called;
  }

  interp::statement statement_of(const text_line& line) const {
    interp::statement s;
    const std::string_view t = line.text;
    std::size_t i = lexing::skip_blanks(t, 0);
    if (const auto n = detail::block_number_at(t, i)) {
      if (labels_wanted_) {
        char name[24] = {'N'};  // `N` and at most 13 digits: within the string's own buffer, no allocation
        s.block_label.assign(name, std::to_chars(name + 1, name + sizeof name, *n).ptr);
      }
      i = lexing::skip_blanks(t, i);
    }
    if (i < t.size() && (is_letter(t[i]) || t[i] == '_') && i + 1 < t.size() && (is_letter(t[i + 1]) || t[i + 1] == '_')) {
      if (auto l = detail::label_name_at(t, i)) {
        if (l->name == "ENDLABEL")
          return refuse(s, line, i, "ENDLABEL: the end of a section kin5 does not read (write REPEAT with two labels, "
                                    "REPEAT start end P=n)");
        s.label = std::move(l->name);
        i = lexing::skip_blanks(t, l->end);
      }
      if (i < t.size() && is_letter(t[i])) control(s, line, i, called_);
    }
    if (s.kind == interp::statement_kind::ordinary && !s.error && i < t.size() && (is_letter(t[i]) || t[i] == '_'))
      bare_call(s, line, i);
    if (s.kind == interp::statement_kind::ordinary) {
      if (s.label.empty() && !s.block_label.empty()) s.label = std::move(s.block_label), s.block_label.clear();
      s.ends_program = detail::has_end_word(t);
    } else if (s.kind != interp::statement_kind::label) {
      labels_wanted_ = true;  // a jump, call or block may search labels from now on
    }
    return s;
  }

 private:
  using K = interp::statement_kind;

  /// Block numbers become labels (`N40`) once a statement that may search labels was seen: the
  /// executor indexes labels only for such a statement, so a program without one makes none.
  mutable bool labels_wanted_ = false;
  bool called_ = false;  // the text of a subprogram's file a call runs

  /// A call of subprogram `name` (upper case): the executor runs its file `count` times.
  static void call_of(interp::statement& s, const std::string& name, std::optional<interp::expression> count) {
    s.kind = K::call;
    s.target = "subprogram " + name;  // no label has a blank: never a label of this file
    s.files = subprogram_file_names(name);
    s.count = std::move(count);
    s.call_frame = true;  // its DEF variables are its own; R parameters are shared
  }

  /// The subprogram name at `i`: `L` and digits, or two letters or `_` and name characters, in
  /// upper case, and its end; none when there is none.
  static std::optional<std::pair<std::string, std::size_t>> subprogram_name_at(std::string_view t, std::size_t i) {
    // Two bytes settle most lines (`G1 X…`, `X10`): no name, nothing made.
    if (i + 1 >= t.size()) return std::nullopt;
    const auto starts = [](char c) { return is_letter(c) || c == '_'; };
    const bool numbered = to_upper(t[i]) == 'L' && is_digit(t[i + 1]);
    if (!numbered && !(starts(t[i]) && starts(t[i + 1]))) return std::nullopt;
    std::size_t k = i;
    while (k < t.size() && detail::is_ident_char(t[k])) ++k;
    if (numbered && !std::all_of(t.begin() + static_cast<std::ptrdiff_t>(i) + 1, t.begin() + static_cast<std::ptrdiff_t>(k), is_digit))
      return std::nullopt;
    return std::pair{lexing::upper(t.substr(i, k - i)), k};
  }

  /// The pass count after a call at `i` (`P3`, `P=R1`), `i` moved past it; refused (none, and
  /// an error in `s`) when malformed; no count: an empty expression.
  static std::optional<std::optional<interp::expression>> passes(interp::statement& s, const text_line& line,
                                                                  std::size_t& i, const std::string& call) {
    const std::string_view t = line.text;
    i = lexing::skip_blanks(t, i);
    if (i >= t.size() || to_upper(t[i]) != 'P') return std::optional<interp::expression>{};
    std::size_t k = lexing::skip_blanks(t, i + 1);
    if (k < t.size() && t[k] == '=') {
      ++k;
      auto c = condition(s, line, k, call + " P=");
      if (!c) return std::nullopt;
      i = k;
      return std::optional<interp::expression>(std::move(*c));
    }
    std::size_t e = k;
    while (e < t.size() && is_digit(t[e])) ++e;
    if (e == k || e - k > 4 || (e < t.size() && detail::is_ident_char(t[e]))) {
      refuse(s, line, i, call + ": P takes the number of passes, 1 to 9999 (P3, P=R1)");
      return std::nullopt;
    }
    interp::expression count;
    count.root = count.number(static_cast<double>(std::stol(std::string(t.substr(k, e - k)))), {line.number, k + 1, e - k});
    i = e;
    return std::optional<interp::expression>(std::move(count));
  }

  /// A name alone in a block, perhaps with a pass count: a call of the subprogram in its file.
  static void bare_call(interp::statement& s, const text_line& line, std::size_t i) {
    const std::string_view t = line.text;
    const auto name = subprogram_name_at(t, i);
    if (!name || is_known_keyword(name->first)) return;
    std::size_t k = name->second;
    if (k < t.size() && !is_space(t[k]) && t[k] != ';') return;  // `SUB(…)`, `X=…`: the reader's
    // Only a pass count and a comment may follow; anything else is the reader's (`SOFT G1 X1`).
    std::size_t p = lexing::skip_blanks(t, k);
    if (p < t.size() && t[p] != ';' && to_upper(t[p]) != 'P') return;
    interp::statement call;
    auto count = passes(call, line, k, name->first);
    if (!count) {
      if (rest_is_empty(t, k) || call.error) s = std::move(call);
      return;
    }
    if (!rest_is_empty(t, k)) return;  // `SUB P1 X…`: words the reader reads (and refuses)
    const std::string label = std::move(s.label), block_label = std::move(s.block_label);
    call_of(s, name->first, std::move(*count));
    s.label = label, s.block_label = block_label;
  }

  /// `CALL "SUB"`, `PCALL SUB`: a call of a subprogram by a name in quotes, or without a path.
  static void named_call(interp::statement& s, const text_line& line, std::size_t i, const std::string& w) {
    const std::string_view t = line.text;
    std::size_t k = lexing::skip_blanks(t, i);
    std::string name;
    if (w == "CALL") {
      const std::size_t close = k < t.size() && t[k] == '"' ? t.find('"', k + 1) : std::string_view::npos;
      const auto n = close == std::string_view::npos ? std::nullopt : subprogram_name_at(t, k + 1);
      if (!n || n->second != close)
        return void(refuse(s, line, k, "CALL: only a subprogram's name in quotes is read (CALL \"SUB\"); a path or a "
                                       "name computed with << is not supported"));
      name = n->first;
      k = lexing::skip_blanks(t, close + 1);
      if (k + 1 < t.size() && t[k] == '<' && t[k + 1] == '<')
        return void(refuse(s, line, k, "CALL \"" + name + "\" << …: a name computed with << is not supported (the "
                                       "subprogram would depend on the run); write its name", 2));
    } else {
      const auto n = subprogram_name_at(t, k);
      if (!n || (n->second < t.size() && !is_space(t[n->second]) && t[n->second] != ';'))
        return void(refuse(s, line, k, "PCALL: only a subprogram's name is read (PCALL SUB); a path or arguments are "
                                       "not supported"));
      name = n->first;
      k = n->second;
    }
    auto count = passes(s, line, k, w + " " + name);
    if (!count || !ends_here(s, line, k, w)) return;
    call_of(s, name, std::move(*count));
  }

  static interp::statement& refuse(interp::statement& s, const text_line& line, std::size_t at, std::string why,
                                   std::size_t length = 1) {
    s.kind = K::label;  // does nothing: the error stops the run
    s.error = interp::expression_error{{line.number, at + 1, length}, std::move(why)};
    return s;
  }

  /// The word at `i`, in upper case, and its end.
  static std::pair<std::string, std::size_t> word_at(std::string_view t, std::size_t i) {
    std::size_t k = i;
    while (k < t.size() && detail::is_ident_char(t[k])) ++k;
    return {lexing::upper(t.substr(i, k - i)), k};
  }

  /// Whether only blanks and a comment follow `i`.
  static bool rest_is_empty(std::string_view t, std::size_t i) {
    i = lexing::skip_blanks(t, i);
    return i == t.size() || t[i] == ';';
  }

  /// Checks that nothing but a comment follows `i` on a control line.
  static bool ends_here(interp::statement& s, const text_line& line, std::size_t i, const std::string& keyword) {
    const std::size_t k = lexing::skip_blanks(line.text, i);
    if (k == line.text.size() || line.text[k] == ';') return true;
    refuse(s, line, k,
           keyword + ": unexpected '" + std::string(line.text.substr(k, 1)) + "' after it (a control statement takes a "
                                                                              "block of its own, with a comment at most)");
    return false;
  }

  /// An expression from `i`, up to where it ends; `i` moved past it. Empty after refusing.
  static std::optional<interp::expression> condition(interp::statement& s, const text_line& line, std::size_t& i,
                                                     const std::string& keyword) {
    i = lexing::skip_blanks(line.text, i);
    if (i >= line.text.size() || line.text[i] == ';') {
      refuse(s, line, i, keyword + " needs a condition");
      return std::nullopt;
    }
    parsed_expression e = read_value(line.text.substr(i), line.number, i + 1);
    if (!e.ok()) {
      s.kind = K::label;
      s.error = std::move(e.error);
      return std::nullopt;
    }
    i += e.end;
    return std::move(e.tree);
  }

  /// A jump target at `i`: a label name or a block number (`N100`), upper case.
  static std::optional<std::string> target_at(interp::statement& s, const text_line& line, std::size_t& i,
                                              const std::string& keyword) {
    const std::string_view t = line.text;
    i = lexing::skip_blanks(t, i);
    std::size_t k = i;
    if (const auto n = detail::block_number_at(t, k)) {
      i = k;
      return "N" + std::to_string(*n);
    }
    if (i < t.size() && (is_letter(t[i]) || t[i] == '_')) {
      auto [name, end] = word_at(t, i);
      if (name.size() >= 2 && !is_digit(name[1])) {
        i = end;
        return name;
      }
      refuse(s, line, i, keyword + ": " + name + " is no label (a label starts with two letters or '_'; a block number is N100)");
      return std::nullopt;
    }
    refuse(s, line, i, keyword + " needs a label (a name, or a block number: N100)");
    return std::nullopt;
  }

  static interp::jump_direction direction_of(const std::string& w) {
    if (w == "GOTOF") return interp::jump_direction::forward;
    if (w == "GOTOB") return interp::jump_direction::backward;
    return interp::jump_direction::either;
  }

  static bool is_jump(const std::string& w) { return w == "GOTOF" || w == "GOTOB" || w == "GOTO" || w == "GOTOC"; }

  static void jump(interp::statement& s, const text_line& line, std::size_t i, const std::string& w) {
    const auto target = target_at(s, line, i, w);
    if (!target || !ends_here(s, line, i, w)) return;
    s.kind = K::jump;
    s.target = *target;
    s.direction = direction_of(w);
    s.target_optional = w == "GOTOC";
  }

  /// `REPEAT l P=n`, `REPEAT a b P=n`, `REPEATB l P=n`: a section repeat.
  static void section(interp::statement& s, const text_line& line, std::size_t i, const std::string& w) {
    const std::string_view t = line.text;
    const auto first = target_at(s, line, i, w);
    if (!first) return;
    s.kind = K::call;
    s.call_frame = false;
    s.target = *first;
    std::size_t k = lexing::skip_blanks(t, i);
    // The start label is searched toward the program's start first, then toward its end.
    s.direction = interp::jump_direction::backward_then_forward;
    if (w == "REPEATB") {
      s.ends = interp::call_end::end_label, s.end_target = *first;
    } else if (k < t.size() && (is_letter(t[k]) || t[k] == '_') && word_at(t, k).first != "P") {
      const auto second = target_at(s, line, k, w);
      if (!second) return;
      s.ends = interp::call_end::end_label, s.end_target = *second;
    } else {
      s.ends = interp::call_end::calling_line;  // from the label before it to this line
      s.direction = interp::jump_direction::backward;
    }
    k = lexing::skip_blanks(t, k);
    if (k < t.size() && to_upper(t[k]) == 'P') {
      std::size_t e = lexing::skip_blanks(t, k + 1);
      if (e >= t.size() || t[e] != '=') return void(refuse(s, line, k, w + ": P takes its count after '=' (P=3)"));
      e = e + 1;
      auto count = condition(s, line, e, w + " P=");
      if (!count) return;
      s.count = std::move(*count);
      k = e;
    }
    ends_here(s, line, k, w);
  }

  /// `FOR v = a TO b`.
  static void counting(interp::statement& s, const text_line& line, std::size_t i) {
    const std::string_view t = line.text;
    i = lexing::skip_blanks(t, i);
    expression_parser p(spelling, t.substr(i), line.number, i + 1);
    const interp::node_id counter = p.operand();
    if (p.failed()) return void(refuse(s, line, i, "FOR needs a counter (FOR R1 = 1 TO 5)"));
    const auto kind = p.tree().at(counter).kind;
    if (kind != interp::node_kind::numbered_parameter && kind != interp::node_kind::named_parameter)
      return void(refuse(s, line, i, "FOR needs a parameter or variable as its counter"));
    if (!p.take('=')) return void(refuse(s, line, i + p.position(), "FOR needs '=' after its counter"));
    interp::expression target = std::move(p.tree());
    target.root = counter;
    std::size_t k = i + p.position();
    auto first = condition(s, line, k, "FOR");
    if (!first) return;
    k = lexing::skip_blanks(t, k);
    if (word_at(t, k).first != "TO") return void(refuse(s, line, k, "FOR needs TO and the last value (FOR R1 = 1 TO 5)"));
    k += 2;
    auto last = condition(s, line, k, "FOR … TO");
    if (!last || !ends_here(s, line, k, "FOR")) return;
    s.kind = K::loop_begin;
    s.loop = interp::loop_kind::counting;
    s.counter = interp::assignment{std::move(target), std::move(*first)};
    s.count = std::move(*last);
  }

  /// The control statement at `i`, if the word there is one (`called`: in a subprogram's file).
  static void control(interp::statement& s, const text_line& line, std::size_t i, bool called) {
    const std::string_view t = line.text;
    const char first = to_upper(t[i]);
    if (first != 'E' && first != 'F' && first != 'G' && first != 'I' && first != 'L' && first != 'R' && first != 'U' &&
        first != 'W' && first != 'C' && first != 'P')
      return;
    // Named, not a structured binding: the lambdas below capture `w`, which Clang refuses for a binding.
    const auto word = word_at(t, i);
    const std::string& w = word.first;
    const std::size_t end = word.second;
    if (end < t.size() && (t[end] == '=' || t[end] == '(' || t[end] == '[')) return;  // an assignment or a call
    std::size_t k = end;
    if (is_jump(w)) return jump(s, line, k, w);
    if (w == "IF") {
      auto c = condition(s, line, k, w);
      if (!c) return;
      const std::size_t after = lexing::skip_blanks(t, k);
      if (rest_is_empty(t, after)) {
        s.kind = K::if_branch;
        s.condition = std::move(*c);
        return;
      }
      const auto [j, j_end] = word_at(t, after);
      if (!is_jump(j))
        return void(refuse(s, line, after, "IF: expected a jump (GOTOF, GOTOB, GOTO, GOTOC) or the end of the line after "
                                           "the condition"));
      jump(s, line, j_end, j);
      if (s.kind == K::jump) s.condition = std::move(*c);
      return;
    }
    if (w == "WHILE" || w == "UNTIL") {
      auto c = condition(s, line, k, w);
      if (!c || !ends_here(s, line, k, w)) return;
      s.kind = w == "WHILE" ? K::loop_begin : K::loop_end;
      s.loop = w == "WHILE" ? interp::loop_kind::test_first : interp::loop_kind::test_last;
      s.until = w == "UNTIL";
      s.condition = std::move(*c);
      return;
    }
    const auto simple = [&](K kind, interp::loop_kind loop = interp::loop_kind::test_first) {
      if (!ends_here(s, line, k, w)) return;
      s.kind = kind;
      s.loop = loop;
    };
    if (w == "ELSE") return simple(K::else_branch);
    if (w == "ENDIF") return simple(K::end_if);
    if (w == "ENDWHILE") return simple(K::loop_end);
    if (w == "ENDFOR") return simple(K::loop_end, interp::loop_kind::counting);
    if (w == "LOOP") return simple(K::loop_begin, interp::loop_kind::endless);
    if (w == "ENDLOOP") return simple(K::loop_end, interp::loop_kind::endless);
    if (w == "FOR") return counting(s, line, k);
    if (w == "REPEAT" && rest_is_empty(t, k)) return simple(K::loop_begin, interp::loop_kind::test_last);
    if (w == "REPEAT" || w == "REPEATB") return section(s, line, k, w);
    if (w == "CALL" || w == "PCALL") return named_call(s, line, k, w);
    if (w == "RET" && called) return simple(K::return_from_call);
    if (w == "RET")
      return void(refuse(s, line, i, "RET: the end of a subprogram, in the main program (M30, M2 or M17 end it)", 3));
    if (w == "GOTOS")
      return void(refuse(s, line, i, "GOTOS: a jump to the program's start is not supported", 5));
    if (w == "CASE")
      return void(refuse(s, line, i, "CASE: a branch by value is not supported (write IF … ELSE … ENDIF)", 4));
  }
};

}  // namespace kin5::program::siemens
