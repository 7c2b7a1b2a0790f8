/// @file program/siemens/parameters.hpp
/// R parameters and user variables used as constants (the table: ../parameters.hpp). `R1=5000`
/// and `_F_CUT=5000` assign a number: recorded, and the line passes through (several on one
/// line too: `N20 _X_HOME=-365. _Z_HOME=610.`). `DEF REAL _F_CUT=1850.5, _Z_SAFE` declares
/// variables, the first with its number, the second holding 0 (SINUMERIK 808D/828D Programming
/// Manual, "Local User Data (LUD)": without an assignment "the starting value is zero"); `DEF
/// INT` takes whole numbers only. A later word whose whole value is one of them, `X=R1`,
/// `F=-R1`, `CR=R2`, `Z=_Z_SAFE`, `F=DEPTH` (a name a DEF declared), reads as that number, as if
/// written there (SINUMERIK 840D Fundamentals 10/2004, §2.2 "Value assignments": an address
/// takes a parameter or variable after `=`). Names read in upper case. Refused, naming the line
/// and column: an assignment of anything but a number (`R2=R1*2`: arithmetic), a fraction for an
/// INT, a use with no number assigned above, and a parameter inside an expression (`X=R1+2`, the
/// reader's `expressions and parameters …` error). Jumps and loops (`GOTOF`, `WHILE`, …) are
/// refused by the reader, so a value never depends on the path.
#pragma once

#include <cmath>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "../lexing.hpp"
#include "../number.hpp"
#include "../parameters.hpp"
#include "../text.hpp"
#include "lexer.hpp"
#include "vocabulary.hpp"
#include "words.hpp"

namespace kin5::program::siemens::detail {

/// The R parameters and user variables of one file, read line by line before the words get
/// their meaning.
class constants {
 public:
  /// Records the assignments and declarations of `words` (line `line`, text `text`) and puts the
  /// number of each parameter or variable a word uses in its place; a word refused here is
  /// reported in `p` and removed. `p.only_assignments` says that the line does nothing else.
  void read(std::size_t line, std::string_view text, std::vector<word>& words, line_parse& p) {
    substituted_.clear();
    if (declare(line, text, words, p)) return;
    std::size_t kept = 0, assignments = 0, others = 0;
    for (word& w : words) {
      bool keep = true;
      if (is_assignment(w)) {
        keep = assign(w, line, text, p);
        ++assignments;
      } else {
        others += w.kind == word_kind::comment || (w.kind == word_kind::address && w.letter == 'N') ? 0 : 1;
        if (uses_value(w)) keep = substitute(w, line, p);
      }
      if (keep) words[kept++] = w;
    }
    words.resize(kept);
    p.only_assignments = assignments > 0 && others == 0;
  }

 private:
  enum class type : unsigned char { real, integer };
  parameter_table table_{"R"};                           // R by number, variables by name
  std::map<std::string, type, std::less<>> declared_;   // what DEF REAL / DEF INT declared
  std::deque<std::string> substituted_;                 // the numbers put into this line's words

  /// A variable's name: `_` then name characters, or a name a DEF declared.
  bool is_variable(std::string_view name) const {
    if (name.size() < 2) return false;
    if (name[0] == '_') return true;
    return declared_.find(name) != declared_.end();
  }

  bool is_assignment(const word& w) const {
    if (w.kind == word_kind::address) return w.letter == 'R' && !w.extension.empty() && w.assigned;
    if (w.kind == word_kind::system) return w.assigned && w.value != value_kind::none && !w.name.empty() && w.name[0] == '_';
    return w.kind == word_kind::keyword && w.assigned && w.value == value_kind::run && declared_.count(w.name) > 0;
  }

  /// `X=R1`, `X=-_Z`, `F=DEPTH`: a word whose whole value is one R parameter (`n`) or variable
  /// (`name`, upper case).
  bool uses_value(const word& w, long* n = nullptr, std::string* name = nullptr, bool* negated = nullptr) const {
    if (!w.assigned || w.value != value_kind::expression) return false;
    std::string_view v = w.text;
    const bool minus = !v.empty() && v[0] == '-';
    if (!v.empty() && (v[0] == '-' || v[0] == '+')) v.remove_prefix(1);
    if (v.empty() || !(is_letter(v[0]) || v[0] == '_')) return false;
    for (char c : v)
      if (!is_ident_char(c)) return false;
    if (negated) *negated = minus;
    const bool r = v.size() >= 2 && v.size() <= 7 && to_upper(v[0]) == 'R' &&
                   v.substr(1).find_first_not_of("0123456789") == std::string_view::npos;
    if (r) {
      if (n) *n = number_of(v.substr(1));
      if (name) name->clear();
      return true;
    }
    const std::string upper = lexing::upper(v);
    if (!is_variable(upper)) return false;
    if (name) *name = upper;
    return true;
  }

  static long number_of(std::string_view digits) {
    long n = 0;
    for (char c : digits.substr(0, 7)) n = n * 10 + (c - '0');
    return n;
  }

  static void error(line_parse& p, std::size_t line, std::size_t column, std::string message) {
    keep_or_count(p.errors, p.errors_not_kept, {{p.b.where.file, line, column + 1}, std::move(message)});
  }

  static std::size_t column_of(std::string_view part, std::string_view text, std::size_t fallback) {
    return part.empty() ? fallback : static_cast<std::size_t>(part.data() - text.data());
  }

  /// Why `number` (`written`) may not be assigned to variable `name` (empty: it may).
  std::string unfit(const std::string& name, double number, std::string_view written) const {
    const auto it = declared_.find(name);
    if (it == declared_.end() || it->second != type::integer || std::floor(number) == number) return "";
    return "variable " + name + " is an INT: " + std::string(written) + " is not a whole number";
  }

  /// `Rn=…`, `_NAME=…`: a number is recorded (the word stays, for the pass-through); anything
  /// else is refused.
  bool assign(const word& w, std::size_t line, std::string_view text, line_parse& p) {
    const bool r = w.kind == word_kind::address;
    const long n = r ? number_of(w.extension) : 0;
    const std::string shown = r ? "parameter " + table_.name(n) : "variable " + w.name;
    const std::string_view v = w.text;
    const parsed_number number = read_number(v);
    const std::size_t column = column_of(v, text, w.column);
    std::string why;
    if (number.error == number_error::none && number.length > 0 && number.length == v.size()) {
      if (!r) why = unfit(w.name, number.value, v);
      if (why.empty()) {
        if (r) table_.assign(n, parameter_literal{number.value, std::string(v)}, line);
        else table_.assign(w.name, parameter_literal{number.value, std::string(v)}, line);
        p.b.assignment = true;
        return true;
      }
    }
    if (r) table_.refuse(n, line);
    else table_.refuse(w.name, line);
    error(p, line, column,
          why.empty() ? shown + " is assigned an expression: only a number is read (arithmetic is not supported)" : why);
    return false;
  }

  /// A word that uses a parameter or variable takes its number; false (reported, unless its
  /// assignment was refused) when it has none.
  bool substitute(word& w, std::size_t line, line_parse& p) {
    long n = 0;
    std::string name;
    bool negated = false;
    uses_value(w, &n, &name, &negated);
    std::string why;
    const parameter_literal* v = name.empty() ? table_.value(n, why) : table_.value(name, why, "variable");
    if (!v) {
      if (!why.empty()) error(p, line, w.column, why);
      return false;
    }
    const parameter_literal number = negated ? v->negated() : *v;
    substituted_.push_back(number.written);
    w.value = value_kind::number;
    w.number = number.value;
    w.text = substituted_.back();
    return true;
  }

  /// `DEF REAL a, b=2.5`, `DEF INT n=3` (after a block number): the names declared, each holding
  /// its number or 0; true when the line is a DEF (it passes through as it is). Another type, or
  /// an attribute before the type, declares nothing kin5 reads: a use of its names is refused.
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
    if (kind != "REAL" && kind != "INT") return true;
    const type t = kind == "INT" ? type::integer : type::real;
    p.b.assignment = true;
    for (;;) {
      const std::string name = name_at(i);
      if (name.size() < 2 || !(is_letter(name[0]) || name[0] == '_')) return true;
      i = lexing::skip_blanks(text, i);
      if (i < text.size() && text[i] == '[') return true;  // an array: not a constant
      declared_[name] = t;
      if (i < text.size() && text[i] == '=') {
        const std::size_t v = lexing::skip_blanks(text, i + 1);
        const parsed_number number = read_number(text.substr(v));
        const std::size_t after = lexing::skip_blanks(text, v + number.length);
        const bool ends = after == text.size() || text[after] == ',' || text[after] == ';';
        std::string why = number.error == number_error::none && number.length > 0 && ends
                              ? unfit(name, number.value, text.substr(v, number.length))
                              : "variable " + name + " is assigned an expression: only a number is read "
                                                     "(arithmetic is not supported)";
        if (!why.empty()) {
          table_.refuse(name, line);
          error(p, line, v, std::move(why));
          return true;
        }
        table_.assign(name, parameter_literal{number.value, std::string(text.substr(v, number.length))}, line);
        i = after;
      } else {
        table_.assign(name, parameter_literal{0, "0"}, line);
      }
      if (i >= text.size() || text[i] != ',') return true;
      ++i;
    }
  }
};

}  // namespace kin5::program::siemens::detail
