/// @file program/heidenhain/expression.hpp
/// Heidenhain Q-parameter arithmetic (TNC 640 / iTNC 530 User's Manuals, "Programming: Q
/// parameters": "Mathematical basic functions" FN 0–FN 5, "Trigonometric functions" FN 6–FN 8,
/// "Entering formulas directly", "Rules for formulas"; docs/dialects/heidenhain.md,
/// "Expressions"), read into the interpreter's tree by the shared parser
/// (../expression_parser.hpp). A formula `Q1 = (Q2 + 3) * SIN Q3`:
/// | level | operators |
/// |---|---|
/// | 3 (first) | `^` |
/// | 2 | `*` `/` `%` (the remainder) |
/// | 1 | `+` `-` |
/// Functions take the operand after them, with or without brackets: `SQ SQRT SIN COS TAN ASIN
/// ACOS ATAN` (one argument, −90°…90°) `LN LOG EXP INT` (toward 0) `ABS FRAC SGN` (1 for ≥ 0,
/// else −1), `NEG` (−x), the constant `PI`; angles in degrees. The manual does not say how `^`
/// binds after a sign or a function, or in a chain, so `-2^2`, `SQ 2^3`, `SIN(Q1)^2` and
/// `2^3^2` are refused: write brackets. Parameters: `Q`, `QL`, `QR` and a number (`QS` strings
/// are not numbers). The FN forms (`read_assignment`): `FN 0: Q1 = a`, `FN 1: Q1 = a + b`,
/// `FN 2: a - b`, `FN 3: a * b`, `FN 4: a DIV b`, `FN 5: Q1 = SQRT a`, `FN 6: SIN a`,
/// `FN 7: COS a`, `FN 8: a LEN b` (√(a² + b²)), `FN 13: a ANG b` (the angle of the adjacent side a
/// and the opposite side b, 0° ≤ angle < 360°; refused for a = b = 0), each operand a number or a
/// parameter with its sign.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "../expression_parser.hpp"
#include "../interp/parameter_store.hpp"

namespace kin5::program::heidenhain {

namespace detail {
using interp::binary_op;
using interp::function_kind;
using interp::unary_op;

inline constexpr operator_spelling formula_operators[] = {
    {"^", binary_op::power, 3},    {"*", binary_op::multiply, 2}, {"/", binary_op::divide, 2},
    {"%", binary_op::remainder, 2}, {"+", binary_op::add, 1},      {"-", binary_op::subtract, 1},
};

inline constexpr function_spelling formula_functions[] = {
    {"SQ", function_kind::square},  {"SQRT", function_kind::sqrt},     {"SIN", function_kind::sin_deg},
    {"COS", function_kind::cos_deg}, {"TAN", function_kind::tan_deg},  {"ASIN", function_kind::asin_deg},
    {"ACOS", function_kind::acos_deg}, {"ATAN", function_kind::atan_deg}, {"LN", function_kind::ln},
    {"LOG", function_kind::log10},  {"EXP", function_kind::exp},       {"INT", function_kind::trunc},
    {"ABS", function_kind::abs},    {"FRAC", function_kind::frac},     {"SGN", function_kind::sign},
};

inline constexpr prefix_spelling formula_prefixes[] = {{"NEG", unary_op::negate}};
inline constexpr constant_spelling formula_constants[] = {{"PI", 3.14159265358979323846}};
inline constexpr std::string_view formula_parameter_prefixes[] = {"QL", "QR", "Q"};
}  // namespace detail

/// Heidenhain's formula spelling (see the file comment).
inline constexpr expression_spelling spelling{
    .open = '(',
    .close = ')',
    .operators = detail::formula_operators,
    .functions = detail::formula_functions,
    .prefixes = detail::formula_prefixes,
    .constants = detail::formula_constants,
    .functions_without_brackets = true,
    .power_needs_brackets = true,
    .letter_prefixes = detail::formula_parameter_prefixes,
    .dialect = "Heidenhain",
};

/// An assignment to a Q parameter: its target and its value.
struct q_assignment {
  interp::parameter_key target;
  parsed_expression value;
};

/// Reads statement `s` (block number removed; at `column` of `line`): `FN k: Qn = …` for k from
/// 0 to 8 and 13, or a formula `Qn = …` (also QL, QR), up to the end of `s` or a `;` comment.
inline q_assignment read_assignment(std::string_view s, std::size_t line = 1, std::size_t column = 1) {
  q_assignment out;
  std::size_t end = s.find(';');
  if (end == std::string_view::npos) end = s.size();
  const std::string_view text = s.substr(0, end);
  expression_parser p(spelling, text, line, column);
  int fn = -1;
  if (p.take_word("FN")) {
    const std::size_t at = p.position();
    std::size_t k = at;
    fn = 0;
    while (k < text.size() && is_digit(text[k]) && k - at < 3) fn = fn * 10 + (text[k++] - '0');
    p.seek(k);
    if (k == at || !p.take(':')) p.fail(at, k + 1, "expected 'FN' with its number and ':'");
  }
  const std::size_t target_at = p.position();
  if (!p.failed()) {
    const interp::node_id t = p.operand();
    const interp::node* n = t == interp::no_node ? nullptr : &p.tree().at(t);
    if (!n || n->kind != interp::node_kind::numbered_parameter)
      p.fail(target_at, p.position(), "expected the Q parameter assigned");
    else
      out.target = {n->prefix, static_cast<long>(p.tree().at(n->a).number)};
    if (!p.failed() && !p.take('=')) p.fail(p.position(), p.position() + 1, "expected '=' after " + out.target.shown());
  }
  p.tree() = interp::expression{};
  interp::node_id root = interp::no_node;
  const auto pair = [&](char op_char, std::string_view op_word, auto&& build) {
    const interp::node_id a = p.operand();
    if (p.failed()) return;
    const std::size_t at = p.position();
    if (op_char ? !p.take(op_char) : !p.take_word(op_word))
      p.fail(at, at + 1, "expected '" + (op_char ? std::string(1, op_char) : std::string(op_word)) + "' in FN " + std::to_string(fn));
    const interp::node_id b = p.failed() ? interp::no_node : p.operand();
    if (!p.failed()) root = build(a, b, p.span_of(at, at + (op_char ? 1 : op_word.size())));
  };
  const auto one = [&](std::string_view name, interp::function_kind f) {
    const std::size_t at = p.position();
    if (!p.take_word(name)) p.fail(at, at + 1, "expected '" + std::string(name) + "' in FN " + std::to_string(fn));
    const interp::node_id a = p.failed() ? interp::no_node : p.operand();
    if (!p.failed()) root = p.tree().function(f, a, interp::no_node, p.span_of(at, at + name.size()));
  };
  const auto bin = [&](interp::binary_op op) {
    return [&p, op](interp::node_id a, interp::node_id b, interp::span w) { return p.tree().binary(op, a, b, w); };
  };
  if (!p.failed()) switch (fn) {
      case -1: root = p.expression(); break;
      case 0: root = p.operand(); break;
      case 1: pair('+', {}, bin(interp::binary_op::add)); break;
      case 2: pair('-', {}, bin(interp::binary_op::subtract)); break;
      case 3: pair('*', {}, bin(interp::binary_op::multiply)); break;
      case 4: pair(0, "DIV", bin(interp::binary_op::divide)); break;
      case 5: one("SQRT", interp::function_kind::sqrt); break;
      case 6: one("SIN", interp::function_kind::sin_deg); break;
      case 7: one("COS", interp::function_kind::cos_deg); break;
      case 8:
        pair(0, "LEN", [&p](interp::node_id a, interp::node_id b, interp::span w) {
          return p.tree().function(interp::function_kind::hypot, a, b, w);
        });
        break;
      case 13:  // the angle of the sides a (adjacent) and b (opposite): atan2(b, a) in [0°, 360°)
        pair(0, "ANG", [&p](interp::node_id a, interp::node_id b, interp::span w) {
          return p.tree().function(interp::function_kind::atan2_deg_0_360, b, a, w);
        });
        break;
      default:
        p.fail(target_at, target_at + 1, "FN " + std::to_string(fn) + " is not an arithmetic function (FN 0 to FN 8, FN 13)");
    }
  const std::size_t after = p.position();
  if (!p.failed() && after < text.size()) p.fail(after, text.size(), "unexpected '" + std::string(text.substr(after, 1)) + "'");
  out.value.end = after;
  out.value.error = p.error();
  out.value.tree = std::move(p.tree());
  out.value.tree.root = out.value.error ? interp::no_node : root;
  return out;
}

}  // namespace kin5::program::heidenhain
