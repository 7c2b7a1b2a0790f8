/// @file reach/box_minimizer.hpp
/// Minimises a smooth function of a few variables over a box with Ipopt (interior point,
/// exact Hessian), from several starting points. The numerical engine of kin5::reach.
///
/// The objective is given as a callable filling the value and the gradient; kin5::reach builds
/// its objectives from dot products (smooth everywhere), never from arccos, whose derivative is
/// infinite at 0.
#pragma once

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

namespace kin5::reach {

/// f(x), ∇f(x) and ∇²f(x): returns f, writes the gradient into `gradient` (size n) and the
/// Hessian into `hessian` (n × n, row-major). With the exact Hessian Ipopt needs a handful of
/// Newton steps on these small problems instead of dozens of quasi-Newton ones.
using objective = std::function<double(const std::vector<double>& x, std::vector<double>& gradient,
                                       std::vector<double>& hessian)>;

/// A box-constrained minimum.
struct box_minimum {
  std::vector<double> x;
  double value = std::numeric_limits<double>::infinity();
  bool converged = false;
};

namespace detail {

class box_problem final : public Ipopt::TNLP {
 public:
  box_problem(const objective& f, const std::vector<double>& lower, const std::vector<double>& upper,
              const std::vector<double>& start)
      : f_(f), lower_(lower), upper_(upper), start_(start), gradient_(start.size()),
        hessian_(start.size() * start.size()) {}

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac, Ipopt::Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = static_cast<Ipopt::Index>(start_.size());
    m = 0;
    nnz_jac = 0;
    nnz_h = n * (n + 1) / 2;  // dense lower triangle
    style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Ipopt::Index n, Ipopt::Number* x_l, Ipopt::Number* x_u, Ipopt::Index, Ipopt::Number*,
                       Ipopt::Number*) override {
    for (Ipopt::Index i = 0; i < n; ++i) {
      x_l[i] = lower_[static_cast<std::size_t>(i)];
      x_u[i] = upper_[static_cast<std::size_t>(i)];
    }
    return true;
  }
  bool get_starting_point(Ipopt::Index n, bool, Ipopt::Number* x, bool, Ipopt::Number*, Ipopt::Number*,
                          Ipopt::Index, bool, Ipopt::Number*) override {
    for (Ipopt::Index i = 0; i < n; ++i) x[i] = start_[static_cast<std::size_t>(i)];
    return true;
  }
  bool eval_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number& value) override {
    value = f_(copy(n, x), gradient_, hessian_);
    return true;
  }
  bool eval_grad_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number* grad) override {
    f_(copy(n, x), gradient_, hessian_);
    for (Ipopt::Index i = 0; i < n; ++i) grad[i] = gradient_[static_cast<std::size_t>(i)];
    return true;
  }
  bool eval_g(Ipopt::Index, const Ipopt::Number*, bool, Ipopt::Index, Ipopt::Number*) override { return true; }
  bool eval_jac_g(Ipopt::Index, const Ipopt::Number*, bool, Ipopt::Index, Ipopt::Index, Ipopt::Index*,
                  Ipopt::Index*, Ipopt::Number*) override {
    return true;
  }
  bool eval_h(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number obj_factor, Ipopt::Index,
              const Ipopt::Number*, bool, Ipopt::Index, Ipopt::Index* rows, Ipopt::Index* cols,
              Ipopt::Number* values) override {
    Ipopt::Index k = 0;
    if (values == nullptr) {
      for (Ipopt::Index i = 0; i < n; ++i)
        for (Ipopt::Index j = 0; j <= i; ++j, ++k) {
          rows[k] = i;
          cols[k] = j;
        }
      return true;
    }
    f_(copy(n, x), gradient_, hessian_);
    for (Ipopt::Index i = 0; i < n; ++i)
      for (Ipopt::Index j = 0; j <= i; ++j, ++k)
        values[k] = obj_factor * hessian_[static_cast<std::size_t>(i * n + j)];
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn status, Ipopt::Index n, const Ipopt::Number* x, const Ipopt::Number*,
                         const Ipopt::Number*, Ipopt::Index, const Ipopt::Number*, const Ipopt::Number*,
                         Ipopt::Number value, const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    result.x = copy(n, x);
    result.value = value;
    result.converged = status == Ipopt::SUCCESS || status == Ipopt::STOP_AT_ACCEPTABLE_POINT;
  }

  box_minimum result;

 private:
  std::vector<double> copy(Ipopt::Index n, const Ipopt::Number* x) const {
    return std::vector<double>(x, x + n);
  }
  const objective& f_;
  std::vector<double> lower_, upper_, start_;
  std::vector<double> gradient_, hessian_;
};

}  // namespace detail

/// How Ipopt gets second derivatives: from the objective (`exact`), or by its limited-memory
/// quasi-Newton update (`quasi_newton`: the objective need not fill the Hessian).
enum class hessian { exact, quasi_newton };

/// The best local minimum of `f` over the box [lower, upper] found from each of `starts`.
/// Throws std::runtime_error if Ipopt cannot be initialised.
inline box_minimum minimize_in_box(const objective& f, const std::vector<double>& lower,
                                   const std::vector<double>& upper,
                                   const std::vector<std::vector<double>>& starts,
                                   hessian second_derivatives = hessian::exact) {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");  // no banner
  app->Options()->SetNumericValue("tol", 1e-13);  // boundaries to 1e-8 deg (pair_check.hpp)
  app->Options()->SetNumericValue("acceptable_tol", 1e-9);
  app->Options()->SetIntegerValue("max_iter", 150);
  // The linear systems have two or three unknowns: MUMPS' default workspace (+1000 %) and its
  // scaling passes cost more than the factorisation; without them a solve takes about a third
  // of the time (measured on the reach tests).
  app->Options()->SetIntegerValue("mumps_mem_percent", 5);
  app->Options()->SetIntegerValue("mumps_permuting_scaling", 0);
  app->Options()->SetIntegerValue("mumps_scaling", 0);
  if (second_derivatives == hessian::quasi_newton) {
    app->Options()->SetStringValue("hessian_approximation", "limited-memory");
    app->Options()->SetNumericValue("tol", 1e-8);  // a travel in radians: 1e-8 is plenty
    app->Options()->SetIntegerValue("max_iter", 40);
  }
  if (app->Initialize() != Ipopt::Solve_Succeeded) throw std::runtime_error("kin5::reach: Ipopt failed to initialise");
  box_minimum best;
  for (const auto& start : starts) {
    Ipopt::SmartPtr<detail::box_problem> problem = new detail::box_problem(f, lower, upper, start);
    app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(GetRawPtr(problem)));
    if (!problem->result.x.empty() && problem->result.value < best.value) best = problem->result;
  }
  return best;
}

}  // namespace kin5::reach
