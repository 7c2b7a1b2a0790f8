/// @file program/iso/expression.hpp
/// FANUC Custom Macro B expressions (FANUC Series 0i/16i/18i/30i Operator's Manuals, "Custom
/// Macro": "Arithmetic and logic operation", "Priority of operations", "Bracket nesting";
/// docs/dialects/iso.md, "Expressions"), read into the interpreter's tree by the shared parser
/// (../expression_parser.hpp):
/// | level | operators |
/// |---|---|
/// | 3 (first) | `*` `/` `AND` `MOD` |
/// | 2 | `+` `-` `OR` `XOR` |
/// | 1 | `EQ` `NE` `GT` `GE` `LT` `LE` (a conditional expression, `IF [ … ]`) |
/// Functions before either; `AND`, `OR`, `XOR` work bit by bit on whole numbers. Functions:
/// `SIN COS TAN ASIN` (270°…90° as [0°, 360°), parameter NAT = 0) `ACOS ATAN[y]/[x]` or
/// `ATAN[y,x]` (0°…360°, NAT = 0) `SQRT ABS ROUND` (halves away from 0) `FIX` (toward 0) `FUP`
/// (away from 0) `LN EXP POW[x,y]`, angles in degrees. `ATAN` with one argument, whose range
/// depends on the control, and `BIN`, `BCD`, `ADP` (PMC signals, machine data) are refused.
/// Parameters (variables): `#n`, `#[expr]`. A value in a word or an assignment is one operand:
/// a number, a variable, a function or `[ … ]` (`read_value`).
#pragma once

#include <cstddef>
#include <string_view>

#include "../expression_parser.hpp"

namespace kin5::program::iso {

namespace detail {
using interp::binary_op;
using interp::function_kind;

inline constexpr operator_spelling macro_operators[] = {
    {"*", binary_op::multiply, 3},   {"/", binary_op::divide, 3},    {"AND", binary_op::bit_and, 3},
    {"MOD", binary_op::remainder, 3}, {"+", binary_op::add, 2},      {"-", binary_op::subtract, 2},
    {"OR", binary_op::bit_or, 2},    {"XOR", binary_op::bit_xor, 2}, {"EQ", binary_op::equal, 1},
    {"NE", binary_op::not_equal, 1}, {"GT", binary_op::greater, 1},  {"GE", binary_op::greater_equal, 1},
    {"LT", binary_op::less, 1},      {"LE", binary_op::less_equal, 1},
};

inline constexpr function_spelling macro_functions[] = {
    {"SIN", function_kind::sin_deg},   {"COS", function_kind::cos_deg},          {"TAN", function_kind::tan_deg},
    {"ASIN", function_kind::asin_deg_0_360}, {"ACOS", function_kind::acos_deg}, {"ATAN", function_kind::atan2_deg_0_360},
    {"SQRT", function_kind::sqrt},     {"ABS", function_kind::abs},              {"ROUND", function_kind::round_half_away},
    {"FIX", function_kind::trunc},     {"FUP", function_kind::away_from_zero},   {"LN", function_kind::ln},
    {"EXP", function_kind::exp},       {"POW", function_kind::power},
};
}  // namespace detail

/// FANUC Custom Macro B's spelling (see the file comment).
inline constexpr expression_spelling macro_spelling{
    .open = '[',
    .close = ']',
    .operators = detail::macro_operators,
    .functions = detail::macro_functions,
    .separator = ',',
    .slash_second_argument = true,
    .hash_numbers = true,
    .dialect = "FANUC macro",
};

/// One value as a word or an assignment takes it (`X[#1*2]`, `#1 = SIN[30]`, `#1 = #2 + 3`):
/// with `whole_expression`, every operator (an assignment's right side); else one operand.
inline parsed_expression read_value(std::string_view text, std::size_t line = 1, std::size_t column = 1,
                                    bool whole_expression = false) {
  if (whole_expression) return parse_expression(macro_spelling, text, line, column, false);
  expression_parser p(macro_spelling, text, line, column);
  const interp::node_id root = p.operand();
  parsed_expression out;
  out.end = p.position();
  out.error = p.error();
  out.tree = std::move(p.tree());
  out.tree.root = out.error ? interp::no_node : root;
  return out;
}

}  // namespace kin5::program::iso
