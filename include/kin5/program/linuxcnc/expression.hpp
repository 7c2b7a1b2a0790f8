/// @file program/linuxcnc/expression.hpp
/// LinuxCNC's expressions (LinuxCNC User Manual, "G-code Overview": "Expressions", "Binary
/// Operators", "Functions"; docs/dialects/linuxcnc.md, "Expressions"), read into the
/// interpreter's tree by the shared parser (../expression_parser.hpp):
/// | level | operators |
/// |---|---|
/// | 5 (first) | `**` |
/// | 4 | `*` `/` `MOD` (the remainder in [0, \|b\|)) |
/// | 3 | `+` `-` |
/// | 2 | `EQ` `NE` (equal within 0.0001, as rs274 compares) `GT` `GE` `LT` `LE` |
/// | 1 | `AND` `OR` `XOR` (logical: 1 or 0) |
/// Equal levels bind left to right (`2**3**2` is 64); a sign binds to the value right after it
/// (`-2**2` is 4). Functions: `ABS ACOS ASIN ATAN[y]/[x] COS EXP FIX` (toward −∞) `FUP` (toward
/// +∞) `LN ROUND` (halves away from 0) `SIN SQRT TAN EXISTS[#<name>]`, angles in degrees.
/// Parameters: `#n`, `#[expr]`, `##n`, `#<name>` (named: lower case, blanks removed). A value
/// in a word or an assignment is one operand: a number, a parameter, a function, or `[ … ]`
/// (`read_value`).
#pragma once

#include <cstddef>
#include <string_view>

#include "../expression_parser.hpp"

namespace kin5::program::linuxcnc {

/// rs274's tolerance of `EQ` and `NE`: |a − b| < 0.0001 counts as equal.
inline constexpr double equal_tolerance = 0.0001;

namespace detail {
using interp::binary_op;
using interp::function_kind;

inline constexpr operator_spelling operators[] = {
    {"**", binary_op::power, 5},
    {"*", binary_op::multiply, 4},
    {"/", binary_op::divide, 4},
    {"MOD", binary_op::modulo_nonnegative, 4},
    {"+", binary_op::add, 3},
    {"-", binary_op::subtract, 3},
    {"EQ", binary_op::equal, 2, equal_tolerance},
    {"NE", binary_op::not_equal, 2, equal_tolerance},
    {"GT", binary_op::greater, 2},
    {"GE", binary_op::greater_equal, 2},
    {"LT", binary_op::less, 2},
    {"LE", binary_op::less_equal, 2},
    {"AND", binary_op::logical_and, 1},
    {"OR", binary_op::logical_or, 1},
    {"XOR", binary_op::logical_xor, 1},
};

inline constexpr function_spelling functions[] = {
    {"ABS", function_kind::abs},         {"ACOS", function_kind::acos_deg},   {"ASIN", function_kind::asin_deg},
    {"ATAN", function_kind::atan2_deg},  {"COS", function_kind::cos_deg},     {"EXP", function_kind::exp},
    {"FIX", function_kind::floor},       {"FUP", function_kind::ceil},        {"LN", function_kind::ln},
    {"ROUND", function_kind::round_half_away}, {"SIN", function_kind::sin_deg}, {"SQRT", function_kind::sqrt},
    {"TAN", function_kind::tan_deg},     {"EXISTS", function_kind::exists},
};
}  // namespace detail

/// LinuxCNC's spelling (see the file comment).
inline constexpr expression_spelling spelling{
    .open = '[',
    .close = ']',
    .operators = detail::operators,
    .functions = detail::functions,
    .slash_second_argument = true,
    .hash_numbers = true,
    .hash_indirect = true,
    .hash_names = true,
    .number_tolerance = 0.0001,
    .dialect = "LinuxCNC",
};

/// One value as a word or an assignment takes it (`X[#1*2]`, `#1 = sin[30]`): a number,
/// parameter, function or bracketed expression, from `text` (at `column` of `line`); `end`
/// says where it stopped.
inline parsed_expression read_value(std::string_view text, std::size_t line = 1, std::size_t column = 1) {
  expression_parser p(spelling, text, line, column);
  const interp::node_id root = p.operand();
  parsed_expression out;
  out.end = p.position();
  out.error = p.error();
  out.tree = std::move(p.tree());
  out.tree.root = out.error ? interp::no_node : root;
  return out;
}

}  // namespace kin5::program::linuxcnc
