/// @file bench/eigen_newton.hpp
/// The numerical baseline: machine M as an Eigen chain of homogeneous transforms,
/// `wp_T_tool = wp_T_p(ψp) · p_T_q(ψq)`, and a Levenberg–Marquardt solve of
/// `wp_T_tool · t = u` from a fixed start.
///
/// This is what a generic post-processor without closed forms does. It returns *one* solution
/// (whichever the iteration reaches), not every branch, and does not check travel.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <kin5/kin5.hpp>

namespace kin5::bench {

inline Eigen::Vector3d to_eigen(const vec3& v) { return {v.x, v.y, v.z}; }

template <machine M>
struct eigen_newton {
  static constexpr int n = static_cast<int>(rotary_count<M>);
  using params = Eigen::Matrix<double, n, 1>;

  struct result {
    std::array<double, rotary_count<M>> commanded{};  ///< radians, M::rotary order
    double residual = 0.0;                            ///< |wp_T_tool · t − u| at the end
    int iterations = 0;
  };

  /// ψ at which every solve starts (radians): away from the zero pose, where the chain of
  /// several catalog machines is singular (t ∥ p).
  static params start() {
    params x;
    x(0) = 0.4;
    if constexpr (n == 2) x(1) = 0.7;
    return x;
  }

  /// wp_T_tool as a product of homogeneous transforms, one per rotary axis (pivots at the origin:
  /// the tool axis does not depend on them).
  static Eigen::Isometry3d wp_T_tool(const params& psi) {
    Eigen::Isometry3d out(Eigen::AngleAxisd(psi(0), to_eigen(M::rotary[0].direction)));
    if constexpr (n == 2) out = out * Eigen::Isometry3d(Eigen::AngleAxisd(psi(1), to_eigen(M::rotary[1].direction)));
    return out;
  }

  static result solve(const vec3& u_target, double tolerance = 1e-12, int max_iterations = 100) {
    const Eigen::Vector3d target = to_eigen(u_target), t = to_eigen(M::tool_reference);
    const Eigen::Vector3d p = to_eigen(M::rotary[0].direction);
    params x = start();
    double lambda = 1e-3;
    auto residual_at = [&](const params& psi, Eigen::Isometry3d& T) {
      T = wp_T_tool(psi);
      return Eigen::Vector3d(T.linear() * t - target);
    };
    Eigen::Isometry3d T;
    Eigen::Vector3d r = residual_at(x, T);
    double cost = r.squaredNorm();
    result out;
    for (; out.iterations < max_iterations && cost > tolerance * tolerance; ++out.iterations) {
      // d(tool)/dψ_i = (axis i in the workpiece frame) × tool.
      const Eigen::Vector3d u = T.linear() * t;
      Eigen::Matrix<double, 3, n> J;
      J.col(0) = p.cross(u);
      if constexpr (n == 2) {
        const Eigen::Vector3d q_wp = Eigen::AngleAxisd(x(0), p) * to_eigen(M::rotary[1].direction);
        J.col(1) = q_wp.cross(u);
      }
      const Eigen::Matrix<double, n, n> JtJ = J.transpose() * J;
      const params g = J.transpose() * r;
      Eigen::Matrix<double, n, n> A = JtJ;
      A.diagonal().array() += lambda * (JtJ.diagonal().array() + 1e-12);
      const params dx = -A.ldlt().solve(g);
      Eigen::Isometry3d T_try;
      const Eigen::Vector3d r_try = residual_at(x + dx, T_try);
      const double cost_try = r_try.squaredNorm();
      if (cost_try < cost) {
        x += dx;
        r = r_try;
        T = T_try;
        cost = cost_try;
        lambda = std::fmax(lambda * 0.1, 1e-12);
      } else {
        lambda *= 10.0;
      }
    }
    for (int i = 0; i < n; ++i) {
      const double c = M::rotary[i].psi_per_commanded() * x(i);
      out.commanded[i] = std::remainder(c, 2.0 * pi);
    }
    out.residual = std::sqrt(cost);
    return out;
  }
};

}  // namespace kin5::bench
