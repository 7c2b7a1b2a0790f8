// The general two-axis solver ((G1)–(G5), docs/theory.md) on random unit p, q, t: properties P19–P24,
// with u built by Eigen's AngleAxisd, not by kin5's rotate.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/eigen.hpp>

#include "generators.hpp"

namespace {

using namespace kin5;

struct axes {
  vec3 p, q, t;
};

/// Random p, q, t with ρ = sin∠(p,q)·sin∠(q,t) >= 0.05 (away from S1).
rc::Gen<axes> nondegenerate_axes() {
  return rc::gen::suchThat(rc::gen::apply([](vec3 p, vec3 q, vec3 t) { return axes{p, q, t}; }, test::unit_vector(),
                                          test::unit_vector(), test::unit_vector()),
                           [](const axes& a) { return norm(cross(a.p, a.q)) * norm(cross(a.q, a.t)) >= 0.05; });
}

/// (G1) through Eigen.
vec3 chain(const axes& g, double psi_p, double psi_q) {
  const Eigen::Vector3d u = Eigen::AngleAxisd(psi_p, eigen::to_eigen(g.p)) *
                            (Eigen::AngleAxisd(psi_q, eigen::to_eigen(g.q)) * eigen::to_eigen(g.t));
  return eigen::to_kin5(u);
}

double circular_distance(double x, double y) { return std::abs(std::remainder(x - y, 2.0 * pi)); }

/// Range of ∠(p, R(q, ψq) t) over ψq by a dense sweep with golden-section refinement.
std::array<double, 2> latitude_range(const axes& g) {
  auto lat = [&](double x) { return std::acos(std::clamp(dot(g.p, chain(g, 0.0, x)), -1.0, 1.0)); };
  double lo = 10, hi = -10, xlo = 0, xhi = 0;
  for (int k = 0; k < 720; ++k) {
    const double x = -pi + 2 * pi * k / 720.0, l = lat(x);
    if (l < lo) { lo = l; xlo = x; }
    if (l > hi) { hi = l; xhi = x; }
  }
  auto refine = [&](double x0, double sign) {
    double a = x0 - 2 * pi / 720, b = x0 + 2 * pi / 720;
    for (int it = 0; it < 100; ++it) {
      const double m1 = b - 0.618034 * (b - a), m2 = a + 0.618034 * (b - a);
      if (sign * lat(m1) < sign * lat(m2)) b = m2; else a = m1;
    }
    return lat(0.5 * (a + b));
  };
  return {std::min(lo, refine(xlo, 1.0)), std::max(hi, refine(xhi, -1.0))};
}

}  // namespace

TEST_CASE("general solver laws (P19-P24)", "[core][solver]") {
  rc::prop("P19: both branches reproduce u; the generating ψq is one of them", [] {
    const axes g = *nondegenerate_axes();
    const double psi_p = *test::real_in(-pi, pi), psi_q = *test::real_in(-pi, pi);
    const vec3 u = chain(g, psi_p, psi_q);
    const auto geo = two_axis_geometry::make(g.p, g.q, g.t);
    const auto s = geo.solve(u);
    RC_ASSERT(s.status != reach_status::unreachable);
    RC_ASSERT(s.count >= 1u);
    for (std::size_t b = 0; b < s.count && s.status == reach_status::reachable; ++b)
      RC_ASSERT(norm(chain(g, s.branch[b].psi_p.value, s.branch[b].psi_q.value) - u) <= 1e-12);
    const double theta = angle_between(g.p, u).value;
    RC_PRE(std::min({theta - geo.theta_min.value, geo.theta_max.value - theta, theta, pi - theta}) > 1e-4);
    bool found = false;
    for (std::size_t b = 0; b < s.count; ++b)
      found = found || (circular_distance(s.branch[b].psi_q.value, psi_q) <= 1e-9 &&
                        circular_distance(s.branch[b].psi_p.value, psi_p) <= 1e-9);
    RC_ASSERT(found);
  });
  rc::prop("P20: reachable exactly inside the swept latitude range; gap is the distance to it", [] {
    const axes g = *nondegenerate_axes();
    const vec3 u = *test::unit_vector();
    const auto range = latitude_range(g);
    const double theta = std::acos(std::clamp(dot(g.p, u), -1.0, 1.0));
    const double outside = std::max(range[0] - theta, theta - range[1]);
    const auto s = two_axis_geometry::make(g.p, g.q, g.t).solve(u);
    if (outside < -1e-7) RC_ASSERT(s.status != reach_status::unreachable);
    if (outside > 1e-7) {
      RC_ASSERT(s.status == reach_status::unreachable);
      RC_ASSERT(std::abs(s.gap.value - outside) <= 1e-9);
    }
  });
  rc::prop("P21: rotating p, q, t and u together leaves the angles unchanged", [] {
    const axes g = *nondegenerate_axes();
    const vec3 u = chain(g, *test::real_in(-pi, pi), *test::real_in(-pi, pi));
    const mat3 Q = rotation(*test::unit_vector(), *test::angle_in(-pi, pi));
    const auto a = two_axis_geometry::make(g.p, g.q, g.t);
    const auto b = two_axis_geometry::make(Q * g.p, Q * g.q, Q * g.t);
    const double theta = angle_between(g.p, u).value;
    RC_PRE(std::min({theta - a.theta_min.value, a.theta_max.value - theta, theta, pi - theta}) > 1e-4);
    const auto sa = a.solve(u), sb = b.solve(Q * u);
    RC_ASSERT(sa.count == sb.count);
    for (std::size_t k = 0; k < sa.count; ++k) {
      RC_ASSERT(circular_distance(sa.branch[k].psi_p.value, sb.branch[k].psi_p.value) <= 1e-9);
      RC_ASSERT(circular_distance(sa.branch[k].psi_q.value, sb.branch[k].psi_q.value) <= 1e-9);
    }
  });
  rc::prop("P22: turning u about p by γ adds γ to ψp and leaves ψq", [] {
    const axes g = *nondegenerate_axes();
    const vec3 u = chain(g, *test::real_in(-pi, pi), *test::real_in(-pi, pi));
    const double gamma = *test::real_in(-pi, pi);
    const auto geo = two_axis_geometry::make(g.p, g.q, g.t);
    const double theta = angle_between(g.p, u).value;
    RC_PRE(std::min({theta - geo.theta_min.value, geo.theta_max.value - theta, theta, pi - theta}) > 1e-4);
    const vec3 turned = eigen::to_kin5(Eigen::AngleAxisd(gamma, eigen::to_eigen(g.p)) * eigen::to_eigen(u));
    const auto s0 = geo.solve(u), s1 = geo.solve(turned);
    RC_ASSERT(s0.count == s1.count);
    for (std::size_t k = 0; k < s0.count; ++k) {
      RC_ASSERT(circular_distance(s1.branch[k].psi_p.value, s0.branch[k].psi_p.value + gamma) <= 1e-9);
      RC_ASSERT(circular_distance(s1.branch[k].psi_q.value, s0.branch[k].psi_q.value) <= 1e-9);
    }
  });
  rc::prop("P23: ρ vanishes when q ∥ p or q ∥ t", [] {
    const vec3 a = *test::unit_vector(), b = *test::unit_vector();
    const double sign = *rc::gen::element(-1.0, 1.0);
    RC_ASSERT(two_axis_geometry::make(a, sign * a, b).rho <= 1e-15);
    RC_ASSERT(two_axis_geometry::make(b, a, sign * a).rho <= 1e-15);
    // ρ = sin∠(p,q)·sin∠(q,t) in general.
    const vec3 t = *test::unit_vector();
    RC_ASSERT(std::abs(two_axis_geometry::make(a, b, t).rho - norm(cross(a, b)) * norm(cross(b, t))) <= 1e-14);
  });
  rc::prop("P24: at u = p, keep returns the given ψp; near p, ψq is continuous", [] {
    // t = R(q, γ) p puts p on the cone (∠(q,t) = ∠(p,q)), so u = p is reachable.
    const vec3 p = *test::unit_vector(), q = *test::unit_vector();
    RC_PRE(norm(cross(p, q)) >= 0.2);
    const double gamma = *test::real_in(0.3, 2 * pi - 0.3);
    const axes g{p, q, eigen::to_kin5(Eigen::AngleAxisd(gamma, eigen::to_eigen(q)) * eigen::to_eigen(p))};
    const auto geo = two_axis_geometry::make(g.p, g.q, g.t);
    const double kept = *test::real_in(-pi, pi);
    const auto at = geo.solve(p, pole_policy::keep(radians{kept}));
    RC_ASSERT(at.status == reach_status::pole);
    RC_ASSERT(at.branch[0].psi_p.value == kept);
    RC_ASSERT(norm(chain(g, kept, at.branch[0].psi_q.value) - p) <= 1e-9);
    const double eps = *test::log_uniform(-9.0, -4.0);
    const auto near = geo.solve(test::tilted(p, eps, *test::real_in(-pi, pi)));
    RC_ASSERT(near.status == reach_status::reachable);
    for (std::size_t k = 0; k < near.count; ++k)
      RC_ASSERT(circular_distance(near.branch[k].psi_q.value, at.branch[0].psi_q.value) <=
                4.0 * eps / std::sqrt(geo.rho) + 1e-9);
  });
}
