// kin5::reach (Ipopt) against the closed forms: docs/matchability.md and P30.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include <kin5/kin5.hpp>
#include <kin5/reach.hpp>

using namespace kin5;
using kin5::machines::dmu_80p;
using kin5::machines::sajo_12000p;

namespace {

constexpr double deg(double v) { return v * pi / 180.0; }
constexpr double in_deg(radians r) { return r.value * 180.0 / pi; }

// (K11): the SAJO → DMU frame map T.
vec3 sajo_to_dmu(const vec3& u) { return {-u.x, u.z, u.y}; }

// (K1) typed from docs/papers.md, independent of kin5::tool_axis.
vec3 sajo_axis(double a_deg, double b_deg) {
  const double a = deg(a_deg), b = deg(b_deg);
  return {std::cos(a) * std::sin(b), -std::sin(a), std::cos(a) * std::cos(b)};
}

}  // namespace

TEST_CASE("DMU 80P reach cone about its table axis is [0 deg, 90 deg]", "[reach][P30]") {
  const auto range = reach::angle_range_to<dmu_80p>(unit_z);
  CHECK(range.converged);
  // The smallest angle is at the pole B = 0, where the objective is flat to second order:
  // 1e-3 deg, as docs/matchability.md advises for degenerate points.
  CHECK(in_deg(range.smallest) == Approx(0.0).margin(1e-3));
  CHECK(in_deg(range.largest) == Approx(90.0).margin(1e-4));
  // The largest angle is reached with the B bound active (docs/matchability.md).
  CHECK(in_deg(range.at_largest[1]) == Approx(180.0).margin(1e-3));
}

TEST_CASE("SAJO 12000P tool axis image about Y is [0 deg, 90 deg + A2]", "[reach][P30]") {
  const auto range = reach::angle_range_to<sajo_12000p>(unit_y);
  const double a2 = sajo_12000p::rotary[1].travel.upper.value;
  CHECK(in_deg(range.smallest) == Approx(0.0).margin(1e-3));  // at the pole A = -90 deg
  CHECK(in_deg(range.largest) == Approx(90.0 + a2).margin(1e-4));
}

TEST_CASE("Per-block gap of SAJO poses on the DMU 80P equals A_s above 0 and 0 elsewhere", "[reach][P30]") {
  for (double a_s : {5.0, 10.0, 20.0, 30.0}) {
    for (double b_s : {0.0, 77.0, 200.0}) {
      const auto nearest = reach::nearest_reachable_axis<dmu_80p>(sajo_to_dmu(sajo_axis(a_s, b_s)));
      INFO("a_s = " << a_s << ", b_s = " << b_s);
      CHECK(in_deg(nearest.gap) == Approx(a_s).margin(1e-4));
      // Reached at B = 180 deg (bound active) and C = b_s (docs/matchability.md).
      CHECK(in_deg(nearest.angles[1]) == Approx(180.0).margin(1e-3));
      CHECK(std::remainder(in_deg(nearest.angles[0]) - b_s, 360.0) == Approx(0.0).margin(1e-3));
    }
  }
  for (double a_s : {-120.0, -100.0, -90.0, -45.0}) {
    const auto nearest = reach::nearest_reachable_axis<dmu_80p>(sajo_to_dmu(sajo_axis(a_s, 33.0)));
    INFO("a_s = " << a_s);
    // At a_s = -90 deg the target pose is the pole B = 0 with C free, where the objective is
    // flat in C and converges slowly (docs/matchability.md): compare the dot product, not the angle.
    CHECK(1.0 - std::cos(nearest.gap.value) < 1e-10);
  }
}

TEST_CASE("Bisection finds the SAJO to DMU 80P reach boundary at A_s = 0 deg", "[reach][P30]") {
  for (double b_s : {0.0, 123.0}) {
    const double boundary = reach::reach_boundary<dmu_80p>(
        [b_s](double a_s) { return sajo_to_dmu(sajo_axis(a_s, b_s)); }, -45.0, 20.0, 1e-4);
    CHECK(boundary == Approx(0.0).margin(1e-3));
  }
}

// Directions spread evenly over the whole sphere (a Fibonacci lattice), poles included.
std::vector<vec3> sphere_directions(int n) {
  std::vector<vec3> out{unit_z, -unit_z, unit_x, -unit_y};
  const double golden = pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
    out.push_back({r * std::cos(golden * i), r * std::sin(golden * i), z});
  }
  return out;
}

TEST_CASE("Closed-form gap of inverse<M> agrees with Ipopt over the sphere", "[reach][P30]") {
  for (const vec3& v : sphere_directions(40)) {
    INFO("v = " << v.x << ", " << v.y << ", " << v.z);
    const auto closed = inverse<dmu_80p>(v);
    const auto numeric = reach::nearest_reachable_axis<dmu_80p>(v, 3);
    // 1e-3 deg: at the pole (B = 0, C free) the objective 1 − u·v is flat to second order, so
    // a converged Ipopt point can sit ~1e-4 deg away (docs/matchability.md).
    CHECK(in_deg(closed.gap) == Approx(in_deg(numeric.gap)).margin(1e-3));
  }
}

TEST_CASE("With both axes bounded (ac-head) the closed-form gap is an upper bound", "[reach][P30]") {
  for (const vec3& v : sphere_directions(40)) {
    INFO("v = " << v.x << ", " << v.y << ", " << v.z);
    const auto closed = inverse<machines::ac_head>(v);
    const auto numeric = reach::nearest_reachable_axis<machines::ac_head>(v, 3);
    CHECK(in_deg(numeric.gap) <= in_deg(closed.gap) + 1e-3);
    CHECK((in_deg(numeric.gap) < 1e-3) == closed.reachable());
  }
}
