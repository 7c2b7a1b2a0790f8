/// @file reach/setup_offset.hpp
/// Where to put the part on the target: the shift Δ (mm, target workpiece frame) of the setup
/// offset that keeps every block's slides within the target's linear travel, for a setup
/// rotation whose rotary angles are already planned. The least such shift, found with Ipopt.
///
/// With the rotary angles θᵢ of block i fixed, its slides are affine in the shift (G7):
///     xᵢ(Δ) = D⁻¹ ( T(θᵢ) W (pᵢ + Δ) − H(θᵢ) g ) = xᵢ(0) + Jᵢ Δ,   Jᵢ = D⁻¹ T(θᵢ),
/// so the shifts that keep them within each travel narrowed by m = 0.01 mm form a convex
/// polytope, and the least one is a quadratic programme: minimise ½|Δ|² subject to
/// lo + m ≤ xᵢ(0) + Jᵢ Δ ≤ hi − m. On a machine without rotary tables T = I, and the polytope
/// is the box max_i(lo + m − xᵢ(0)) ≤ D⁻¹ Δ ≤ min_i(hi − m − xᵢ(0)) (the laws check it).
/// The answer is rounded to a micrometre, which m covers, and checked again by (G7).
/// @code
///   const auto shift = kin5::reach::setup_offset_shift(to, tips_mm, angles, inputs);
///   if (shift) setup.translation_mm = setup.translation_mm + *shift;
/// @endcode
#pragma once

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "../kinematics/inverse_pose.hpp"

namespace kin5::reach {

/// What each travel is narrowed by, mm, so that a printed offset keeps within it.
inline constexpr double offset_margin_mm = 0.01;

/// A linear constraint lo ≤ row · Δ ≤ hi on the shift.
struct shift_constraint {
  vec3 row{};
  double lo = 0.0, hi = 0.0;
};

namespace detail {

/// minimise ½|x|² subject to lo_j ≤ row_j · x ≤ hi_j (x ∈ ℝ³): Ipopt with the exact, constant
/// derivatives of a convex quadratic programme.
class least_shift_problem final : public Ipopt::TNLP {
 public:
  explicit least_shift_problem(const std::vector<shift_constraint>& c) : c_(c) {}

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac, Ipopt::Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = 3, m = static_cast<Ipopt::Index>(c_.size()), nnz_jac = 3 * m, nnz_h = 3, style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Ipopt::Index n, Ipopt::Number* x_l, Ipopt::Number* x_u, Ipopt::Index m, Ipopt::Number* g_l,
                       Ipopt::Number* g_u) override {
    for (Ipopt::Index i = 0; i < n; ++i) x_l[i] = -1e19, x_u[i] = 1e19;
    for (Ipopt::Index j = 0; j < m; ++j) g_l[j] = c_[static_cast<std::size_t>(j)].lo, g_u[j] = c_[static_cast<std::size_t>(j)].hi;
    return true;
  }
  bool get_starting_point(Ipopt::Index, bool, Ipopt::Number* x, bool, Ipopt::Number*, Ipopt::Number*, Ipopt::Index,
                          bool, Ipopt::Number*) override {
    x[0] = x[1] = x[2] = 0.0;
    return true;
  }
  bool eval_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number& f) override {
    f = 0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    return true;
  }
  bool eval_grad_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number* g) override {
    g[0] = x[0], g[1] = x[1], g[2] = x[2];
    return true;
  }
  bool eval_g(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Index m, Ipopt::Number* g) override {
    for (Ipopt::Index j = 0; j < m; ++j) g[j] = dot(c_[static_cast<std::size_t>(j)].row, {x[0], x[1], x[2]});
    return true;
  }
  bool eval_jac_g(Ipopt::Index, const Ipopt::Number*, bool, Ipopt::Index m, Ipopt::Index, Ipopt::Index* rows,
                  Ipopt::Index* cols, Ipopt::Number* values) override {
    for (Ipopt::Index j = 0; j < m; ++j) {
      const vec3& r = c_[static_cast<std::size_t>(j)].row;
      const double v[3] = {r.x, r.y, r.z};
      for (Ipopt::Index k = 0; k < 3; ++k) {
        if (values) values[3 * j + k] = v[k];
        else rows[3 * j + k] = j, cols[3 * j + k] = k;
      }
    }
    return true;
  }
  bool eval_h(Ipopt::Index, const Ipopt::Number*, bool, Ipopt::Number obj_factor, Ipopt::Index, const Ipopt::Number*,
              bool, Ipopt::Index, Ipopt::Index* rows, Ipopt::Index* cols, Ipopt::Number* values) override {
    for (Ipopt::Index k = 0; k < 3; ++k) {
      if (values) values[k] = obj_factor;
      else rows[k] = cols[k] = k;
    }
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Ipopt::Index, const Ipopt::Number* x, const Ipopt::Number*,
                         const Ipopt::Number*, Ipopt::Index, const Ipopt::Number*, const Ipopt::Number*, Ipopt::Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    result = vec3{x[0], x[1], x[2]};
  }

  vec3 result{};

 private:
  const std::vector<shift_constraint>& c_;
};

/// The constraints of blocks with tips `tips_mm` and angles `angles`: one per slide and distinct
/// row of Jᵢ (to 1e-12), bounded by the tightest block. Without rotary tables that is three.
inline std::vector<shift_constraint> shift_constraints(const machine_model& to, std::span<const vec3> tips_mm,
                                                       std::span<const rotary_values> angles, const run_inputs& in) {
  std::map<std::tuple<long long, long long, long long, std::size_t>, shift_constraint> rows;
  auto key = [](const vec3& r, std::size_t k) {
    return std::tuple{std::llround(r.x * 1e12), std::llround(r.y * 1e12), std::llround(r.z * 1e12), k};
  };
  for (std::size_t i = 0; i < tips_mm.size(); ++i) {
    const vec3 p = in.work_offset.map_point(tips_mm[i]);
    const vec3 x0 = linear_axes_for(to, angles[i], p, in);
    const vec3 jx = linear_axes_for(to, angles[i], p + unit_x, in) - x0;  // affine in p: exact columns
    const vec3 jy = linear_axes_for(to, angles[i], p + unit_y, in) - x0;
    const vec3 jz = linear_axes_for(to, angles[i], p + unit_z, in) - x0;
    const double x[3] = {x0.x, x0.y, x0.z};
    const vec3 r[3] = {{jx.x, jy.x, jz.x}, {jx.y, jy.y, jz.y}, {jx.z, jy.z, jz.z}};
    for (std::size_t k = 0; k < 3; ++k) {
      const linear_travel& t = to.linear(k).travel;
      const double lo = t.lower_mm + offset_margin_mm - x[k], hi = t.upper_mm - offset_margin_mm - x[k];
      auto [it, fresh] = rows.try_emplace(key(r[k], k), shift_constraint{r[k], lo, hi});
      if (!fresh) it->second.lo = std::max(it->second.lo, lo), it->second.hi = std::min(it->second.hi, hi);
    }
  }
  std::vector<shift_constraint> out;
  for (const auto& row : rows) out.push_back(row.second);
  return out;
}

/// Whether every block's slides, with the tips shifted by `shift_mm`, lie within the travel (to
/// the slack `translate` allows).
inline bool slides_within_travel(const machine_model& to, std::span<const vec3> tips_mm,
                                 std::span<const rotary_values> angles, const run_inputs& in, const vec3& shift_mm) {
  for (std::size_t i = 0; i < tips_mm.size(); ++i) {
    const vec3 x = linear_axes_for(to, angles[i], in.work_offset.map_point(tips_mm[i] + shift_mm), in);
    const double v[3] = {x.x, x.y, x.z};
    for (std::size_t k = 0; k < 3; ++k)
      if (to.linear(k).travel.excess_mm(v[k]) > inverse_options{}.linear_slack_mm) return false;
  }
  return true;
}

}  // namespace detail

/// The least shift Δ (mm, rounded to 0.001) of the tips `tips_mm` (target workpiece frame) with
/// which every block's slides, at its rotary angles `angles`, lie within the travel of `to`
/// narrowed by `offset_margin_mm`; `in` holds the tool length and the work offset. Nothing when
/// no shift does. Throws std::runtime_error if Ipopt cannot be initialised.
inline std::optional<vec3> setup_offset_shift(const machine_model& to, std::span<const vec3> tips_mm,
                                              std::span<const rotary_values> angles, const run_inputs& in) {
  const std::vector<shift_constraint> c = detail::shift_constraints(to, tips_mm, angles, in);
  for (const auto& k : c)
    if (k.lo > k.hi) return std::nullopt;  // one row alone is infeasible (a stroke longer than the travel)
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetNumericValue("tol", 1e-10);
  app->Options()->SetNumericValue("constr_viol_tol", 1e-7);
  app->Options()->SetIntegerValue("max_iter", 200);
  app->Options()->SetStringValue("jac_c_constant", "yes");
  app->Options()->SetStringValue("jac_d_constant", "yes");
  app->Options()->SetStringValue("hessian_constant", "yes");
  app->Options()->SetIntegerValue("mumps_mem_percent", 5);  // as box_minimizer.hpp: tiny systems
  app->Options()->SetIntegerValue("mumps_permuting_scaling", 0);
  app->Options()->SetIntegerValue("mumps_scaling", 0);
  if (app->Initialize() != Ipopt::Solve_Succeeded) throw std::runtime_error("kin5::reach: Ipopt failed to initialise");
  Ipopt::SmartPtr<detail::least_shift_problem> problem = new detail::least_shift_problem(c);
  app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(GetRawPtr(problem)));
  auto micrometre = [](double v) { return std::round(v * 1000.0) / 1000.0 + 0.0; };
  const vec3 shift{micrometre(problem->result.x), micrometre(problem->result.y), micrometre(problem->result.z)};
  if (!detail::slides_within_travel(to, tips_mm, angles, in, shift)) return std::nullopt;
  return shift;
}

}  // namespace kin5::reach
