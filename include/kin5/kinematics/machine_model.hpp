/// @file machine_model.hpp
/// The machine as a value: `machine_geometry` states every axis (what a catalog header or a
/// machine file writes), `machine_model` is that geometry with the constants the solver derives
/// from it, built once by `machine_model::from`. Every kinematic function takes a
/// `machine_model`, so a machine read at run time runs the same code as a catalog machine, whose
/// type holds its model as `static constexpr`. Frames and equations: docs/theory.md, "The whole
/// machine" (G6)–(G8).
/// @code
///   constexpr kin5::machine_model m = kin5::machine_model::from({
///       .id = "my-trunnion", .structure = "table-table: A about +X carrying C about +Z",
///       .linear = kin5::cartesian_axes({-300, 300}, {-200, 200}, {-400, 0}),
///       .rotary = {kin5::rotary_axis{kin5::axis_letter::C, kin5::mount::table, kin5::unit_z,
///                                    kin5::angle_sense::physical, kin5::rotary_travel::endless(), {0, 0, -250}},
///                  kin5::rotary_axis{kin5::axis_letter::A, kin5::mount::table, kin5::unit_x,
///                                    kin5::angle_sense::physical, kin5::rotary_travel::between({-30.0}, {110.0}),
///                                    {0, 0, -250}}}});
///   static_assert(kin5::machine_rules::check(m.geometry).ok());
/// @endcode
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "axis.hpp"
#include "solver.hpp"

namespace kin5 {

/// The tool at the zero pose: its axis t (from the tip towards the spindle, unit, machine frame)
/// and the pivot length L, from the reference point the linear axes place down to the gauge point
/// (the spindle nose, where the tool length is measured from).
struct tool_mount {
  vec3 reference = unit_z;
  double pivot_length_mm = 0.0;
};

/// Everything a machine is, as data (docs/theory.md, "The model").
struct machine_geometry {
  std::string_view id{};
  std::string_view structure{};
  std::array<linear_axis, 3> linear{};  ///< X, Y, Z, in that order
  /// Rotary axes in chain order, from the workpiece to the tool: `rotary[0]` is p of (G1), the
  /// axis fixed in the workpiece frame; `rotary[1]` is q. A 4-axis machine leaves `rotary[1]`
  /// with `axis_letter::none`.
  std::array<rotary_axis, 2> rotary{};
  tool_mount tool{};
};

/// Linear axes X, Y, Z along the machine's own axes with the given travels, mm; the sides default
/// to the usual column machine (X and Y move the table, Z the spindle), which does not change
/// the kinematics (G6).
constexpr std::array<linear_axis, 3> cartesian_axes(linear_travel x, linear_travel y, linear_travel z,
                                                    mount x_side = mount::table, mount y_side = mount::table,
                                                    mount z_side = mount::head) {
  return {linear_axis{axis_letter::X, x_side, unit_x, x}, linear_axis{axis_letter::Y, y_side, unit_y, y},
          linear_axis{axis_letter::Z, z_side, unit_z, z}};
}

/// A machine geometry with its derived constants: the (G1) solver geometry, the rotary count and
/// D⁻¹ for (G7). Literal, so a catalog machine builds it at compile time.
struct machine_model {
  machine_geometry geometry{};
  std::size_t rotary_count = 0;           ///< 1 (4-axis) or 2
  two_axis_geometry orientation{};        ///< p, q, t and the (G2) constants; two rotary axes
  one_axis_geometry orientation_single{}; ///< p, t; one rotary axis
  mat3 linear_inverse = mat3::identity(); ///< D⁻¹, D the matrix of the linear axis directions

  /// The model of `g`. `g` should pass `machine_rules::check`; a geometry that does not gives
  /// meaningless constants, never undefined behaviour.
  static constexpr machine_model from(const machine_geometry& g) noexcept {
    machine_model m{g};
    m.rotary_count = g.rotary[0].letter == axis_letter::none ? 0 : (g.rotary[1].letter == axis_letter::none ? 1 : 2);
    if (m.rotary_count == 2)
      m.orientation = two_axis_geometry::make(g.rotary[0].direction, g.rotary[1].direction, g.tool.reference);
    if (m.rotary_count >= 1) m.orientation_single = one_axis_geometry::make(g.rotary[0].direction, g.tool.reference);
    const vec3 dx = g.linear[0].direction, dy = g.linear[1].direction, dz = g.linear[2].direction;
    const double det = dot(dx, cross(dy, dz));
    if (det != 0.0) {  // rows of D⁻¹ are the reciprocal basis
      const double k = 1.0 / det;
      m.linear_inverse = {{k * cross(dy, dz), k * cross(dz, dx), k * cross(dx, dy)}};
    }
    return m;
  }

  constexpr const rotary_axis& rotary(std::size_t i) const { return geometry.rotary[i]; }
  constexpr const linear_axis& linear(std::size_t i) const { return geometry.linear[i]; }
  constexpr const vec3& tool_reference() const { return geometry.tool.reference; }
  /// The index of the rotary axis with NC letter `l` in chain order, or `rotary_count` if none.
  constexpr std::size_t rotary_index(axis_letter l) const {
    for (std::size_t i = 0; i < rotary_count; ++i)
      if (geometry.rotary[i].letter == l) return i;
    return rotary_count;
  }
  /// D·x: the tool's displacement relative to the part for linear axis values x (mm).
  constexpr vec3 linear_displacement(const vec3& x_mm) const {
    return x_mm.x * geometry.linear[0].direction + x_mm.y * geometry.linear[1].direction +
           x_mm.z * geometry.linear[2].direction;
  }
};

/// The rules a machine geometry must satisfy, each a constexpr test, and `check` listing the
/// broken ones (for `static_assert` messages and machine-file errors).
namespace machine_rules {

inline constexpr double unit_tolerance = 1e-12;
/// A machine whose ρ (G2) is below this is degenerate (S1).
inline constexpr double degenerate_rho = 1e-9;
/// Widest travel of a bounded rotary axis, so that one pose has at most four 360° shifts.
inline constexpr double widest_bounded_travel_deg = 1080.0;
/// |det D| below this: the linear axes do not span space.
inline constexpr double degenerate_linear = 1e-9;

/// Each rule, in the order `check` tests them.
enum class rule {
  rotary_count,        ///< one or two rotary axes, in the first slots
  unit_directions,     ///< every direction and the tool reference are unit vectors
  rotary_letters,      ///< rotary axes are A, B or C, each at most once
  linear_letters,      ///< the linear axes are X, Y, Z in that order
  linear_independent,  ///< the linear directions span space
  travel_order,        ///< lower <= upper; a bounded rotary axis at most 1080° wide
  moves_the_tool,      ///< (S1): each rotary axis can change the tool direction
  finite,              ///< every number is finite, the pivot length >= 0
};

/// One line per rule, for error messages.
constexpr std::string_view message(rule r) {
  switch (r) {
    case rule::rotary_count: return "a machine has one or two rotary axes";
    case rule::unit_directions: return "every axis direction and the tool reference must be unit vectors";
    case rule::rotary_letters: return "rotary axes are named A, B or C, each letter at most once";
    case rule::linear_letters: return "the linear axes are X, Y and Z, in that order";
    case rule::linear_independent: return "the linear axis directions must not lie in one plane";
    case rule::travel_order:
      return "a travel needs lower <= upper, and a bounded rotary axis at most 1080 degrees; declare wider axes continuous";
    case rule::moves_the_tool:
      return "degenerate machine (S1): a rotary axis is parallel to the axis it carries or to the tool, so it cannot "
             "change the tool direction";
    case rule::finite: return "every number must be finite and the pivot length not negative";
  }
  return "?";
}

constexpr bool is_unit(const vec3& v) {
  const double d = squared_norm(v) - 1.0;
  return d < unit_tolerance && d > -unit_tolerance;
}
constexpr bool is_finite(double x) { return x == x && x - x == 0.0; }
constexpr bool is_finite(const vec3& v) { return is_finite(v.x) && is_finite(v.y) && is_finite(v.z); }

constexpr std::size_t count_rotary(const machine_geometry& g) {
  return g.rotary[0].letter == axis_letter::none ? 0 : (g.rotary[1].letter == axis_letter::none ? 1 : 2);
}

constexpr bool holds(rule r, const machine_geometry& g) {
  const std::size_t n = count_rotary(g);
  switch (r) {
    case rule::rotary_count: return n >= 1;
    case rule::unit_directions: {
      bool ok = is_unit(g.tool.reference);
      for (const auto& a : g.linear) ok = ok && is_unit(a.direction);
      for (std::size_t i = 0; i < n; ++i) ok = ok && is_unit(g.rotary[i].direction);
      return ok;
    }
    case rule::rotary_letters: {
      for (std::size_t i = 0; i < n; ++i) {
        const auto l = g.rotary[i].letter;
        if (l != axis_letter::A && l != axis_letter::B && l != axis_letter::C) return false;
        for (std::size_t j = 0; j < i; ++j)
          if (g.rotary[j].letter == l) return false;
      }
      return true;
    }
    case rule::linear_letters:
      return g.linear[0].letter == axis_letter::X && g.linear[1].letter == axis_letter::Y &&
             g.linear[2].letter == axis_letter::Z;
    case rule::linear_independent: {
      const double det = dot(g.linear[0].direction, cross(g.linear[1].direction, g.linear[2].direction));
      return det > degenerate_linear || det < -degenerate_linear;
    }
    case rule::travel_order: {
      for (const auto& a : g.linear)
        if (!(a.travel.lower_mm <= a.travel.upper_mm)) return false;
      for (std::size_t i = 0; i < n; ++i) {
        const auto& t = g.rotary[i].travel;
        if (t.continuous) continue;
        if (!(t.lower.value <= t.upper.value)) return false;
        if (t.upper.value - t.lower.value > widest_bounded_travel_deg) return false;
      }
      return true;
    }
    case rule::moves_the_tool: {
      const vec3 t = g.tool.reference;
      if (n == 2) {
        const vec3 p = g.rotary[0].direction, q = g.rotary[1].direction;
        return norm(cross(p, q)) * norm(cross(q, t)) > degenerate_rho;
      }
      return n == 1 && norm(cross(g.rotary[0].direction, t)) > degenerate_rho;
    }
    case rule::finite: {
      bool ok = is_finite(g.tool.reference) && is_finite(g.tool.pivot_length_mm) && g.tool.pivot_length_mm >= 0.0;
      for (const auto& a : g.linear)
        ok = ok && is_finite(a.direction) && is_finite(a.travel.lower_mm) && is_finite(a.travel.upper_mm);
      for (std::size_t i = 0; i < n; ++i) {
        const auto& a = g.rotary[i];
        ok = ok && is_finite(a.direction) && is_finite(a.point_mm) &&
             (a.travel.continuous || (is_finite(a.travel.lower.value) && is_finite(a.travel.upper.value)));
      }
      return ok;
    }
  }
  return false;
}

inline constexpr std::array all_rules{rule::rotary_count,       rule::unit_directions, rule::rotary_letters,
                                      rule::linear_letters,     rule::linear_independent, rule::travel_order,
                                      rule::moves_the_tool,     rule::finite};

/// The rules `g` breaks, in `all_rules` order.
struct check_result {
  std::array<rule, all_rules.size()> broken{};
  std::size_t count = 0;
  constexpr bool ok() const { return count == 0; }
  constexpr const rule* begin() const { return broken.data(); }
  constexpr const rule* end() const { return broken.data() + count; }
};

constexpr check_result check(const machine_geometry& g) {
  check_result out{};
  for (rule r : all_rules)
    if (!holds(r, g)) out.broken[out.count++] = r;
  return out;
}

}  // namespace machine_rules

}  // namespace kin5
