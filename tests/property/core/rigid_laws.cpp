// rigid.hpp and the Eigen conversions: inverse, composition, det = +1, and agreement of
// kin5::rotation / rigid_transform with Eigen's AngleAxisd / Isometry3d.
#include <cmath>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/eigen.hpp>

#include "generators.hpp"

namespace {

using namespace kin5;

rc::Gen<rigid_transform> rigid() {
  return rc::gen::apply(
      [](vec3 axis, radians angle, double x, double y, double z) {
        return rigid_transform{rotation(axis, angle), vec3{x, y, z}};
      },
      test::unit_vector(), test::angle_in(-2 * pi, 2 * pi), test::real_in(-1000, 1000), test::real_in(-1000, 1000),
      test::real_in(-1000, 1000));
}

double max_abs(const Eigen::Matrix4d& m) { return m.cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("rigid_transform laws", "[core][rigid]") {
  rc::prop("rotation(n, θ) equals Eigen's AngleAxisd and has det +1", [] {
    const vec3 n = *test::unit_vector();
    const radians a = *test::angle_in(-2 * pi, 2 * pi);
    const Eigen::Matrix3d expected = Eigen::AngleAxisd(a.value, eigen::to_eigen(n)).toRotationMatrix();
    RC_ASSERT((eigen::to_eigen(rotation(n, a)) - expected).cwiseAbs().maxCoeff() <= 1e-15);
    RC_ASSERT(std::abs(determinant(rotation(n, a)) - 1.0) <= 1e-14);
  });
  rc::prop("T · T⁻¹ = T⁻¹ · T = identity", [] {
    const rigid_transform a_T_b = *rigid();
    const auto a_T_a = a_T_b * a_T_b.inverse();
    const auto b_T_b = a_T_b.inverse() * a_T_b;
    RC_ASSERT(max_abs(eigen::to_eigen(a_T_a).matrix() - Eigen::Matrix4d::Identity()) <= 1e-11);  // |t| <= 1.7e3 mm
    RC_ASSERT(max_abs(eigen::to_eigen(b_T_b).matrix() - Eigen::Matrix4d::Identity()) <= 1e-11);  // |t| <= 1.7e3 mm
  });
  rc::prop("composition is associative, matches Eigen, and maps points as a chain", [] {
    const rigid_transform a_T_b = *rigid(), b_T_c = *rigid(), c_T_d = *rigid();
    const auto left = (a_T_b * b_T_c) * c_T_d, right = a_T_b * (b_T_c * c_T_d);
    RC_ASSERT(max_abs(eigen::to_eigen(left).matrix() - eigen::to_eigen(right).matrix()) <= 1e-9);
    const Eigen::Isometry3d e = eigen::to_eigen(a_T_b) * eigen::to_eigen(b_T_c);
    RC_ASSERT(max_abs(eigen::to_eigen(a_T_b * b_T_c).matrix() - e.matrix()) <= 1e-9);
    const vec3 c_point{*test::real_in(-500, 500), *test::real_in(-500, 500), *test::real_in(-500, 500)};
    const vec3 chained = a_T_b.map_point(b_T_c.map_point(c_point));
    RC_ASSERT(norm((a_T_b * b_T_c).map_point(c_point) - chained) <= 1e-9);
    RC_ASSERT(std::abs(determinant((a_T_b * b_T_c).rotation) - 1.0) <= 1e-13);
    // (a_T_b · b_T_c)⁻¹ = c_T_b · b_T_a
    const auto inv = (a_T_b * b_T_c).inverse(), rev = b_T_c.inverse() * a_T_b.inverse();
    RC_ASSERT(max_abs(eigen::to_eigen(inv).matrix() - eigen::to_eigen(rev).matrix()) <= 1e-9);
  });
  rc::prop("directions ignore the translation; to_kin5 ∘ to_eigen = id", [] {
    const rigid_transform a_T_b = *rigid();
    const vec3 d = *test::unit_vector();
    RC_ASSERT(norm(a_T_b.map_direction(d) - a_T_b.rotation * d) == 0.0);
    RC_ASSERT(std::abs(norm(a_T_b.map_direction(d)) - 1.0) <= 1e-14);
    const rigid_transform back = eigen::to_kin5(eigen::to_eigen(a_T_b));
    RC_ASSERT(back.rotation == a_T_b.rotation);
    RC_ASSERT(back.translation_mm == a_T_b.translation_mm);
  });
}
