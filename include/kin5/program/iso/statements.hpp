/// @file program/iso/statements.hpp
/// What a line of an ISO-family program is to the interpreter (../interp/statement.hpp): the
/// syntax the ISO reader (reader.hpp) runs its lines through. An ordinary line, perhaps with a
/// parameter assignment (`#1 = 5000`, `#1 = [#2 + 3]`, `#[#1] = SIN[30]`, `N10 #2 = #1 * 2`:
/// FANUC Custom Macro B, "Variables", "Arithmetic and logic operation": the right side is a
/// whole expression, and the assignment takes its block alone, with a comment). Only the block
/// number and blanks come before the `#`: a line that does not start so is told apart by its
/// first character, so an ordinary line costs a few byte comparisons.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../expression_parser.hpp"
#include "../interp/statement.hpp"
#include "../lexing.hpp"
#include "../text.hpp"
#include "expression.hpp"
#include "lexer.hpp"

namespace kin5::program::iso {

namespace detail {

/// The offset after the block number `N123` (and the blanks after it) that may start the line
/// from `i`, or `i` when there is none; its number into `number` when it is given.
inline std::size_t after_block_number(std::string_view s, std::size_t i, std::size_t end,
                                      std::optional<long>* number = nullptr) {
  if (i >= end || (s[i] != 'N' && s[i] != 'n')) return i;
  std::size_t k = i + 1;
  long n = 0;
  while (k < end && is_digit(s[k]) && k - i <= 9) n = n * 10 + (s[k++] - '0');
  if (k == i + 1) return i;
  if (number) *number = n;
  return lexing::skip_blanks(s.substr(0, end), k);
}

/// The end of a line's code: `end`, or the first byte of a comment that runs to it (`;`).
inline std::size_t code_end(std::string_view s, std::size_t end) {
  const std::size_t semi = s.substr(0, end).find(';');
  return semi == std::string_view::npos ? end : semi;
}

/// Whether the line from `k` to `end` holds nothing but blanks and comments (nested as
/// `nesting` says); where the first thing that is not one starts, or the problem a comment has,
/// otherwise.
inline std::optional<lex_problem> only_comments(std::string_view s, std::size_t k, std::size_t end,
                                                comment_nesting nesting = comment_nesting::nested) {
  std::vector<word> words;
  std::optional<std::string> comment;
  if (auto p = lex_line(s, k, end, words, comment, {}, nesting)) return p;
  if (!words.empty()) return lex_problem{words.front().column, ""};
  return std::nullopt;
}

/// An expression of `e` rooted at node `root` (a copy: targets and values are kept apart).
inline interp::expression rooted(const interp::expression& e, interp::node_id root) {
  interp::expression out = e;
  out.root = root;
  return out;
}

/// The error of statement `s` at 1-based `column`.
inline interp::statement failed(interp::statement s, std::size_t line, std::size_t column, std::string message) {
  s.error = interp::expression_error{{line, column, 1}, std::move(message)};
  return s;
}

/// Reads `target = value` at offset `k` of `s` (a `#`) with spelling `spelling`: the value a
/// whole expression (`whole`) or one operand. Adds it to `s.assignments`; the offset after the
/// value, or nothing after setting `s.error`.
inline std::optional<std::size_t> read_assignment(const expression_spelling& spelling, bool whole, std::string_view s,
                                                  std::size_t k, std::size_t end, std::size_t line,
                                                  interp::statement& out) {
  expression_parser p(spelling, s.substr(k, end - k), line, k + 1);
  const interp::node_id target = p.operand();
  if (p.failed()) return out.error = p.error(), std::nullopt;
  const interp::node& t = p.tree().at(target);
  if (t.kind != interp::node_kind::numbered_parameter && t.kind != interp::node_kind::named_parameter) {
    out = failed(std::move(out), line, k + 1, "a value with no address letter (only a parameter may start a block)");
    return std::nullopt;
  }
  const std::size_t target_end = p.position();
  if (!p.take('=')) {
    const std::string shown(lexing::trim(s.substr(k, target_end)));
    out = failed(std::move(out), line, k + 1,
                 "parameter " + shown + " with no address letter (a block sets it with `" + shown + " = value`)");
    return std::nullopt;
  }
  const std::size_t value_at = p.position();
  if (value_at >= end - k) {
    out = failed(std::move(out), line, k + value_at + 1, "'=' with no value after it");
    return std::nullopt;
  }
  const interp::node_id value = whole ? p.expression() : p.operand();
  if (p.failed()) return out.error = p.error(), std::nullopt;
  out.assignments.push_back({rooted(p.tree(), target), rooted(p.tree(), value)});
  return k + p.position();
}

}  // namespace detail

/// The G65 argument of letter `l` (argument specification I; a value without a decimal point
/// is in the address's least input increment, and is refused unless 0: A #1, B #2, C #3, I #4, J #5,
/// K #6, D #7, E #8, F #9, H #11, M #13, Q #17, R #18, S #19, T #20, U #21, V #22, W #23,
/// X #24, Y #25, Z #26), or 0 for a letter that is no argument (G, L, N, O, P).
constexpr long argument_number(char l) {
  switch (l) {
    case 'A': return 1;  case 'B': return 2;  case 'C': return 3;  case 'I': return 4;  case 'J': return 5;
    case 'K': return 6;  case 'D': return 7;  case 'E': return 8;  case 'F': return 9;  case 'H': return 11;
    case 'M': return 13; case 'Q': return 17; case 'R': return 18; case 'S': return 19; case 'T': return 20;
    case 'U': return 21; case 'V': return 22; case 'W': return 23; case 'X': return 24; case 'Y': return 25;
    case 'Z': return 26; default: return 0;
  }
}

/// FANUC Custom Macro B statements (see the file comment); with `Haas`, a Haas mill's, which
/// add `M97 P n` (a local subprogram: the part from block N n, in this file) and take M98's P
/// as the whole program number (Haas mill manual, "Subprograms").
template <bool Haas = false>
class basic_macro_statements {
 public:
  explicit basic_macro_statements(std::string_view text = {}) : text_(text) {}

  interp::statement statement_of(const text_line& line) const {
    interp::statement out;
    const std::string_view s = line.text;
    const std::size_t end = s.size();
    std::optional<long> n;
    const std::size_t i = detail::after_block_number(s, lexing::skip_blanks(s, 0), end, &n);
    if (n && labels_wanted_) out.label = block_label(*n, line);
    if (i >= end) return out;
    const char c = to_upper(s[i]);
    const std::size_t code = detail::code_end(s, end);
    if (c == '#') return assignment(std::move(out), s, i, code, end, line.number);
    if (c == 'O' && i + 1 < end && is_digit(s[i + 1])) {  // a program's number: `O1000`, a subprogram's start
      long o = 0;
      for (std::size_t k = i + 1; k < end && is_digit(s[k]) && k - i <= 9; ++k) o = o * 10 + (s[k] - '0');
      out.label = "O" + std::to_string(o);
      return out;
    }
    if (keyword(s, i, code, "GOTO")) return go_to(std::move(out), s, i + 4, code, line, std::nullopt);
    if (keyword(s, i, code, "IF")) return if_statement(std::move(out), s, i + 2, code, line);
    if (keyword(s, i, code, "WHILE")) return while_loop(std::move(out), s, i + 5, code, end, line.number);
    if (c == 'D' && i + 2 < code && to_upper(s[i + 1]) == 'O' && is_digit(lexing::skip_blanks(s.substr(0, code), i + 2) < code ? s[lexing::skip_blanks(s.substr(0, code), i + 2)] : 'x'))
      return loop_key(std::move(out), s, i + 2, code, end, line.number, interp::statement_kind::loop_begin, true);
    if (keyword(s, i, code, "END") && !keyword(s, i, code, "ENDM"))
      return loop_key(std::move(out), s, i + 3, code, end, line.number, interp::statement_kind::loop_end, false);
    return calls(std::move(out), s, i, code, line);
  }

  /// The label of block `N n` on `line`: the number and the program it is in (`N10@O3200`), as
  /// a GOTO or M97 searches only the program it is in.
  std::string block_label(long n, const text_line& line) const {
    labels_wanted_ = true;
    if (!programs_) {
      programs_.emplace();
      for_each_line(text_, [&](const text_line& l) {
        const std::size_t i = detail::after_block_number(l.text, lexing::skip_blanks(l.text, 0), l.text.size());
        if (i + 1 < l.text.size() && to_upper(l.text[i]) == 'O' && is_digit(l.text[i + 1])) {
          long o = 0;
          for (std::size_t k = i + 1; k < l.text.size() && is_digit(l.text[k]) && k - i <= 9; ++k) o = o * 10 + (l.text[k] - '0');
          programs_->push_back({static_cast<std::size_t>(l.text.data() - text_.data()), o});
        }
      });
    }
    std::string label = "N" + std::to_string(n);
    const char* at = line.text.data();
    if (text_.empty() || at < text_.data() || at > text_.data() + text_.size()) return label;
    const auto offset = static_cast<std::size_t>(at - text_.data());
    std::optional<long> program;
    for (const auto& [start, o] : *programs_)
      if (start <= offset) program = o;
    return program ? label + "@O" + std::to_string(*program) : label;
  }

  /// Whether `s`, a line after the program's end, starts a part of the file the program calls
  /// or may call: a program (`O1000`) or a block a call went to (M97's `N1000`).
  bool starts_called_part(const interp::statement& s) const {
    return !s.label.empty() && (s.label[0] == 'O' || called_.count(s.label) > 0);
  }

  /// The files that may hold program number `n` when this file does not (docs/dialects/iso.md):
  /// `O1000`, `O1000.nc`, `1000.nc`, and the same with the number padded to the control's
  /// digits (FANUC four: `O0100`; Haas five: `O00100`).
  static std::vector<std::string> file_names(long n) {
    std::vector<std::string> names;
    const auto add = [&](const std::string& digits) {
      for (std::string name : {"O" + digits, "O" + digits + ".nc", digits + ".nc"})
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
    };
    const std::string digits = std::to_string(n);
    add(digits);
    const std::size_t width = Haas ? 5 : 4;
    if (digits.size() < width) add(std::string(width - digits.size(), '0') + digits);
    return names;
  }

  /// A flow error's message in this dialect's terms.
  static std::string explain(const std::string& message) {
    if (message == "returns from a call, but no call is open")
      return "M99 in the main program: the control runs the program again from its start, without end (kin5 "
             "translates a program that ends: M30 or M2)";
    return message;
  }

 private:
  std::string_view text_;
  /// Block labels are made once a GOTO or M97 needs them (before, none is searched for).
  mutable bool labels_wanted_ = false;
  mutable std::optional<std::vector<std::pair<std::size_t, long>>> programs_;  // the O lines: offset, number
  mutable std::set<std::string> called_;  // the labels calls have named

  /// Whether keyword `w` (upper case) is at `i`, not run on into a letter.
  static bool keyword(std::string_view s, std::size_t i, std::size_t end, std::string_view w) {
    if (end - i < w.size()) return false;
    for (std::size_t k = 0; k < w.size(); ++k)
      if (to_upper(s[i + k]) != w[k]) return false;
    return true;
  }

  static interp::statement rest_is_comment(interp::statement out, std::string_view s, std::size_t after,
                                           std::size_t end, std::size_t line, std::string_view what) {
    if (const auto rest = detail::only_comments(s, after, end))
      return detail::failed(std::move(out), line, rest->column,
                            rest->message.empty() ? "a word after " + std::string(what) +
                                                        ": a macro statement takes its block alone (write the word "
                                                        "in a block of its own)"
                                                  : rest->message);
    return out;
  }

  static interp::statement assignment(interp::statement out, std::string_view s, std::size_t i, std::size_t code,
                                      std::size_t end, std::size_t line) {
    const auto after = detail::read_assignment(macro_spelling, true, s, i, code, line, out);
    if (!after) return out;
    if (is_alarm(out.assignments.back().target)) {  // `#3000 = n (MESSAGE)`: the reader's alarm stop
      if (out.condition)
        return detail::failed(std::move(out), line, i + 1, "an alarm (#3000) under IF [ … ] THEN is not supported: "
                                                           "write IF [ … ] GOTO to a block that sets #3000");
      out.assignments.pop_back();
      return out;
    }
    return rest_is_comment(std::move(out), s, *after, end, line, "the parameter assignment");
  }

  /// Whether `target` is `#3000`, written with its number: the alarm (FANUC Custom Macro B).
  static bool is_alarm(const interp::expression& target) {
    const interp::node& t = target.at(target.root);
    return t.kind == interp::node_kind::numbered_parameter && t.prefix == "#" &&
           target.at(t.a).kind == interp::node_kind::number && target.at(t.a).number == 3000;
  }

  /// A whole number written at `i` (after blanks): its value and the offset after it.
  static std::optional<long> number_at(std::string_view s, std::size_t& i, std::size_t end) {
    i = lexing::skip_blanks(s.substr(0, end), i);
    std::size_t k = i;
    long n = 0;
    while (k < end && is_digit(s[k]) && k - i < 9) n = n * 10 + (s[k++] - '0');
    if (k == i) return std::nullopt;
    i = k;
    return n;
  }

  /// `GOTO n` from `i` (after the keyword), under `condition` when an IF gave one.
  interp::statement go_to(interp::statement out, std::string_view s, std::size_t i, std::size_t code,
                          const text_line& line, std::optional<interp::expression> condition) const {
    const std::size_t end = line.text.size();
    const std::size_t at = lexing::skip_blanks(s.substr(0, code), i);
    const auto n = number_at(s, i, code);
    if (!n)
      return detail::failed(std::move(out), line.number, at + 1,
                            at < code && (s[at] == '#' || s[at] == '[')
                                ? "GOTO to a computed block number is not supported (write GOTO n)"
                                : "GOTO needs the block number to go to (GOTO n)");
    out.kind = interp::statement_kind::jump;
    out.target = block_label(*n, line);
    out.condition = std::move(condition);
    return rest_is_comment(std::move(out), s, i, end, line.number, "GOTO n");
  }

  /// The bracketed condition at `i`, into `into`; the offset after it, or nothing (error set).
  static std::optional<std::size_t> condition_at(std::string_view s, std::size_t i, std::size_t code, std::size_t line,
                                                 std::string_view what, interp::statement& out,
                                                 std::optional<interp::expression>& into) {
    i = lexing::skip_blanks(s.substr(0, code), i);
    if (i >= code || s[i] != '[') {
      out = detail::failed(std::move(out), line, i + 1, std::string(what) + " needs its condition in brackets: [ … ]");
      return std::nullopt;
    }
    parsed_expression e = read_value(s.substr(i, code - i), line, i + 1);
    if (!e.ok()) return out.error = e.error, std::nullopt;
    into = std::move(e.tree);
    return i + e.end;
  }

  /// `IF [c] GOTO n` or `IF [c] THEN #i = e`.
  interp::statement if_statement(interp::statement out, std::string_view s, std::size_t i, std::size_t code,
                                 const text_line& text) const {
    const std::size_t end = text.text.size(), line = text.number;
    std::optional<interp::expression> condition;
    const auto after = condition_at(s, i, code, line, "IF", out, condition);
    if (!after) return out;
    const std::size_t k = lexing::skip_blanks(s.substr(0, code), *after);
    if (keyword(s, k, code, "GOTO")) return go_to(std::move(out), s, k + 4, code, text, std::move(condition));
    if (keyword(s, k, code, "THEN")) {
      const std::size_t a = lexing::skip_blanks(s.substr(0, code), k + 4);
      if (a >= code || s[a] != '#')
        return detail::failed(std::move(out), line, a + 1, "IF [ … ] THEN takes a parameter assignment (#i = …)");
      out.condition = std::move(condition);  // the assignment runs when it holds
      return assignment(std::move(out), s, a, code, end, line);
    }
    return detail::failed(std::move(out), line, k + 1, "IF [ … ] needs GOTO n or THEN #i = … after its condition");
  }

  /// `WHILE [c] DOm`: a loop keyed m (1, 2 or 3).
  static interp::statement while_loop(interp::statement out, std::string_view s, std::size_t i, std::size_t code,
                                      std::size_t end, std::size_t line) {
    const auto after = condition_at(s, i, code, line, "WHILE", out, out.condition);
    if (!after) return out;
    const std::size_t k = lexing::skip_blanks(s.substr(0, code), *after);
    if (!keyword(s, k, code, "DO"))
      return detail::failed(std::move(out), line, k + 1, "WHILE [ … ] needs DOm after its condition (m: 1, 2 or 3)");
    return loop_key(std::move(out), s, k + 2, code, end, line, interp::statement_kind::loop_begin, false);
  }

  /// The m of `DOm` or `ENDm` at `i`: the loop's key.
  static interp::statement loop_key(interp::statement out, std::string_view s, std::size_t i, std::size_t code,
                                    std::size_t end, std::size_t line, interp::statement_kind kind, bool endless) {
    const std::size_t at = i;
    const auto m = number_at(s, i, code);
    if (!m) return detail::failed(std::move(out), line, at + 1, "DO and END need the loop's number (DO1 … END1)");
    out.kind = kind;
    out.key = std::to_string(*m);
    if (endless) out.loop = interp::loop_kind::endless;
    return rest_is_comment(std::move(out), s, i, end, line, kind == interp::statement_kind::loop_end ? "ENDm" : "DOm");
  }

  /// A scan of the words for M98, M99, G65 (and Haas M97), M30 and M2: a call, a return, the
  /// program's end; any other line is ordinary.
  interp::statement calls(interp::statement out, std::string_view s, std::size_t i, std::size_t code,
                          const text_line& text) const {
    const std::size_t end = text.text.size(), line = text.number;
    int found = 0;  // 98, 99, 97 (M) or 65 (G)
    for (std::size_t k = i; k < code; ++k) {
      if (s[k] == '(') {
        const std::size_t close = detail::comment_close(s, k, code, comment_nesting::nested);
        if (close >= code) break;
        k = close;
        continue;
      }
      const char l = to_upper(s[k]);
      if (l != 'M' && l != 'G') continue;
      std::size_t d = lexing::skip_blanks(s.substr(0, code), k + 1);
      long v = 0;
      const std::size_t from = d;
      while (d < code && is_digit(s[d]) && d - from < 6) v = v * 10 + (s[d++] - '0');
      if (d == from || (d < code && s[d] == '.')) continue;
      if (l == 'M' && (v == 30 || v == 2)) out.ends_program = true;
      if ((l == 'M' && (v == 98 || v == 99 || (Haas && v == 97))) || (l == 'G' && v == 65)) {
        if (found) return detail::failed(std::move(out), line, k + 1, "two subprogram calls or returns in one block");
        found = l == 'G' ? 65 : static_cast<int>(v);
      }
    }
    if (!found) return out;
    std::vector<word> words;
    std::vector<interp::expression> values;
    std::optional<std::string> comment;
    const computed_values computed{&macro_value, line, &values};
    if (auto p = lex_line(s, i, end, words, comment, computed)) return detail::failed(std::move(out), line, p->column, p->message);
    const std::string name = found == 65 ? "G65" : "M" + std::to_string(found);
    const word* p = nullptr;
    const word* l = nullptr;
    for (const word& w : words) {
      const bool own = (w.letter == 'M' && found != 65 && !w.computed && w.value == found) ||
                       (w.letter == 'G' && found == 65 && !w.computed && w.value == 65);
      if (own || w.letter == 'N') continue;
      if (w.letter == 'P' && !p) {
        p = &w;
      } else if (w.letter == 'L' && !l && found != 99) {
        l = &w;
      } else if (found == 65 && argument_number(w.letter) != 0) {
        const interp::parameter_key key{"#", argument_number(w.letter)};
        for (const interp::argument& a : out.arguments)
          if (a.key == key)
            return detail::failed(std::move(out), line, w.column,
                                  "G65: argument " + std::string(1, w.letter) + " given twice (argument specification "
                                  "II, I J K repeated, is not read)");
        if (!w.computed && w.value != 0 && w.digits.find('.') == std::string_view::npos)
          return detail::failed(std::move(out), line, w.column,
                                "G65 argument " + std::string(w.text) + " without a decimal point: the control reads "
                                "it in the least input increment of address " + std::string(1, w.letter) +
                                " (write " + std::string(w.text) + ".)");
        interp::expression value;
        if (w.computed) value = std::move(values[*w.computed]);
        else value.root = value.number(w.value, {line, w.column + 1, w.digits.size()});
        out.arguments.push_back({key, std::move(value)});
      } else {
        return detail::failed(std::move(out), line, w.column,
                              "word '" + std::string(w.text) + "' in the block of " + name +
                                  ": a subprogram call or return is read in a block of its own (write the word in a "
                                  "block before it)");
      }
    }
    if (found == 99) {
      if (p) return detail::failed(std::move(out), line, p->column, "M99 P n (a return to block n of the caller) is not supported");
      out.kind = interp::statement_kind::return_from_call;
      out.ends_program = false;
      return out;
    }
    if (!p) return detail::failed(std::move(out), line, 1, name + " needs P, the " + (found == 97 ? "block number" : "program number") + " it calls");
    if (p->computed || !lexing::is_whole(p->value))
      return detail::failed(std::move(out), line, p->column, name + ": P must be a whole number written in the block");
    long number = static_cast<long>(p->value);
    if (l) {
      if (l->computed) out.count = std::move(values[*l->computed]);
      else {
        out.count.emplace();
        out.count->root = out.count->number(l->value, {line, l->column + 1, l->digits.size()});
      }
    }
    if (found == 98 && !Haas && p->digits.size() > 4) {  // FANUC: P△△△△□□□□, repetitions then the program
      if (l) return detail::failed(std::move(out), line, p->column, "M98: repetitions both in P (its first digits) and in L");
      out.count.emplace();
      out.count->root = out.count->number(static_cast<double>(number / 10000), {line, p->column + 1, 1});
      number %= 10000;
    }
    out.kind = interp::statement_kind::call;
    labels_wanted_ = true;
    out.target = found == 97 ? block_label(number, text) : "O" + std::to_string(number);
    if (found != 97) out.files = file_names(number);
    called_.insert(out.target);
    out.call_frame = found == 65;
    out.ends_program = false;
    return out;
  }

  static parsed_expression macro_value(std::string_view text, std::size_t line, std::size_t column) {
    return read_value(text, line, column);
  }
};

using macro_statements = basic_macro_statements<false>;

}  // namespace kin5::program::iso
