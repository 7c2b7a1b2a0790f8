/// @file program/interp/expression.hpp
/// An expression as the interpreter evaluates it, the same for every dialect: numbers, parameter
/// references (numbered `#1`, `R1`, `Q1`, `QL1`, `#[#1+1]`; named `#<feed>`, `_F_CUT`), unary and
/// binary operators and functions, each node with the span of the text it was read from. What
/// an operator or function *means* is in its kind, not in its spelling: LinuxCNC's `FIX` is
/// `function_kind::floor`, FANUC's `FIX` is `function_kind::trunc`; a dialect's parser
/// (`program/<dialect>/expression.hpp`) chooses the kind its manual describes.
///
/// Nodes live in one array (`expression::nodes`), children before parents, and are addressed by
/// index: a tree of any shape is freed without recursion. Every node records its depth; a tree
/// deeper than `max_expression_depth` is refused by the parsers and by `evaluate`, so that a
/// hostile program cannot exhaust the stack.
/// @code
///   namespace ip = kin5::program::interp;
///   ip::expression e;                                                    // [1 + #3] on line 1
///   const auto one = e.number(1, {1, 2, 1});
///   const auto p3 = e.numbered_parameter("#", e.number(3, {1, 7, 1}), {1, 6, 2});
///   e.root = e.binary(ip::binary_op::add, one, p3, {1, 4, 1});
/// @endcode
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace kin5::program::interp {

/// Expressions nested deeper than this are refused: more brackets inside each other (a
/// function's brackets included; a function written without brackets and each sign count as
/// one too), or a tree deeper than this (an operator's node is one deeper than its operands':
/// `1+2*3` is 3 deep, `1+1+…+1` with 100 `+` is 101). Real programs nest a handful of levels
/// (FANUC allows 5 brackets); 100 is far beyond them and far within any stack.
inline constexpr std::size_t max_expression_depth = 100;

/// Where a node's text is: 1-based line and column of its first byte, and its length in bytes.
struct span {
  std::size_t line = 0;
  std::size_t column = 0;
  std::size_t length = 0;
  friend bool operator==(const span&, const span&) = default;
};

/// Why an expression cannot be read or has no value, and where: the text or the node.
struct expression_error {
  span where;
  std::string message;
};

enum class unary_op : unsigned char {
  negate,       ///< `-x`, Heidenhain `NEG x`
  plus,         ///< `+x`
  logical_not,  ///< Siemens `NOT x`: 1 when x is 0, else 0
  bit_not,      ///< Siemens `B_NOT x`: the bits of a whole number turned (two's complement)
};

enum class binary_op : unsigned char {
  add,
  subtract,
  multiply,
  divide,              ///< refused when the divisor is 0
  power,               ///< refused for a negative base with a fractional exponent
  modulo_nonnegative,  ///< LinuxCNC `MOD`: the remainder moved into [0, |b|) (`-7 MOD 3` is 2)
  remainder,           ///< Siemens `MOD`, FANUC `MOD`, Heidenhain `%`: of two numbers not negative only
  integer_divide,      ///< Siemens `DIV`: the quotient's whole part, of two numbers not negative only
  equal,               ///< 1 or 0; with a tolerance (`node::tolerance`) when the dialect has one
  not_equal,
  greater,
  greater_equal,
  less,
  less_equal,
  logical_and,  ///< 1 when neither operand is 0
  logical_or,
  logical_xor,
  bit_and,  ///< bit by bit, of whole numbers within 32 bits (FANUC `AND`, Siemens `B_AND`)
  bit_or,
  bit_xor,
};

/// A function as the interpreter computes it. Angles are degrees at the program's side (the
/// argument of `sin_deg`, the result of `atan2_deg`) and radians inside the computation.
enum class function_kind : unsigned char {
  sin_deg,
  cos_deg,
  tan_deg,          ///< refused at an odd multiple of 90°
  asin_deg,         ///< −90° … 90°; refused outside −1 … 1
  acos_deg,         ///< 0° … 180°; refused outside −1 … 1
  atan_deg,         ///< one argument: −90° … 90°
  atan2_deg,        ///< (y, x): the angle of (x, y), −180° … 180°; 0 at (0, 0) (LinuxCNC's rs274)
  atan2_deg_0_360,  ///< (y, x): the same angle in [0°, 360°) (FANUC with parameter NAT = 0); refused at (0, 0)
  asin_deg_0_360,   ///< the arc sine in [0°, 90°] ∪ [270°, 360°) (FANUC with parameter NAT = 0)
  sqrt,             ///< refused below 0
  square,           ///< Heidenhain `SQ`, Siemens `POT`
  abs,
  round_half_away,  ///< to the nearest whole number, halves away from 0
  floor,            ///< toward −∞ (LinuxCNC `FIX`)
  ceil,             ///< toward +∞ (LinuxCNC `FUP`)
  trunc,            ///< toward 0 (FANUC `FIX`, Siemens `TRUNC`, Heidenhain `INT`)
  away_from_zero,   ///< the next whole number away from 0 (FANUC `FUP`)
  frac,             ///< x − trunc(x) (Heidenhain `FRAC`)
  sign,             ///< 1 for x ≥ 0, else −1 (Heidenhain `SGN`)
  ln,               ///< refused at 0 and below
  log10,            ///< refused at 0 and below
  exp,
  power,            ///< (x, y): x to the y (FANUC `POW`), as `binary_op::power`
  hypot,            ///< (a, b): √(a² + b²) (Heidenhain `FN 8`)
  minimum,          ///< (a, b)
  maximum,          ///< (a, b)
  exists,           ///< LinuxCNC `EXISTS[#<name>]`: 1 when the parameter holds a value, else 0
};

/// The number of arguments a function takes.
constexpr int arity(function_kind f) {
  switch (f) {
    case function_kind::atan2_deg:
    case function_kind::atan2_deg_0_360:
    case function_kind::power:
    case function_kind::hypot:
    case function_kind::minimum:
    case function_kind::maximum: return 2;
    default: return 1;
  }
}

enum class node_kind : unsigned char {
  number,
  numbered_parameter,  ///< `prefix` and the number, an expression (`a`): `#1`, `#[#2+1]`, `R5`, `QL3`
  named_parameter,     ///< `name` as the dialect reads it: `#<feed>`, `_F_CUT`
  unary,
  binary,
  function,
};

using node_id = std::uint32_t;
inline constexpr node_id no_node = 0xffffffffu;

struct node {
  node_kind kind = node_kind::number;
  unary_op unary{};
  binary_op binary{};
  function_kind function{};
  double number = 0;     ///< a number's value
  /// A comparison: above 0, equal / not_equal count |a − b| < tolerance as equal (LinuxCNC);
  /// below 0, operands that differ by no more than |tolerance| relative are refused, because the
  /// control compares them with a relative tolerance of its own (SINUMERIK); 0: exactly. A
  /// numbered parameter: a number within it of a whole number is that number (0: whole only).
  double tolerance = 0;
  std::string prefix;    ///< a numbered parameter's family: "#", "R", "Q", "QL", "QR"
  std::string name;      ///< a named parameter
  node_id a = no_node;   ///< operand, first argument, or a parameter's number
  node_id b = no_node;   ///< second operand or argument
  std::uint32_t depth = 1;  ///< 1 for a leaf, else 1 + the deepest child's
  span where;
};

/// One expression: its nodes, children first, and the root.
struct expression {
  std::vector<node> nodes;
  node_id root = no_node;

  const node& at(node_id id) const { return nodes[id]; }
  std::size_t depth() const { return root == no_node ? 0 : nodes[root].depth; }

  node_id number(double value, span where) {
    node n;
    n.number = value;
    n.where = where;
    return add(std::move(n));
  }
  node_id numbered_parameter(std::string prefix, node_id number, span where, double tolerance = 0) {
    node n;
    n.tolerance = tolerance;
    n.kind = node_kind::numbered_parameter;
    n.prefix = std::move(prefix);
    n.a = number;
    n.where = where;
    return add(std::move(n));
  }
  node_id named_parameter(std::string name, span where) {
    node n;
    n.kind = node_kind::named_parameter;
    n.name = std::move(name);
    n.where = where;
    return add(std::move(n));
  }
  node_id unary(unary_op op, node_id operand, span where) {
    node n;
    n.kind = node_kind::unary;
    n.unary = op;
    n.a = operand;
    n.where = where;
    return add(std::move(n));
  }
  node_id binary(binary_op op, node_id left, node_id right, span where, double tolerance = 0) {
    node n;
    n.kind = node_kind::binary;
    n.binary = op;
    n.a = left;
    n.b = right;
    n.tolerance = tolerance;
    n.where = where;
    return add(std::move(n));
  }
  node_id function(function_kind f, node_id first, node_id second, span where) {
    node n;
    n.kind = node_kind::function;
    n.function = f;
    n.a = first;
    n.b = second;
    n.where = where;
    return add(std::move(n));
  }

 private:
  node_id add(node&& n) {
    std::uint32_t d = 0;
    if (n.a != no_node) d = nodes[n.a].depth;
    if (n.b != no_node) d = std::max(d, nodes[n.b].depth);
    n.depth = d + 1;
    nodes.push_back(std::move(n));
    return static_cast<node_id>(nodes.size() - 1);
  }
};

}  // namespace kin5::program::interp
