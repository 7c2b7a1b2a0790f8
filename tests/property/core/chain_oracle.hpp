/// @file chain_oracle.hpp
/// The Eigen homogeneous chain as the oracle of the machine-coordinate laws: the tool tip of
/// slides and angles, and the slides a control without TCP drives to for a program point.
/// Independent of kin5's closed forms (`eigen.hpp` multiplies the chain's transforms).
#pragma once

#include <Eigen/Dense>

#include <kin5/eigen.hpp>
#include <kin5/kin5.hpp>

namespace kin5::test {

/// The Eigen chain's tool tip for slides `x` and angles `rotary`.
template <machine M>
vec3 chain_tip(const vec3& x, const rotary_angles<M>& rotary, const run_inputs& in) {
  axis_position<M> q{};
  q.xyz_mm = x;
  q.rotary = rotary;
  return eigen::to_kin5(Eigen::Vector3d(eigen::chain_work_T_tool<M>(q, in).translation()));
}

/// The slides a control without TCP drives to for program point `p`: the chain's tip with every
/// rotary axis at zero is affine in the slides; solved here with Eigen.
template <machine M>
vec3 slides_for(const vec3& p, const run_inputs& in) {
  const vec3 o = chain_tip<M>({}, {}, in);
  Eigen::Matrix3d a;
  for (int i = 0; i < 3; ++i) {
    vec3 e{};
    (i == 0 ? e.x : i == 1 ? e.y : e.z) = 1.0;
    a.col(i) = eigen::to_eigen(chain_tip<M>(e, {}, in) - o);
  }
  return eigen::to_kin5(Eigen::Vector3d(a.colPivHouseholderQr().solve(eigen::to_eigen(p - o))));
}

}  // namespace kin5::test
