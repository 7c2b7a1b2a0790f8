/// @file program/siemens/parameters.hpp
/// R parameters used as constants (the table: ../parameters.hpp). `R1=5000` assigns a number:
/// recorded, and the line passes through (`changes_nothing`); a later word whose whole value is
/// the parameter, `X=R1`, `F=-R1`, `CR=R2`, `A3=R3`, reads as that number, as if written there
/// (SINUMERIK 840D Fundamentals 10/2004, §2.2 "Value assignments": an address takes a parameter
/// after `=`). Refused, naming the line and column: an assignment of anything but a number
/// (`R2=R1*2`: arithmetic), a use with no number assigned above, and a parameter inside an
/// expression (`X=R1+2`, the reader's `expressions and parameters …` error). Jumps and loops
/// (`GOTOF`, `WHILE`, …) are refused by the reader, so a value never depends on the path.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "../lexing.hpp"
#include "../number.hpp"
#include "../parameters.hpp"
#include "../text.hpp"
#include "lexer.hpp"
#include "words.hpp"

namespace kin5::program::siemens::detail {

/// The R parameters of one file, read line by line before the words get their meaning.
class r_parameters {
 public:
  /// Records the assignments of `words` (line `line`, text `text`) and puts the number of each
  /// parameter a word uses in its place; a word refused here is reported in `p` and removed.
  void read(std::size_t line, std::string_view text, std::vector<word>& words, line_parse& p) {
    substituted_.clear();
    std::size_t kept = 0;
    for (word& w : words) {
      const bool keep = is_assignment(w) ? assign(w, line, text, p) : !uses_parameter(w) || substitute(w, line, p);
      if (keep) words[kept++] = w;
    }
    words.resize(kept);
  }

 private:
  parameter_table table_{"R"};
  std::deque<std::string> substituted_;  // the numbers put into this line's words

  static bool is_assignment(const word& w) {
    return w.kind == word_kind::address && w.letter == 'R' && !w.extension.empty() && w.assigned;
  }

  /// `X=R1`, `X=-R1`: a word whose whole value is one R parameter (its number in `n`).
  static bool uses_parameter(const word& w, long* n = nullptr, bool* negated = nullptr) {
    if (!w.assigned || w.value != value_kind::expression) return false;
    std::string_view v = w.text;
    const bool minus = !v.empty() && v[0] == '-';
    if (!v.empty() && (v[0] == '-' || v[0] == '+')) v.remove_prefix(1);
    if (v.size() < 2 || v.size() > 7 || to_upper(v[0]) != 'R') return false;
    long number = 0;
    for (char c : v.substr(1)) {
      if (!is_digit(c)) return false;
      number = number * 10 + (c - '0');
    }
    if (n) *n = number;
    if (negated) *negated = minus;
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

  /// `Rn=…`: a number is recorded (the word stays, for `changes_nothing`); anything else is refused.
  bool assign(const word& w, std::size_t line, std::string_view text, line_parse& p) {
    const long n = number_of(w.extension);
    const std::string_view v = w.text;
    const parsed_number number = read_number(v);
    if (number.error == number_error::none && number.length > 0 && number.length == v.size()) {
      table_.assign(n, parameter_literal{number.value, std::string(v)}, line);
      p.b.assignment = true;
      return true;
    }
    table_.refuse(n, line);
    const std::size_t column = v.empty() ? w.column : static_cast<std::size_t>(v.data() - text.data());
    error(p, line, column, "parameter " + table_.name(n) + " is assigned an expression: only a number is read "
                                                          "(arithmetic is not supported)");
    return false;
  }

  /// A word that uses a parameter takes its number; false (reported, unless the parameter's
  /// assignment was refused) when it has none.
  bool substitute(word& w, std::size_t line, line_parse& p) {
    long n = 0;
    bool negated = false;
    uses_parameter(w, &n, &negated);
    std::string why;
    const parameter_literal* v = table_.value(n, why);
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
};

}  // namespace kin5::program::siemens::detail
