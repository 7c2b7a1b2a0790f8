/// @file program/expression_parser.hpp
/// Reading expressions into the interpreter's tree (interp/expression.hpp), shared by the
/// dialects' spellings: a precedence-climbing parser driven by a table (`expression_spelling`)
/// that each dialect fills from its manual (`program/<dialect>/expression.hpp`): brackets,
/// binary operators with their levels (higher binds tighter; equal levels bind left to right),
/// functions, prefix operators and constants, and how parameters are written. A sign binds to
/// the operand right after it (`-2**2` is 4 in LinuxCNC, whose interpreter reads it so), and a
/// spelling that cannot tell which reading its control takes refuses the construct and says to
/// write brackets (`power_needs_brackets`: Heidenhain's `2^3^2`, `-2^2`, `SQ 2^3`, `SIN(Q1)^2`).
///
/// Nesting is bounded (`interp::max_expression_depth`), checked before each level is entered,
/// so that no input, however deep, exhausts the stack. Errors carry the span of the offending
/// text; nothing is thrown.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "interp/expression.hpp"
#include "lexing.hpp"
#include "number.hpp"
#include "parameters.hpp"
#include "text.hpp"

namespace kin5::program {

/// A binary operator as a dialect writes it (`**`, `MOD`, `<>`), its meaning and its level.
struct operator_spelling {
  std::string_view text;  ///< upper case; a word (`MOD`) must not run on into a letter
  interp::binary_op op;
  int level = 0;          ///< higher binds tighter
  double tolerance = 0;   ///< for equal / not_equal (`interp::node::tolerance`)
};

/// A function as a dialect writes it (`FIX`, `POT`) and its meaning.
struct function_spelling {
  std::string_view name;  ///< upper case
  interp::function_kind kind;
};

/// A prefix operator written as a word (`NOT`, `B_NOT`, Heidenhain `NEG`).
struct prefix_spelling {
  std::string_view name;
  interp::unary_op op;
};

/// A named constant (Heidenhain `PI`).
struct constant_spelling {
  std::string_view name;
  double value;
};

/// How one dialect writes expressions (see the file comment).
struct expression_spelling {
  char open = '[', close = ']';
  std::span<const operator_spelling> operators;  ///< a longer text before its prefixes (`<>` before `<`)
  std::span<const function_spelling> functions;
  std::span<const prefix_spelling> prefixes{};
  std::span<const constant_spelling> constants{};
  char separator = 0;                 ///< between two arguments (`ATAN2(y, x)`), 0 for none
  bool slash_second_argument = false; ///< `ATAN[y]/[x]`
  bool functions_without_brackets = false;  ///< `SIN Q3` (Heidenhain)
  bool power_needs_brackets = false;  ///< refuse `a^b^c`, `-a^b`, `SIN a^b`
  // Parameters:
  bool hash_numbers = false;          ///< `#1`, `#[#1+1]`
  bool hash_indirect = false;         ///< `##1`: the parameter whose number #1 holds
  bool hash_names = false;            ///< `#<name>` (read as `named_parameter` does)
  double number_tolerance = 0;        ///< a parameter number within this of a whole one is it
  std::span<const std::string_view> letter_prefixes{};  ///< `R`, `Q`, `QL`, `QR`: prefix and digits
  bool names_are_parameters = false;  ///< any other name is a named parameter (upper case)
  char system_prefix = 0;             ///< `$`: a name that starts with it is the machine's state, refused
  std::string_view dialect;           ///< for messages: "LinuxCNC"
};

/// An expression read from text: the tree and where reading stopped, or the error.
struct parsed_expression {
  interp::expression tree;
  std::size_t end = 0;  ///< offset in the text after the expression
  std::optional<interp::expression_error> error{};
  bool ok() const { return !error; }
};

/// The parser over one piece of text; `operand` and `expression` may be called in turn by a
/// dialect reading a statement (Heidenhain `FN 1: Q1 = a + b`).
class expression_parser {
 public:
  /// `text` starts at 1-based `column` of `line`.
  expression_parser(const expression_spelling& s, std::string_view text, std::size_t line = 1, std::size_t column = 1)
      : s_(s), text_(text), line_(line), column_(column) {}

  /// A whole expression (every operator), from the current position.
  interp::node_id expression() { return level(0); }

  /// One operand: a number, parameter, function, bracketed expression, each with its signs.
  interp::node_id operand() { return unary(); }

  /// The current offset, after blanks.
  std::size_t position() {
    skip();
    return i_;
  }
  void seek(std::size_t i) { i_ = i; }

  /// Whether the word `w` (upper case) is next; consumed when it is.
  bool take_word(std::string_view w) {
    skip();
    if (!at_word(w)) return false;
    i_ += w.size();
    return true;
  }
  /// Whether the character `c` is next; consumed when it is.
  bool take(char c) {
    skip();
    if (i_ >= text_.size() || text_[i_] != c) return false;
    ++i_;
    return true;
  }

  interp::expression& tree() { return tree_; }
  const std::optional<interp::expression_error>& error() const { return error_; }
  bool failed() const { return error_.has_value(); }

  /// Records an error at offsets [from, to) (the first one is kept).
  interp::node_id fail(std::size_t from, std::size_t to, std::string message) {
    if (!error_) error_ = interp::expression_error{span_of(from, to), std::move(message)};
    return interp::no_node;
  }

  interp::span span_of(std::size_t from, std::size_t to) const {
    return {line_, column_ + from, to > from ? to - from : 1};
  }

 private:
  static bool ident(char c) { return is_letter(c) || is_digit(c) || c == '_'; }

  void skip() {
    while (i_ < text_.size() && is_space(text_[i_])) ++i_;
  }

  bool at_word(std::string_view w) const {
    if (!starts_with_keyword(text_.substr(i_), w)) return false;
    const bool word = is_letter(w.back()) || w.back() == '_';
    return !word || i_ + w.size() >= text_.size() || !(is_letter(text_[i_ + w.size()]) || text_[i_ + w.size()] == '_');
  }

  /// Enters one level of nesting: false (an error recorded) past the bound.
  bool nest(std::size_t at) {
    if (++nesting_ <= interp::max_expression_depth) return true;
    fail(at, at + 1, "expression nested more than " + std::to_string(interp::max_expression_depth) + " levels deep");
    return false;
  }

  interp::node_id checked(interp::node_id id) {
    if (id == interp::no_node || failed()) return interp::no_node;
    if (tree_.at(id).depth > interp::max_expression_depth) {
      const interp::span w = tree_.at(id).where;
      if (!error_)
        error_ = interp::expression_error{w, "expression nested more than " + std::to_string(interp::max_expression_depth) +
                                                 " levels deep"};
      return interp::no_node;
    }
    return id;
  }

  const operator_spelling* peek_operator() {
    skip();
    for (const operator_spelling& o : s_.operators)
      if (at_word(o.text)) return &o;
    return nullptr;
  }

  interp::node_id level(int min_level) {
    const std::size_t start = position();
    if (!nest(start)) return interp::no_node;
    const bool left_bracketed = start < text_.size() && text_[start] == s_.open;
    interp::node_id left = unary();
    bool power_before = false;
    while (!failed()) {
      const operator_spelling* o = peek_operator();
      if (!o || o->level < min_level) break;
      const std::size_t at = i_;
      const bool power = o->op == interp::binary_op::power;
      if (power && s_.power_needs_brackets) {
        const interp::node& l = tree_.at(left);
        if (power_before || (!left_bracketed && (l.kind == interp::node_kind::unary || l.kind == interp::node_kind::function)))
          return fail(at, at + o->text.size(),
                      "'" + std::string(o->text) + "' after a sign, a function or another power: " + std::string(s_.dialect) +
                          "'s manual does not say which is calculated first; write brackets");
      }
      i_ += o->text.size();
      const interp::node_id right = level(o->level + 1);
      if (failed()) break;
      left = checked(tree_.binary(o->op, left, right, span_of(at, at + o->text.size()), o->tolerance));
      power_before = power;
    }
    --nesting_;
    return failed() ? interp::no_node : left;
  }

  interp::node_id unary() {
    const std::size_t at = position();
    const bool sign = at < text_.size() && (text_[at] == '-' || text_[at] == '+');
    const prefix_spelling* p = sign ? nullptr : prefix_at();
    if (!sign && !p) return primary();
    if (!nest(at)) return interp::no_node;
    const std::size_t length = sign ? 1 : p->name.size();
    i_ += length;
    const interp::node_id x = unary();
    interp::node_id out = interp::no_node;
    if (!failed()) {
      const interp::unary_op op = p ? p->op : text_[at] == '-' ? interp::unary_op::negate : interp::unary_op::plus;
      out = checked(tree_.unary(op, x, span_of(at, at + length)));
    }
    --nesting_;
    return failed() ? interp::no_node : out;
  }

  const prefix_spelling* prefix_at() const {
    for (const prefix_spelling& p : s_.prefixes)
      if (at_word(p.name)) return &p;
    return nullptr;
  }

  interp::node_id bracketed(std::size_t at) {
    ++i_;  // the opening bracket
    const interp::node_id x = level(0);
    if (failed()) return interp::no_node;
    if (!take(s_.close))
      return fail(position(), position() + 1,
                  std::string("expected '") + s_.close + "' to close the '" + s_.open + "' at column " + std::to_string(column_ + at));
    return x;
  }

  interp::node_id primary() {
    const std::size_t at = position();
    if (at >= text_.size()) return fail(at, at, "expected a value: the expression ends here");
    const char c = text_[at];
    if (c == s_.open) return bracketed(at);
    if (is_digit(c) || c == '.') {
      const parsed_number n = read_number(text_.substr(at));
      if (n.error != number_error::none || n.length == 0) return fail(at, at + 1, "not a number");
      i_ = at + n.length;
      return tree_.number(n.value, span_of(at, i_));
    }
    if (c == '#' && (s_.hash_numbers || s_.hash_names)) return hash_parameter(at);
    if (is_letter(c) || c == '_' || (s_.system_prefix && c == s_.system_prefix)) return word(at);
    return fail(at, at + 1, std::string("expected a number, a parameter, a function or '") + s_.open + "', not '" + c + "'");
  }

  interp::node_id hash_parameter(std::size_t at) {
    ++i_;
    skip();
    if (s_.hash_names && i_ < text_.size() && text_[i_] == '<') {
      const std::size_t close = text_.find('>', i_);
      if (close == std::string_view::npos) return fail(at, text_.size(), "'#<' without its '>'");
      const std::string name = named_parameter(text_.substr(i_ + 1, close - i_ - 1));
      i_ = close + 1;
      return tree_.named_parameter(name, span_of(at, i_));
    }
    if (!s_.hash_numbers) return fail(at, at + 1, "'#' without '<name>'");
    interp::node_id number = interp::no_node;
    const std::size_t n_at = i_;
    if (i_ < text_.size() && is_digit(text_[i_])) {
      std::size_t k = i_;
      while (k < text_.size() && (is_digit(text_[k]) || text_[k] == '.')) ++k;
      const parsed_number n = read_number(text_.substr(i_, k - i_));
      if (n.error != number_error::none || n.length != k - i_) return fail(i_, k, "not a parameter number");
      number = tree_.number(n.value, span_of(i_, k));
      i_ = k;
    } else if (i_ < text_.size() && text_[i_] == s_.open) {
      number = bracketed(i_);
    } else if (s_.hash_indirect && i_ < text_.size() && text_[i_] == '#') {
      if (!nest(i_)) return interp::no_node;
      number = hash_parameter(i_);
      --nesting_;
    } else {
      return fail(at, n_at + 1, "'#' without a parameter number");
    }
    if (failed()) return interp::no_node;
    return checked(tree_.numbered_parameter("#", number, span_of(at, i_), s_.number_tolerance));
  }

  interp::node_id word(std::size_t at) {
    std::size_t k = at + 1;
    while (k < text_.size() && ident(text_[k])) ++k;
    const std::string name = lexing::upper(text_.substr(at, k - at));
    if (s_.system_prefix && name[0] == s_.system_prefix)
      return fail(at, k, "system variable " + name + " is the machine's state, not fixed by the program");
    for (const function_spelling& f : s_.functions)
      if (name == f.name) {
        i_ = k;
        return call(f, at);
      }
    for (const constant_spelling& c : s_.constants)
      if (name == c.name) {
        i_ = k;
        return tree_.number(c.value, span_of(at, k));
      }
    for (std::string_view p : s_.letter_prefixes)
      if (name.size() > p.size() && name.compare(0, p.size(), p) == 0 &&
          name.find_first_not_of("0123456789", p.size()) == std::string::npos && name.size() - p.size() <= 9) {
        i_ = k;
        const interp::node_id number = tree_.number(static_cast<double>(std::stol(name.substr(p.size()))), span_of(at + p.size(), k));
        return checked(tree_.numbered_parameter(std::string(p), number, span_of(at, k)));
      }
    if (s_.names_are_parameters && (name.size() > 1 || name[0] == '_')) {
      i_ = k;
      return tree_.named_parameter(name, span_of(at, k));
    }
    return fail(at, k, "'" + name + "' is no function, operator or parameter of " + std::string(s_.dialect) + " expressions");
  }

  interp::node_id call(const function_spelling& f, std::size_t at) {
    const std::size_t name_end = i_;
    const int n = interp::arity(f.kind);
    interp::node_id first = interp::no_node, second = interp::no_node;
    skip();
    const bool open = i_ < text_.size() && text_[i_] == s_.open;
    if (!open && !s_.functions_without_brackets)
      return fail(at, name_end, std::string(f.name) + " takes its argument in '" + s_.open + " " + s_.close + "'");
    if (!open && !nest(at)) return interp::no_node;  // with brackets, their expression is the level
    if (f.kind == interp::function_kind::exists) {
      ++i_;
      const std::size_t p = position();
      first = primary();
      if (!failed() && tree_.at(first).kind != interp::node_kind::named_parameter &&
          tree_.at(first).kind != interp::node_kind::numbered_parameter)
        return fail(p, i_, std::string(f.name) + " takes a parameter");
      if (!failed() && !take(s_.close)) return fail(position(), position() + 1, std::string("expected '") + s_.close + "'");
    } else if (!open) {
      first = unary();
    } else if (n == 2 && s_.separator) {
      const std::size_t b = i_;
      ++i_;
      first = level(0);
      if (!failed() && take(s_.separator)) {
        second = level(0);
        if (!failed() && !take(s_.close))
          return fail(position(), position() + 1,
                      std::string("expected '") + s_.close + "' after the arguments of " + std::string(f.name));
      } else if (!failed() && take(s_.close) && s_.slash_second_argument) {
        second = slash_argument(f, at);
      } else if (!failed()) {
        return fail(b, position() + 1, std::string(f.name) + " takes two arguments");
      }
    } else {
      first = bracketed(i_);
      if (!failed() && n == 2) {
        if (!s_.slash_second_argument) return fail(at, i_, std::string(f.name) + " takes two arguments");
        second = slash_argument(f, at);
      }
    }
    if (!open) --nesting_;
    if (failed()) return interp::no_node;
    const interp::node_id id = checked(tree_.function(f.kind, first, second, span_of(at, name_end)));
    return id;
  }

  interp::node_id slash_argument(const function_spelling& f, std::size_t at) {
    skip();
    if (!take('/')) {
      const std::string name(f.name);
      return fail(at, i_, name + " takes two arguments: " + name + s_.open + "y" + s_.close + "/" + s_.open + "x" + s_.close);
    }
    skip();
    if (i_ >= text_.size() || text_[i_] != s_.open) return fail(i_, i_ + 1, std::string("expected '") + s_.open + "' after '/'");
    return bracketed(i_);
  }



  const expression_spelling& s_;
  std::string_view text_;
  std::size_t line_, column_;
  std::size_t i_ = 0;
  std::size_t nesting_ = 0;
  interp::expression tree_;
  std::optional<interp::expression_error> error_;
};

/// Reads `text` (starting at `column` of `line`) as one expression of spelling `s`: the whole of
/// it, or with `whole` false as much as is an expression (`end` says where it stopped).
inline parsed_expression parse_expression(const expression_spelling& s, std::string_view text, std::size_t line = 1,
                                          std::size_t column = 1, bool whole = true) {
  expression_parser p(s, text, line, column);
  const interp::node_id root = p.expression();
  parsed_expression out;
  out.end = p.position();
  if (!p.failed() && whole && out.end < text.size())
    p.fail(out.end, text.size(), "unexpected '" + std::string(text.substr(out.end, 1)) + "' after the expression");
  out.error = p.error();
  out.tree = std::move(p.tree());
  out.tree.root = out.error ? interp::no_node : root;
  return out;
}

}  // namespace kin5::program
