/// @file program/interp/evaluate.hpp
/// The value of an expression (expression.hpp) with the parameters of a running program
/// (parameter_store.hpp), or the first error met, at the span of the node that caused it:
/// division by zero, a root of a negative number, an argument outside a function's domain, a
/// parameter that has no value, a result that is not finite. Errors are values, not exceptions.
/// Operands are evaluated left to right, as the controls do; angles are degrees at the
/// program's side and radians inside (`core/units.hpp`).
/// @code
///   const auto r = kin5::program::interp::evaluate(e, parameters);
///   if (r.error) { /* r.error->where.line, .column; r.error->message */ } else { /* r.value */ }
/// @endcode
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "../../core/units.hpp"
#include "expression.hpp"
#include "parameter_store.hpp"

namespace kin5::program::interp {

/// An expression's value, or its error.
struct evaluation {
  double value = 0;
  std::optional<expression_error> error{};
  bool ok() const { return !error; }
};

namespace detail {

/// sin and cos of an angle in degrees: reduced to one turn first (exactly: `fmod` is exact), so
/// that a large angle keeps its value, and exact at multiples of 90° (so that `COS[90]` is 0
/// and `TAN[90]` is recognised).
inline double sin_of_degrees(double deg) {
  const double r = std::fmod(deg, 360.0);
  if (r == 0 || r == 180 || r == -180) return 0;
  if (r == 90 || r == -270) return 1;
  if (r == -90 || r == 270) return -1;
  return std::sin(to_radians(degrees{r}).value);
}
inline double cos_of_degrees(double deg) {
  const double r = std::fmod(deg, 360.0);
  if (r == 90 || r == -90 || r == 270 || r == -270) return 0;
  if (r == 0) return 1;
  if (r == 180 || r == -180) return -1;
  return std::cos(to_radians(degrees{r}).value);
}

/// Whether `v` is a whole number within 32 bits (for the bit operators), as that number.
inline std::optional<std::int64_t> bits_of(double v) {
  if (!(std::floor(v) == v) || v < -2147483648.0 || v > 4294967295.0) return std::nullopt;
  return static_cast<std::int64_t>(v);
}

class evaluator {
 public:
  explicit evaluator(const expression& e, const parameter_store& p) : e_(e), p_(p) {}

  evaluation run() {
    if (e_.root == no_node) return fail(span{}, "empty expression");
    if (e_.depth() > max_expression_depth)
      return fail(e_.at(e_.root).where, "expression nested more than " + std::to_string(max_expression_depth) + " levels deep");
    return value_of(e_.root);
  }

  /// The parameter the root names (a numbered or named parameter node), its number evaluated.
  std::optional<parameter_key> target(evaluation& error) {
    const node& n = e_.at(e_.root);
    if (n.kind != node_kind::numbered_parameter && n.kind != node_kind::named_parameter) {
      error = fail(n.where, "only a parameter can be assigned");
      return std::nullopt;
    }
    return key_of(n, error);
  }

 private:
  static evaluation fail(span where, std::string message) { return {0, expression_error{where, std::move(message)}}; }

  evaluation finite(const node& n, double v) const {
    if (std::isnan(v)) return fail(n.where, "the calculation has no value (not a number)");
    if (std::isinf(v)) return fail(n.where, "the calculation overflows (infinity)");
    return {v};
  }

  std::optional<parameter_key> key_of(const node& n, evaluation& error) {
    if (n.kind == node_kind::named_parameter) return parameter_key{{}, 0, n.name};
    const evaluation number = value_of(n.a);
    if (!number.ok()) {
      error = number;
      return std::nullopt;
    }
    const double whole = std::round(number.value);
    if (std::abs(number.value - whole) > n.tolerance || std::abs(whole) > 1e9) {
      error = fail(n.where, "parameter number " + std::to_string(number.value) + " is not a whole number");
      return std::nullopt;
    }
    return parameter_key{n.prefix, static_cast<long>(whole)};
  }

  evaluation value_of(node_id id) {
    const node& n = e_.at(id);
    switch (n.kind) {
      case node_kind::number: return finite(n, n.number);
      case node_kind::numbered_parameter:
      case node_kind::named_parameter: {
        evaluation error;
        const auto key = key_of(n, error);
        if (!key) return error;
        const parameter_read r = p_.read(*key);
        if (!r.value) return fail(n.where, r.why);
        return {*r.value};
      }
      case node_kind::unary: return unary(n);
      case node_kind::binary: return binary(n);
      case node_kind::function: return function(n);
    }
    return fail(n.where, "unknown expression node");  // not reached
  }

  evaluation unary(const node& n) {
    const evaluation x = value_of(n.a);
    if (!x.ok()) return x;
    switch (n.unary) {
      case unary_op::negate: return {-x.value};
      case unary_op::plus: return x;
      case unary_op::logical_not: return {x.value == 0 ? 1.0 : 0.0};
      case unary_op::bit_not: {
        const auto b = bits_of(x.value);
        if (!b) return fail(n.where, "B_NOT takes a whole number within 32 bits");
        return {static_cast<double>(static_cast<std::int32_t>(~static_cast<std::uint32_t>(*b)))};
      }
    }
    return x;
  }

  evaluation binary(const node& n) {
    const evaluation l = value_of(n.a);
    if (!l.ok()) return l;
    const evaluation r = value_of(n.b);
    if (!r.ok()) return r;
    const double a = l.value, b = r.value;
    const auto truth = [](bool t) { return evaluation{t ? 1.0 : 0.0}; };
    const bool comparison = n.binary >= binary_op::equal && n.binary <= binary_op::less_equal;
    if (comparison && n.tolerance < 0 && a != b && std::abs(a - b) <= -n.tolerance * std::max(std::abs(a), std::abs(b)))
      return fail(n.where, "a comparison of two values this close: the control compares within a relative tolerance of its own");
    switch (n.binary) {
      case binary_op::add: return finite(n, a + b);
      case binary_op::subtract: return finite(n, a - b);
      case binary_op::multiply: return finite(n, a * b);
      case binary_op::divide:
        if (b == 0) return fail(n.where, "division by zero");
        return finite(n, a / b);
      case binary_op::power:
        if (a < 0 && std::floor(b) != b) return fail(n.where, "a negative number raised to a fractional power");
        if (a == 0 && b < 0) return fail(n.where, "zero raised to a negative power");
        return finite(n, std::pow(a, b));
      case binary_op::modulo_nonnegative: {
        if (b == 0) return fail(n.where, "remainder of a division by zero");
        double m = std::fmod(a, b);
        if (m < 0) m += std::abs(b);
        return finite(n, m);
      }
      case binary_op::remainder:
      case binary_op::integer_divide:
        if (b == 0) return fail(n.where, "division by zero");
        if (a < 0 || b < 0)
          return fail(n.where, "the remainder and whole quotient of a negative number are not defined by the control's manual");
        return finite(n, n.binary == binary_op::remainder ? std::fmod(a, b) : std::trunc(a / b));
      case binary_op::equal: return truth(n.tolerance > 0 ? std::abs(a - b) < n.tolerance : a == b);
      case binary_op::not_equal: return truth(n.tolerance > 0 ? !(std::abs(a - b) < n.tolerance) : a != b);
      case binary_op::greater: return truth(a > b);
      case binary_op::greater_equal: return truth(a >= b);
      case binary_op::less: return truth(a < b);
      case binary_op::less_equal: return truth(a <= b);
      case binary_op::logical_and: return truth(a != 0 && b != 0);
      case binary_op::logical_or: return truth(a != 0 || b != 0);
      case binary_op::logical_xor: return truth((a != 0) != (b != 0));
      case binary_op::bit_and:
      case binary_op::bit_or:
      case binary_op::bit_xor: {
        const auto x = bits_of(a), y = bits_of(b);
        if (!x || !y) return fail(n.where, "a bit operation takes whole numbers within 32 bits");
        const auto ux = static_cast<std::uint32_t>(*x), uy = static_cast<std::uint32_t>(*y);
        const std::uint32_t v = n.binary == binary_op::bit_and ? (ux & uy) : n.binary == binary_op::bit_or ? (ux | uy) : (ux ^ uy);
        return {(*x < 0 || *y < 0) ? static_cast<double>(static_cast<std::int32_t>(v)) : static_cast<double>(v)};
      }
    }
    return fail(n.where, "unknown operator");  // not reached
  }

  evaluation function(const node& n) {
    if (n.function == function_kind::exists) {
      const node& p = e_.at(n.a);
      evaluation error;
      const auto key = key_of(p, error);
      if (!key) return error;
      return {p_.holds(*key) ? 1.0 : 0.0};
    }
    const evaluation first = value_of(n.a);
    if (!first.ok()) return first;
    double y = 0;
    if (arity(n.function) == 2) {
      const evaluation second = value_of(n.b);
      if (!second.ok()) return second;
      y = second.value;
    }
    const double x = first.value;
    const auto deg = [](double rad) { return to_degrees(radians{rad}).value; };
    switch (n.function) {
      case function_kind::sin_deg: return finite(n, sin_of_degrees(x));
      case function_kind::cos_deg: return finite(n, cos_of_degrees(x));
      case function_kind::tan_deg: {
        const double c = cos_of_degrees(x);
        if (c == 0) return fail(n.where, "the tangent of an odd multiple of 90 degrees");
        return finite(n, sin_of_degrees(x) / c);
      }
      case function_kind::asin_deg:
      case function_kind::asin_deg_0_360:
      case function_kind::acos_deg: {
        if (x < -1 || x > 1) return fail(n.where, "the argument of an arc sine or arc cosine is outside -1 to 1");
        if (n.function == function_kind::acos_deg) return {deg(std::acos(x))};
        const double a = deg(std::asin(x));
        return {n.function == function_kind::asin_deg_0_360 && a < 0 ? a + 360.0 : a};
      }
      case function_kind::atan_deg: return {deg(std::atan(x))};
      case function_kind::atan2_deg:
      case function_kind::atan2_deg_0_360: {
        // (0, 0): 0 as C's atan2 and rs274 give it; FANUC's manual gives no angle there
        if (x == 0 && y == 0 && n.function == function_kind::atan2_deg_0_360) return fail(n.where, "the arc tangent of 0/0");
        const double a = deg(std::atan2(x, y));
        return {n.function == function_kind::atan2_deg_0_360 && a < 0 ? a + 360.0 : a};
      }
      case function_kind::sqrt:
        if (x < 0) return fail(n.where, "the square root of a negative number");
        return {std::sqrt(x)};
      case function_kind::square: return finite(n, x * x);
      case function_kind::abs: return {std::abs(x)};
      case function_kind::round_half_away: return {std::round(x)};
      case function_kind::floor: return {std::floor(x)};
      case function_kind::ceil: return {std::ceil(x)};
      case function_kind::trunc: return {std::trunc(x)};
      case function_kind::away_from_zero: return {x < 0 ? -std::ceil(-x) : std::ceil(x)};
      case function_kind::frac: return {x - std::trunc(x)};
      case function_kind::sign: return {x >= 0 ? 1.0 : -1.0};
      case function_kind::ln:
      case function_kind::log10:
        if (x <= 0) return fail(n.where, "the logarithm of zero or a negative number");
        return {n.function == function_kind::ln ? std::log(x) : std::log10(x)};
      case function_kind::exp: return finite(n, std::exp(x));
      case function_kind::power:
        if (x < 0 && std::floor(y) != y) return fail(n.where, "a negative number raised to a fractional power");
        if (x == 0 && y < 0) return fail(n.where, "zero raised to a negative power");
        return finite(n, std::pow(x, y));
      case function_kind::hypot: return finite(n, std::hypot(x, y));
      case function_kind::minimum: return {std::min(x, y)};
      case function_kind::maximum: return {std::max(x, y)};
      case function_kind::exists: break;
    }
    return fail(n.where, "unknown function");  // not reached
  }

  const expression& e_;
  const parameter_store& p_;
};

}  // namespace detail

/// The value of `e` with the parameters `p` (see the file comment).
inline evaluation evaluate(const expression& e, const parameter_store& p) { return detail::evaluator(e, p).run(); }

/// The parameter an assignment sets: the key `e`'s root names (`#[#1+1]` is `#3` while #1 is 2),
/// or the error.
struct parameter_target {
  std::optional<parameter_key> key;
  std::optional<expression_error> error{};
};

/// The parameter `e` (a parameter node at its root) names, with the parameters `p`.
inline parameter_target parameter_of(const expression& e, const parameter_store& p) {
  evaluation error;
  auto key = detail::evaluator(e, p).target(error);
  return {std::move(key), error.error};
}

}  // namespace kin5::program::interp
