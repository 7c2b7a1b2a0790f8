/// @file program/linuxcnc/statements.hpp
/// What a line of a LinuxCNC program is to the interpreter (../interp/statement.hpp): the
/// syntax the reader (reader.hpp, through iso/reader.hpp) runs its lines through. An o-word
/// (LinuxCNC User Manual, "O Codes"), `o100` or `o<name>` (the name in lower case without
/// blanks), then its keyword:
/// | o-word | statement |
/// |---|---|
/// | `sub` … `endsub` | a subroutine (skipped where the flow reaches it); `endsub` returns |
/// | `call [a] [b] …` | a call; the arguments set #1, #2, … (up to #30) of the call |
/// | `return` | a return from the subroutine |
/// | `if [c]`, `elseif [c]`, `else`, `endif` | an IF's branches |
/// | `while [c]` … `endwhile` | a loop that tests first |
/// | `do` … `while [c]` | a loop that tests last (a `while` with a `do` of its o-word before it) |
/// | `repeat [n]` … `endrepeat` | a loop run n times |
/// | `break`, `continue` | leave the while or do loop of their o-word, go to its end (not a `repeat`'s: rs274 stops there) |
/// Statements pair by their o-word. A value after `endsub` or `return` sets only `#<_value>`,
/// which kin5 does not read (it is the control's): it is read and left. A call of a named
/// subroutine this file does not define runs the file `name.ngc` that defines it, found in the
/// reading's include directories as LinuxCNC searches its SUBROUTINE_PATH (User Manual, "O
/// Codes", "Calling Files"; ../called_files.hpp); without one it is refused, naming the file.
/// Any other line is ordinary, perhaps a parameter setting (`#1 = 5000`, `#<feed> = [#1 * 2]`, `#[#1] = sin[30]`,
/// `#1 = 2 #2 = 3`: LinuxCNC User Manual, "G-code Overview", "Parameters": each value one
/// operand, a number, parameter, function or bracketed expression). rs274 reads every value
/// of a line before it sets any parameter of it; kin5 sets them in order, so a line that sets
/// more than one parameter and reads one is refused (write one setting a line). A line that
/// does not start with `#` (after a block number) is ordinary at its first character.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "../interp/statement.hpp"
#include "../parameters.hpp"
#include "../iso/statements.hpp"
#include "../lexing.hpp"
#include "../text.hpp"
#include "expression.hpp"

namespace kin5::program::linuxcnc {

namespace detail {

/// Whether the part of expression `e` under node `id` reads a parameter.
inline bool reads_parameter(const interp::expression& e, interp::node_id id) {
  if (id == interp::no_node) return false;
  const interp::node& n = e.at(id);
  if (n.kind == interp::node_kind::numbered_parameter || n.kind == interp::node_kind::named_parameter) return true;
  return reads_parameter(e, n.a) || reads_parameter(e, n.b);
}

}  // namespace detail

/// LinuxCNC's statements (see the file comment), over the program `text` (whose lines it is
/// given).
class statements {
 public:
  explicit statements(std::string_view text = {}) : text_(text) {}

  interp::statement statement_of(const text_line& line) const {
    const std::string_view s = line.text;
    const std::size_t end = s.size();
    std::size_t i = iso::detail::after_block_number(s, lexing::skip_blanks(s, 0), end);
    if (i >= end) return {};
    if (s[i] == '#') return assignments(s, i, end, line.number);
    if (s[i] != 'o' && s[i] != 'O') return {};
    return o_word(s, i, end, line);
  }

  /// Whether a line after the program's end starts a called part: LinuxCNC's statements end no
  /// program (its subroutines skip themselves where the flow meets them), so no line comes after.
  static bool starts_called_part(const interp::statement&) { return true; }

  /// A flow error's message in this dialect's terms: the executor's.
  static std::string explain(const std::string& message) { return message; }

 private:
  std::string_view text_;
  mutable std::map<std::string, std::size_t> first_;  // per "o-word keyword": the offset of its first line

  /// The o-word at `i` ("o100", "o<probe>") and the offset after it; empty when none is there.
  static std::string key_at(std::string_view s, std::size_t& i, std::size_t end) {
    std::size_t k = i + 1;
    std::string key = "o";
    if (k < end && s[k] == '<') {
      const std::size_t close = s.find('>', k);
      if (close == std::string_view::npos || close >= end) return {};
      key += named_parameter(s.substr(k + 1, close - k - 1)).substr(1);  // "<name>" of "#<name>"
      if (key.size() <= 3) return {};
      i = close + 1;
      return key;
    }
    long n = 0;
    const std::size_t from = k;
    while (k < end && is_digit(s[k]) && k - from < 9) n = n * 10 + (s[k++] - '0');
    if (k == from) return {};
    i = k;
    return key + std::to_string(n);
  }

  /// The keyword at `i` in lower case, and the offset after it.
  static std::string keyword_at(std::string_view s, std::size_t& i, std::size_t end) {
    i = lexing::skip_blanks(s.substr(0, end), i);
    std::string w;
    while (i < end && is_letter(s[i])) w += static_cast<char>(s[i] >= 'A' && s[i] <= 'Z' ? s[i] - 'A' + 'a' : s[i]), ++i;
    return w;
  }

  /// The offset of the first line of o-word `key` with keyword `keyword` (`do`, `repeat`), or
  /// none; each pair is searched once.
  std::size_t first_line(const std::string& key, const std::string& keyword) const {
    const std::string wanted = key + " " + keyword;
    auto it = first_.find(wanted);
    if (it == first_.end()) {
      std::size_t found = std::string_view::npos;
      for_each_line(text_, [&](const text_line& l) {
        if (found != std::string_view::npos) return;
        const std::string_view s = l.text;
        std::size_t i = iso::detail::after_block_number(s, lexing::skip_blanks(s, 0), s.size());
        if (i >= s.size() || (s[i] != 'o' && s[i] != 'O')) return;
        if (key_at(s, i, s.size()) != key || keyword_at(s, i, s.size()) != keyword) return;
        found = static_cast<std::size_t>(s.data() - text_.data());
      });
      it = first_.emplace(wanted, found).first;
    }
    return it->second;
  }

  /// A bracketed value at `i` (`[#1 LT 3]`), read into `into`; the offset after it, or nothing
  /// after setting `out.error`.
  static std::optional<std::size_t> bracketed(std::string_view s, std::size_t i, std::size_t end, std::size_t line,
                                              const std::string& what, interp::statement& out,
                                              std::optional<interp::expression>& into) {
    i = lexing::skip_blanks(s.substr(0, end), i);
    if (i >= end || s[i] != '[') {
      out = iso::detail::failed(std::move(out), line, i + 1, what + " needs a value in brackets: [ … ]");
      return std::nullopt;
    }
    parsed_expression e = read_value(s.substr(i, end - i), line, i + 1);
    if (!e.ok()) return out.error = e.error, std::nullopt;
    into = std::move(e.tree);
    return i + e.end;
  }

  interp::statement o_word(std::string_view s, std::size_t i, std::size_t end, const text_line& line) const {
    using interp::statement_kind;
    interp::statement out;
    const std::size_t column = i + 1;
    const std::size_t code = iso::detail::code_end(s, end);
    std::string key = key_at(s, i, code);
    if (key.empty())
      return iso::detail::failed(std::move(out), line.number, column,
                                 "an o-word needs a number or a name in angle brackets (o100, o<name>)");
    const std::string shown = key + " " + keyword_at(s, i, code);
    const std::string keyword = shown.substr(key.size() + 1);
    out.key = key;
    std::optional<std::size_t> after = i;
    std::optional<interp::expression> value;  // a return value: read, not used
    if (keyword == "sub") {
      out.kind = statement_kind::subprogram, out.label = key;
    } else if (keyword == "endsub" || keyword == "return") {
      out.kind = statement_kind::return_from_call, out.ends_subprogram = keyword == "endsub";
      const std::size_t v = lexing::skip_blanks(s.substr(0, code), i);
      if (v < code && s[v] == '[') after = bracketed(s, v, code, line.number, shown, out, value);
    } else if (keyword == "call") {
      out.kind = statement_kind::call, out.target = key;
      if (key.size() > 3 && key[1] == '<') out.files = {key.substr(2, key.size() - 3) + ".ngc"};
      for (std::size_t v = lexing::skip_blanks(s.substr(0, code), i); after && v < code && s[v] == '[';
           v = lexing::skip_blanks(s.substr(0, code), *after)) {
        if (out.arguments.size() == 30)
          return iso::detail::failed(std::move(out), line.number, v + 1,
                                     shown + ": more than 30 arguments (they set #1 … #30 of the call)");
        after = bracketed(s, v, code, line.number, shown, out, value);
        if (after) out.arguments.push_back({{"#", static_cast<long>(out.arguments.size() + 1)}, std::move(*value)});
      }
    } else if (keyword == "if" || keyword == "elseif") {
      out.kind = keyword == "if" ? statement_kind::if_branch : statement_kind::else_if_branch;
      after = bracketed(s, i, code, line.number, shown, out, out.condition);
    } else if (keyword == "else") {
      out.kind = statement_kind::else_branch;
    } else if (keyword == "endif") {
      out.kind = statement_kind::end_if;
    } else if (keyword == "while") {
      const std::size_t do_at = first_line(key, "do");
      const bool ends_do = do_at != std::string_view::npos && do_at < static_cast<std::size_t>(s.data() - text_.data());
      out.kind = ends_do ? statement_kind::loop_end : statement_kind::loop_begin;
      out.loop = ends_do ? interp::loop_kind::test_last : interp::loop_kind::test_first;
      after = bracketed(s, i, code, line.number, shown, out, out.condition);
    } else if (keyword == "endwhile") {
      out.kind = statement_kind::loop_end;
    } else if (keyword == "do") {
      out.kind = statement_kind::loop_begin, out.loop = interp::loop_kind::test_last;
    } else if (keyword == "repeat") {
      out.kind = statement_kind::loop_begin, out.loop = interp::loop_kind::counted;
      after = bracketed(s, i, code, line.number, shown, out, out.count);
    } else if (keyword == "endrepeat") {
      out.kind = statement_kind::loop_end, out.loop = interp::loop_kind::counted;
    } else if (keyword == "break" || keyword == "continue") {
      out.kind = keyword == "break" ? statement_kind::loop_break : statement_kind::loop_continue;
      if (first_line(key, "while") == std::string_view::npos && first_line(key, "do") == std::string_view::npos)
        return iso::detail::failed(std::move(out), line.number, column,
                                   shown + ": break and continue name a while or do loop of their o-word, and " + key +
                                       " is none (LinuxCNC stops: \"no matching while/do label\")");
    } else {
      return iso::detail::failed(std::move(out), line.number, column,
                                 "unknown o-word '" + shown + "' (LinuxCNC User Manual, \"O Codes\": sub, endsub, "
                                 "call, return, if, elseif, else, endif, while, endwhile, do, repeat, endrepeat, "
                                 "break, continue)");
    }
    if (!after) return out;
    if (const auto rest = iso::detail::only_comments(s, *after, end, iso::comment_nesting::flat))
      return iso::detail::failed(std::move(out), line.number, rest->column,
                                 rest->message.empty() ? "a word after '" + shown + "': an o-word takes its line alone"
                                                       : rest->message);
    return out;
  }

  static interp::statement assignments(std::string_view s, std::size_t i, std::size_t end, std::size_t line) {
    interp::statement out;
    const std::size_t code = iso::detail::code_end(s, end);
    while (true) {
      const auto after = iso::detail::read_assignment(spelling, false, s, i, code, line, out);
      if (!after) return out;
      i = lexing::skip_blanks(s.substr(0, code), *after);
      while (i < code && s[i] == '(') {  // a comment between settings
        const std::size_t close = s.find(')', i);
        if (close == std::string_view::npos || close >= code) break;
        i = lexing::skip_blanks(s.substr(0, code), close + 1);
      }
      if (i >= code || s[i] != '#') break;
    }
    if (const auto rest = iso::detail::only_comments(s, i, end, iso::comment_nesting::flat))
      return iso::detail::failed(std::move(out), line, rest->column,
                                 rest->message.empty() ? "a word after the parameter assignment on one line is not "
                                                         "supported (write the setting on a line of its own)"
                                                       : rest->message);
    for (std::size_t k = 1; k < out.assignments.size(); ++k) {
      const interp::assignment& a = out.assignments[k];
      const interp::node& target = a.target.at(a.target.root);
      if (detail::reads_parameter(a.value, a.value.root) ||
          (target.kind == interp::node_kind::numbered_parameter && detail::reads_parameter(a.target, target.a))) {
        const std::size_t column = target.where.column;
        return iso::detail::failed(std::move(out), line, column,
                                   "a second parameter setting on a line that reads a parameter: LinuxCNC reads "
                                   "every value of the line before it sets any (write one setting a line)");
      }
    }
    return out;
  }
};

}  // namespace kin5::program::linuxcnc
