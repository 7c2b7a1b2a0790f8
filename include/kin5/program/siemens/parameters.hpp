/// @file program/siemens/parameters.hpp
/// R parameters and user variables as the program runs (SINUMERIK 840D sl Programming Manual
/// Fundamentals, "Arithmetic parameters (R)"; Job Planning, "Flexible NC programming":
/// "Variables", "Definition of user variables (DEF)", "Arithmetic functions"), with the values of
/// the executor's parameter store (../interp/parameter_store.hpp, parameter_rules.hpp):
/// - `R1=R1+0.5`, `_F_CUT=R5*2`, `DEPTH=DEPTH-1` (a name a DEF declared): the expression is
///   evaluated and assigned, in the order written; several on one line too.
/// - `DEF REAL a, b=2.5*R1`, `DEF INT n=3`, `DEF BOOL f=TRUE`: declared, each holding its value
///   or 0 ("Local User Data": without an assignment "the starting value is zero"). An INT takes
///   whole numbers only (a fraction is refused, not rounded), a BOOL 1 for any value but 0. Other
///   types and arrays declare nothing kin5 reads: a use of their names is refused.
/// - `X=R1*2`, `F=R5`, `CR=_R`, `A3=…`: a word whose value is an expression reads as its value
///   (Fundamentals, "Value assignments": an address takes an expression after `=`).
/// Refused, naming the line and column: an expression that cannot be read or evaluated (a
/// parameter without a value, a system variable `$AA_IM[X]`, a division by zero: the evaluator's
/// messages), and a fraction for an INT. `IC()`, `AC()` and the rotary positioning functions
/// (`DC()`, `ACP()`, `ACN()`) are left to words.hpp.
///
/// A line of assignments only passes through (`assignment`); where a value was an expression the
/// block's text has the number in its place (`R2=R1*2` becomes `R2=10`), so that the executed
/// program says the values it ran with and reads back alone, whatever ran before it.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../interp/evaluate.hpp"
#include "../interp/parameter_store.hpp"
#include "../lexing.hpp"
#include "../number.hpp"
#include "../text.hpp"
#include "expression.hpp"
#include "lexer.hpp"
#include "vocabulary.hpp"
#include "words.hpp"

namespace kin5::program::siemens::detail {

/// `v` as the shortest plain number that reads back as `v` (no exponent: the 840D reads none).
inline std::string plain_number_text(double v) {
  char buffer[400];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed);
  return r.ec == std::errc{} ? std::string(buffer, r.ptr) : std::to_string(v);
}

/// The R parameters and user variables of one running program (see the file comment).
class variables {
 public:
  explicit variables(interp::parameter_store& store) : store_(store) {}

  /// Runs the assignments and declarations of `words` (line `line`, text `text`) and puts the
  /// value of each expression a word holds in its place; a word refused here is reported in `p`
  /// and removed. `p.only_assignments` says that the line does nothing else; `p.b.text` gets the
  /// assigned numbers in place of their expressions.
  void read(std::size_t line, std::string_view text, std::vector<word>& words, line_parse& p) {
    substituted_.clear();
    edits_.clear();
    if (declare(line, text, words, p)) return;
    std::size_t kept = 0, assignments = 0, others = 0;
    for (word& w : words) {
      bool keep = true;
      if (is_assignment(w)) {
        keep = assign(w, line, text, p);
        ++assignments;
      } else {
        others += w.kind == word_kind::comment || (w.kind == word_kind::address && w.letter == 'N') ? 0 : 1;
        if (holds_expression(w)) keep = substitute(w, line, text, p);
      }
      if (keep) words[kept++] = w;
    }
    words.resize(kept);
    p.only_assignments = assignments > 0 && others == 0;
    if (p.only_assignments && !edits_.empty()) p.b.text = edited(p.b.text, text);
  }

 private:
  enum class type : unsigned char { real, integer, boolean };
  interp::parameter_store& store_;
  std::map<std::string, type, std::less<>> declared_;  // what DEF REAL / INT / BOOL declared
  std::deque<std::string> substituted_;                // the numbers put into this line's words
  std::vector<std::pair<std::string_view, std::string>> edits_;  // an expression's text, its number

  /// The line's text with each edited expression replaced by its number.
  std::string edited(const std::string& block_text, std::string_view text) const {
    if (block_text.size() != text.size()) return block_text;  // the same line (its label blanked in `text`)
    std::string out;
    std::size_t at = 0;
    for (const auto& [part, number] : edits_) {
      const auto from = static_cast<std::size_t>(part.data() - text.data());
      out.append(std::string_view(block_text).substr(at, from - at));
      out += number;
      at = from + part.size();
    }
    out.append(std::string_view(block_text).substr(at));
    return out;
  }

  bool is_assignment(const word& w) const {
    if (w.kind == word_kind::address) return w.letter == 'R' && !w.extension.empty() && w.assigned;
    if (w.kind == word_kind::system) return w.assigned && w.value != value_kind::none && !w.name.empty() && w.name[0] == '_';
    return w.kind == word_kind::keyword && w.assigned && w.value == value_kind::run && declared_.count(w.name) > 0;
  }

  /// `X=R1*2`, `F=-_F`, `CR=R2`: a word whose value, after `=`, is an expression kin5 evaluates
  /// (IC(), AC() and the positioning functions are words.hpp's).
  static bool holds_expression(const word& w) {
    if (!w.assigned || w.value != value_kind::expression) return false;
    const std::string v = lexing::upper(w.text.substr(0, 5));
    for (std::string_view f : {"IC(", "AC(", "DC(", "ACP(", "ACN(", "CIC("})
      if (v.rfind(f, 0) == 0) return false;
    for (std::string_view f : {"NAN", "INF", "-NAN", "-INF", "+NAN", "+INF"})
      if (v.rfind(f, 0) == 0 && (w.text.size() == f.size() || lexing::upper(w.text) == "INFINITY")) return false;
    return true;
  }

  static void error(line_parse& p, std::size_t line, std::size_t column, std::string message) {
    keep_or_count(p.errors, p.errors_not_kept, {{p.b.where.file, line, column}, std::move(message)});
  }

  static std::size_t column_of(std::string_view part, std::string_view text, std::size_t fallback) {
    return part.empty() ? fallback : static_cast<std::size_t>(part.data() - text.data());
  }

  /// The value of the expression `v` (at 0-based `column` of `line`), or reported and none.
  std::optional<double> value_of(std::string_view v, std::size_t line, std::size_t column, line_parse& p) const {
    const parsed_expression e = parse_expression(spelling, v, line, column + 1, true);
    if (!e.ok()) {
      error(p, line, e.error->where.column, e.error->message);
      return std::nullopt;
    }
    const interp::evaluation r = interp::evaluate(e.tree, store_);
    if (!r.ok()) {
      error(p, line, r.error->where.column, r.error->message);
      return std::nullopt;
    }
    return r.value;
  }

  /// Why `value` may not be assigned to variable `name` (empty: it may), and the value it takes.
  std::string unfit(const std::string& name, double& value, std::string_view written) const {
    const auto it = declared_.find(name);
    if (it == declared_.end()) return "";
    if (it->second == type::boolean) value = value != 0 ? 1 : 0;
    if (it->second != type::integer || std::floor(value) == value) return "";
    return "variable " + name + " is an INT: " + std::string(written) + " is not a whole number";
  }

  /// `Rn=…`, `_NAME=…`, `NAME=…`: the value is assigned (the word stays, for the pass-through).
  bool assign(const word& w, std::size_t line, std::string_view text, line_parse& p) {
    const bool r = w.kind == word_kind::address;
    const interp::parameter_key key = r ? interp::parameter_key{"R", number_of(w.extension)}
                                        : interp::parameter_key{"", 0, w.name};
    const std::string_view v = w.text;
    const std::size_t column = column_of(v, text, w.column);
    if (v.empty()) {
      error(p, line, w.column + 1, "word '" + key.shown() + "=' has no value");
      return false;
    }
    auto value = value_of(v, line, column, p);
    if (!value) return false;
    const parsed_number literal = read_number(v);
    const bool plain = literal.error == number_error::none && literal.length == v.size();
    std::string written = plain ? std::string(v) : plain_number_text(*value);
    if (std::string why = r ? "" : unfit(w.name, *value, written); !why.empty()) {
      error(p, line, column + 1, why);
      return false;
    }
    if (auto why = store_.assign(key, *value)) {
      error(p, line, w.column + 1, *why);
      return false;
    }
    if (!plain) edits_.emplace_back(v, plain_number_text(*value));
    p.b.assignment = true;
    return true;
  }

  static long number_of(std::string_view digits) {
    long n = 0;
    for (char c : digits.substr(0, 7)) n = n * 10 + (c - '0');
    return n;
  }

  /// A word whose value is an expression takes its number; false (reported) when it has none.
  bool substitute(word& w, std::size_t line, std::string_view text, line_parse& p) {
    const auto value = value_of(w.text, line, column_of(w.text, text, w.column), p);
    if (!value) return false;
    substituted_.push_back(plain_number_text(*value));
    w.value = std::isfinite(*value) ? value_kind::number : value_kind::out_of_range;
    w.number = *value;
    w.text = substituted_.back();
    return true;
  }

  /// `DEF REAL a, b=2.5`, `DEF INT n=3`, `DEF BOOL f` (after a block number): the names
  /// declared, each holding its value or 0; true when the line is a DEF (it passes through as
  /// it is). Another type, or an attribute before the type, declares nothing kin5 reads.
  bool declare(std::size_t line, std::string_view text, const std::vector<word>& words, line_parse& p) {
    std::size_t first = 0;
    if (!words.empty() && words[0].kind == word_kind::address && words[0].letter == 'N') first = 1;
    if (words.size() <= first || words[first].kind != word_kind::keyword || words[first].name != "DEF") return false;
    std::size_t i = words[first].column + 3;
    const auto name_at = [&](std::size_t& k) {
      k = lexing::skip_blanks(text, k);
      const std::size_t start = k;
      while (k < text.size() && is_ident_char(text[k])) ++k;
      return lexing::upper(text.substr(start, k - start));
    };
    const std::string kind = name_at(i);
    if (kind != "REAL" && kind != "INT" && kind != "BOOL") return true;
    const type t = kind == "INT" ? type::integer : kind == "BOOL" ? type::boolean : type::real;
    p.b.assignment = true;
    for (;;) {
      const std::string name = name_at(i);
      if (name.size() < 2 || !(is_letter(name[0]) || name[0] == '_')) return true;
      i = lexing::skip_blanks(text, i);
      if (i < text.size() && text[i] == '[') return true;  // an array: not read
      declared_[name] = t;
      double value = 0;
      if (i < text.size() && text[i] == '=') {
        const std::size_t v = lexing::skip_blanks(text, i + 1);
        const parsed_expression e = parse_expression(spelling, text.substr(v), line, v + 1, false);
        if (!e.ok()) return error(p, line, e.error->where.column, e.error->message), true;
        const std::size_t after = lexing::skip_blanks(text, v + e.end);
        if (after < text.size() && text[after] != ',' && text[after] != ';')
          return error(p, line, after + 1, "DEF: unexpected '" + std::string(text.substr(after, 1)) + "' after the value of " + name), true;
        const interp::evaluation r = interp::evaluate(e.tree, store_);
        if (!r.ok()) return error(p, line, r.error->where.column, r.error->message), true;
        value = r.value;
        if (std::string why = unfit(name, value, text.substr(v, e.end)); !why.empty())
          return error(p, line, v + 1, std::move(why)), true;
        i = after;
      }
      if (auto why = store_.assign({"", 0, name}, value)) return error(p, line, i + 1, *why), true;
      if (i >= text.size() || text[i] != ',') return true;
      ++i;
    }
  }
};

}  // namespace kin5::program::siemens::detail
