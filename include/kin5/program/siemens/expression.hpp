/// @file program/siemens/expression.hpp
/// SINUMERIK arithmetic (840D sl Programming Manual Job Planning, "Flexible NC programming":
/// "Arithmetic functions", "Comparison and logic operations", "Priority of the operations";
/// docs/dialects/siemens.md, "Expressions"), read into the interpreter's tree by the shared
/// parser (../expression_parser.hpp):
/// | level | operators |
/// |---|---|
/// | 1 (first) | `NOT`, `B_NOT` (prefix) |
/// | 2 | `*` `/` `DIV` `MOD` |
/// | 3 | `+` `-` |
/// | 4 – 6 | `B_AND`, then `B_XOR`, then `B_OR` (bit by bit) |
/// | 7 – 9 | `AND`, then `XOR`, then `OR` (logical: 1 or 0) |
/// | 11 (last) | `==` `<>` `>` `<` `>=` `<=` |
/// so that `R1 == 1 AND R2 == 2` compares with `1 AND R2`: write brackets, as the manual does.
/// The control compares within a relative tolerance: two operands that differ by 1e-12 or
/// less, relative, are refused (`comparison_tolerance`).
/// Functions: `SIN COS TAN ASIN ACOS ATAN2(y, x) SQRT ABS POT` (the square) `TRUNC` (toward 0)
/// `ROUND` (halves away from 0) `LN EXP MINVAL(a, b) MAXVAL(a, b)`, angles in degrees.
/// Constants: `TRUE` (1) and `FALSE` (0), the values of a BOOL.
/// Parameters: `R0`, `R1`, … and names (`_F_CUT`, `DEPTH`; read in upper case); a system
/// variable (`$AA_IM[X]`) is the machine's state and refused. `<<` (strings), frames, and `EX`
/// exponents are not read.
#pragma once

#include <cstddef>
#include <string_view>

#include "../expression_parser.hpp"

namespace kin5::program::siemens {

/// The control compares for relative equality (840D sl NC programming 12/2019, §3.1.3.4
/// "Precision correction on comparison errors"); operands that differ by no more than this,
/// relative, are refused (`interp::node::tolerance` below 0), since which way such a comparison
/// goes is the control's.
inline constexpr double comparison_tolerance = -1e-12;

namespace detail {
using interp::binary_op;
using interp::function_kind;
using interp::unary_op;

inline constexpr operator_spelling expression_operators[] = {
    {"*", binary_op::multiply, 10},      {"/", binary_op::divide, 10},     {"DIV", binary_op::integer_divide, 10},
    {"MOD", binary_op::remainder, 10},   {"+", binary_op::add, 9},         {"-", binary_op::subtract, 9},
    {"B_AND", binary_op::bit_and, 8},    {"B_XOR", binary_op::bit_xor, 7}, {"B_OR", binary_op::bit_or, 6},
    {"AND", binary_op::logical_and, 5},  {"XOR", binary_op::logical_xor, 4}, {"OR", binary_op::logical_or, 3},
    {"==", binary_op::equal, 1, comparison_tolerance},         {"<>", binary_op::not_equal, 1, comparison_tolerance},
    {">=", binary_op::greater_equal, 1, comparison_tolerance}, {"<=", binary_op::less_equal, 1, comparison_tolerance},
    {">", binary_op::greater, 1, comparison_tolerance},        {"<", binary_op::less, 1, comparison_tolerance},
};

inline constexpr function_spelling expression_functions[] = {
    {"SIN", function_kind::sin_deg},  {"COS", function_kind::cos_deg},     {"TAN", function_kind::tan_deg},
    {"ASIN", function_kind::asin_deg}, {"ACOS", function_kind::acos_deg},  {"ATAN2", function_kind::atan2_deg},
    {"SQRT", function_kind::sqrt},    {"ABS", function_kind::abs},         {"POT", function_kind::square},
    {"TRUNC", function_kind::trunc},  {"ROUND", function_kind::round_half_away}, {"LN", function_kind::ln},
    {"EXP", function_kind::exp},      {"MINVAL", function_kind::minimum},  {"MAXVAL", function_kind::maximum},
};

inline constexpr prefix_spelling expression_prefixes[] = {
    {"NOT", unary_op::logical_not},
    {"B_NOT", unary_op::bit_not},
};

inline constexpr constant_spelling expression_constants[] = {{"TRUE", 1}, {"FALSE", 0}};

inline constexpr std::string_view expression_parameter_prefixes[] = {"R"};
}  // namespace detail

/// SINUMERIK's spelling (see the file comment).
inline constexpr expression_spelling spelling{
    .open = '(',
    .close = ')',
    .operators = detail::expression_operators,
    .functions = detail::expression_functions,
    .prefixes = detail::expression_prefixes,
    .constants = detail::expression_constants,
    .separator = ',',
    .letter_prefixes = detail::expression_parameter_prefixes,
    .names_are_parameters = true,
    .system_prefix = '$',
    .dialect = "SINUMERIK",
};

/// The expression on the right of `=` (`R1=R2*2+SIN(30)`, `X=R1+2`), from `text` (at `column`
/// of `line`), up to the first blank that ends it (`end`).
inline parsed_expression read_value(std::string_view text, std::size_t line = 1, std::size_t column = 1) {
  return parse_expression(spelling, text, line, column, false);
}

}  // namespace kin5::program::siemens
