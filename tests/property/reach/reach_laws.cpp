// kin5::reach (Ipopt) against the closed forms, 1e-6° apart (cosines at degenerate points: a pole
// or a boundary the objective touches, where the angle is fixed only to about √ε): the reach
// cones, the per-block gap, and the SAJO 12000P → DMU 80P regions of Tian et al. 2010 §1.1 —
// A = −90° (branch), A = 0° (reach), gap = A above 0 — worked out by hand (docs/matchability.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include <kin5/kin5.hpp>
#include <kin5/reach.hpp>
#include <kin5/translate/setup.hpp>

using namespace kin5;
using kin5::machines::dmu_80p;
using kin5::machines::sajo_12000p;

namespace {

constexpr double deg(double v) { return v * pi / 180.0; }
constexpr double in_deg(radians r) { return r.value * 180.0 / pi; }
constexpr double tol_deg = 1e-6;
// At a pole the optimum is flat to second order: compare 1 − cos of the angle instead.
bool cosine_near_one(radians r) { return 1.0 - std::cos(r.value) < 1e-10; }

// (K11) = Tian et al. 2010 eqs (15)-(17): the SAJO → DMU frame map T, typed here.
vec3 sajo_to_dmu(const vec3& u) { return {-u.x, u.z, u.y}; }

// (K1) = Tian et al. 2010 eq (8), typed here, independent of kin5::tool_axis.
vec3 sajo_axis(double a_deg, double b_deg) {
  const double a = deg(a_deg), b = deg(b_deg);
  return {std::cos(a) * std::sin(b), -std::sin(a), std::cos(a) * std::cos(b)};
}

}  // namespace

TEST_CASE("DMU 80P reach cone about its table axis is [0 deg, 90 deg]", "[reach][P30]") {
  const auto range = reach::angle_range_to<dmu_80p>(unit_z);
  CHECK(range.converged);
  // The smallest angle is at the pole B = 0, where the objective is flat to second order.
  CHECK(cosine_near_one(range.smallest));
  CHECK(in_deg(range.largest) == Approx(90.0).margin(tol_deg));
  // The largest angle is reached with the B bound active.
  CHECK(in_deg(range.at_largest[1]) == Approx(180.0).margin(1e-3));
}

TEST_CASE("SAJO 12000P tool axis image about Y is [0 deg, 90 deg + A2]", "[reach][P30]") {
  const auto range = reach::angle_range_to<sajo_12000p>(unit_y);
  const double a2 = sajo_12000p::rotary[1].travel.upper.value;
  CHECK(cosine_near_one(range.smallest));  // at the pole A = -90 deg
  CHECK(in_deg(range.largest) == Approx(90.0 + a2).margin(tol_deg));
}

TEST_CASE("Per-block gap of SAJO poses on the DMU 80P equals A_s above 0 and 0 elsewhere", "[reach][P30]") {
  for (double a_s : {5.0, 10.0, 20.0, 30.0}) {
    for (double b_s : {0.0, 77.0, 200.0}) {
      const auto nearest = reach::nearest_reachable_axis<dmu_80p>(sajo_to_dmu(sajo_axis(a_s, b_s)));
      INFO("a_s = " << a_s << ", b_s = " << b_s);
      CHECK(in_deg(nearest.gap) == Approx(a_s).margin(tol_deg));
      // Reached at B = 180 deg (bound active, zero multiplier: flat) and C = b_s.
      CHECK(in_deg(nearest.angles[1]) == Approx(180.0).margin(1e-3));
      CHECK(std::remainder(in_deg(nearest.angles[0]) - b_s, 360.0) == Approx(0.0).margin(1e-3));
    }
  }
  for (double a_s : {-120.0, -100.0, -90.0, -45.0}) {
    const auto nearest = reach::nearest_reachable_axis<dmu_80p>(sajo_to_dmu(sajo_axis(a_s, 33.0)));
    INFO("a_s = " << a_s);
    // At a_s = -90 deg the target pose is the pole B = 0 with C free, where the objective is
    // flat in C and converges slowly: compare the dot product, not the angle.
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
    // At the pole (B = 0, C free) the objective 1 − u·v is flat to second order: cosines there.
    if (closed.gap.value < 1e-9) CHECK(cosine_near_one(numeric.gap));
    else CHECK(in_deg(closed.gap) == Approx(in_deg(numeric.gap)).margin(tol_deg));
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

TEST_CASE("SAJO 12000P to DMU 80P: the regions of Tian et al. 2010 section 1.1, both ways", "[reach][match]") {
  const auto t = reach::make_pair_table(sajo_12000p::model, dmu_80p::model, default_setup<sajo_12000p, dmu_80p>(), true);
  REQUIRE(t.rows_independent);  // T Y_s = Z_d: the regions do not depend on B
  const auto& regions = t.rows.front().regions;
  REQUIRE(regions.size() == 3);
  // [-120, -90) other branch, [-90, 0] direct, (0, 30] unreachable with worst gap 30 at A = 30.
  CHECK(regions[0].match == matchability::other_branch);
  CHECK((in_deg({regions[0].lo}) == Approx(-120.0).margin(1e-12) && regions[0].lo_included));
  CHECK((in_deg({regions[0].hi}) == Approx(-90.0).margin(1e-12) && !regions[0].hi_included));
  CHECK(regions[1].match == matchability::direct);
  CHECK((regions[1].lo_included && regions[1].hi_included));
  CHECK(in_deg({regions[1].hi}) == Approx(0.0).margin(1e-12));
  CHECK(regions[2].match == matchability::unreachable);
  CHECK((!regions[2].lo_included && regions[2].hi_included));
  CHECK(in_deg({regions[2].worst_gap_rad}) == Approx(30.0).margin(1e-12));
  CHECK(in_deg({regions[2].worst_gap_at_rad}) == Approx(30.0).margin(1e-12));
  // Ipopt: the branch boundary where the latitude about Y_s is extreme, the reach boundary
  // from the gap alone, and the worst gap.
  REQUIRE(t.branch_checks.size() == 1);
  CHECK(in_deg({t.branch_checks[0].numeric}) == Approx(-90.0).margin(tol_deg));
  const auto& checks = t.checks.front();
  REQUIRE(checks.size() == 2);
  CHECK(checks[0].what == "reach boundary");
  CHECK(in_deg({checks[0].numeric}) == Approx(0.0).margin(tol_deg));
  CHECK(checks[1].what == "worst gap");
  CHECK(in_deg({checks[1].numeric}) == Approx(30.0).margin(tol_deg));
}

TEST_CASE("Per-block gap of SAJO poses on the DMU 80P: closed form = A = Ipopt above 0", "[reach][match]") {
  const reach::pair_geometry g(sajo_12000p::model, dmu_80p::model, default_setup<sajo_12000p, dmu_80p>().rotation);
  for (double b_s : {-170.0, 0.0, 77.0}) {
    const reach::pose_row row = reach::row_regions(g, deg(b_s));
    for (double a_s : {0.5, 5.0, 17.0, 30.0}) {
      INFO("a_s = " << a_s << ", b_s = " << b_s);
      radians closed{};
      g.classify_pose({radians{deg(b_s)}, radians{deg(a_s)}}, &closed);
      CHECK(in_deg(closed) == Approx(a_s).margin(1e-12));
      std::vector<std::vector<double>> starts;
      CHECK(reach::numeric_gap(g, row, deg(a_s), starts) * 180.0 / pi == Approx(a_s).margin(tol_deg));
    }
  }
}
