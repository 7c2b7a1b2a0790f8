// One law suite, run for every catalog machine: the tool axis against the Eigen chain
// (P1, P2), FK∘IK and IK∘FK, travel flags, reach against a brute-force sweep, poles (S2,
// P16) and the branch-choice helpers.
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/eigen.hpp>
#include <kin5/kin5.hpp>
#include <kin5/machines/every_machine.hpp>

#include "generators.hpp"
#include "sweep.hpp"

namespace {

using namespace kin5;
using kin5::test::angle_between_eigen;

template <machine M>
vec3 oracle(const rotary_angles<M>& a) {
  return eigen::to_kin5(eigen::chain_tool_axis<M>(a));
}

double distance(const vec3& a, const vec3& b) { return std::sqrt(squared_norm(a - b)); }

/// Travel test written out here, independently of `rotary_travel::contains`.
bool inside_travel(const rotary_axis& a, double commanded, double slack) {
  if (a.travel.continuous) return true;
  const double lo = a.travel.lower.value * pi / 180.0, hi = a.travel.upper.value * pi / 180.0;
  return commanded >= lo - slack && commanded <= hi + slack;
}

/// |x − y| modulo 2π, in [0, π].
double circular_distance(double x, double y) { return std::abs(std::remainder(x - y, 2.0 * pi)); }

/// Whether a commanded angle set appears in the inverse result: continuous axes modulo 2π,
/// bounded axes by value.
template <machine M>
bool listed(const inverse_result<M>& r, const rotary_angles<M>& a, double tol) {
  for (const auto& s : r) {
    bool same = true;
    for (std::size_t i = 0; i < rotary_count<M>; ++i) {
      const double d = M::rotary[i].travel.continuous ? circular_distance(s.angles[i].value, a[i].value)
                                                      : std::abs(s.angles[i].value - a[i].value);
      same = same && d <= tol;
    }
    if (same) return true;
  }
  return false;
}

/// Angular distance from u to the nearest singular latitude: the pole(s) ±p and the edges of the
/// cone swept with ψq unlimited (S2, S3). Written from the definitions, not from the solver.
template <machine M>
double distance_to_singular(const vec3& u) {
  const vec3 p = M::rotary[0].direction, t = M::tool_reference;
  const double theta = std::acos(std::clamp(dot(p, u), -1.0, 1.0));
  double d = std::min(theta, pi - theta);
  if constexpr (rotary_count<M> == 2) {
    const vec3 q = M::rotary[1].direction;
    const double pq = std::acos(std::clamp(dot(p, q), -1.0, 1.0)), qt = std::acos(std::clamp(dot(q, t), -1.0, 1.0));
    const double lo = std::abs(pq - qt), hi = std::min(pq + qt, 2.0 * pi - pq - qt);
    d = std::min({d, std::abs(theta - lo), std::abs(theta - hi)});
  }
  return d;
}

/// Whether some bounded axis sits exactly on a travel limit.
template <machine M>
bool at_a_limit(const rotary_angles<M>& a) {
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    const auto& tr = M::rotary[i].travel;
    if (!tr.continuous && (a[i].value == to_radians(tr.lower).value || a[i].value == to_radians(tr.upper).value))
      return true;
  }
  return false;
}

/// Whether every commanded value of p's travel sweeps at least one full turn.
template <machine M>
constexpr bool p_covers_turn() {
  const auto& tr = M::rotary[0].travel;
  return tr.continuous || tr.upper.value - tr.lower.value >= 360.0;
}

/// A direction near the edge of what M reaches: the tool axis at a travel limit, tilted a little.
template <machine M>
rc::Gen<vec3> near_reach_edge() {
  return rc::gen::apply(
      [](rotary_angles<M> a, std::size_t axis, bool upper, double eps, double phi) {
        const auto& tr = M::rotary[axis].travel;
        if (!tr.continuous) a[axis] = to_radians(upper ? tr.upper : tr.lower);
        return test::tilted(oracle<M>(a), eps, phi);
      },
      test::angles_within<M>(), rc::gen::inRange<std::size_t>(0, rotary_count<M>), rc::gen::arbitrary<bool>(),
      test::log_uniform(-7.0, -1.0), test::real_in(-pi, pi));
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("forward kinematics equals the Eigen chain (P1, P2)", "[core][forward]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("|u| = 1 and tool_axis = chain_tool_axis to 1e-12", [] {
    const auto a = *rc::gen::oneOf(test::angles_within<M>(), test::angles_anywhere<M>());
    const vec3 u = tool_axis<M>(a);
    RC_ASSERT(std::abs(norm(u) - 1.0) <= 1e-12);
    RC_ASSERT(distance(u, oracle<M>(a)) <= 1e-12);
  });
}

TEMPLATE_LIST_TEST_CASE("FK∘IK = id and IK∘FK contains the generating angles", "[core][inverse]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("every listed solution reproduces u", [] {
    const auto a = *test::angles_within<M>();
    const vec3 u = oracle<M>(a);
    const auto r = inverse<M>(u);
    RC_LOG() << "u = (" << u.x << ", " << u.y << ", " << u.z << ")\n";
    RC_ASSERT(r.status != reach_status::unreachable);
    RC_ASSERT(r.size() > 0u);
    const double pole_distance = norm(cross(M::rotary[0].direction, u));
    const double tol = r.status == reach_status::pole ? 1e-12 + 2.0 * pole_distance : 1e-12;
    for (const auto& s : r) {
      // inverse clamps a value up to travel_slack (1e-9 rad) outside a limit onto it; such a
      // solution is only that close (|du/dψ| <= 1).
      const double clamp_tol = at_a_limit<M>(s.angles) ? inverse_options{}.travel_slack.value : 0.0;
      RC_ASSERT(distance(oracle<M>(s.angles), u) <= tol + clamp_tol);
    }
  });
  rc::prop("near and at the poles ±p (1e-12..1e-3 rad): every listed solution reproduces u", [] {
    const vec3 u = *test::near_axis(M::rotary[0].direction);
    const auto r = inverse<M>(u);
    const double pole_distance = norm(cross(M::rotary[0].direction, u));
    const double tol = r.status == reach_status::pole ? 1e-12 + 2.0 * pole_distance : 1e-12;
    for (const auto& s : r) {
      if (r.status == reach_status::unreachable) break;  // listed angles are then only nearest shifts
      const double clamp_tol = at_a_limit<M>(s.angles) ? inverse_options{}.travel_slack.value : 0.0;
      RC_ASSERT(distance(oracle<M>(s.angles), u) <= tol + clamp_tol);
    }
  });
  rc::prop("the generating angles are among the solutions, flagged within travel", [] {
    const auto a = *test::angles_within<M>();
    const vec3 u = oracle<M>(a);
    RC_PRE(distance_to_singular<M>(u) > 1e-5);
    const auto r = inverse<M>(u);
    RC_ASSERT(r.status == reach_status::reachable);
    RC_ASSERT(listed<M>(r, a, 1e-9));
    bool flagged = false;
    for (const auto& s : r) {
      bool same = true;
      for (std::size_t i = 0; i < rotary_count<M>; ++i)
        same = same && (M::rotary[i].travel.continuous ? circular_distance(s.angles[i].value, a[i].value)
                                                       : std::abs(s.angles[i].value - a[i].value)) <= 1e-9;
      flagged = flagged || (same && s.within_travel);
    }
    RC_ASSERT(flagged);
  });
}

TEMPLATE_LIST_TEST_CASE("travel flags and output ranges", "[core][inverse]", kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("within_travel is exactly 'every axis inside its travel'; status agrees", [] {
    const vec3 u = *rc::gen::oneOf(test::unit_vector(), near_reach_edge<M>(), test::near_axis(M::rotary[0].direction),
                                   rc::gen::map(test::angles_anywhere<M>(), [](auto a) { return oracle<M>(a); }));
    const auto r = inverse<M>(u);
    bool any_within = false;
    for (const auto& s : r) {
      bool inside = true;
      for (std::size_t i = 0; i < rotary_count<M>; ++i) {
        inside = inside && inside_travel(M::rotary[i], s.angles[i].value, 1e-9);
        if (M::rotary[i].travel.continuous) {  // reported in (−π, π]
          RC_ASSERT(s.angles[i].value > -pi);
          RC_ASSERT(s.angles[i].value <= pi);
        }
      }
      RC_ASSERT(s.within_travel == inside);
      any_within = any_within || s.within_travel;
    }
    RC_ASSERT(r.reachable() == any_within);
    RC_ASSERT((r.status == reach_status::unreachable) == (r.gap.value > 0.0));
    RC_ASSERT(r.first_within_travel().has_value() == any_within);
  });
}

TEMPLATE_LIST_TEST_CASE("reach and gap agree with a dense sweep of the Eigen chain", "[core][reach]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("unreachable exactly when the sweep finds no pose; gap = sweep minimum", [] {
    const vec3 u = *rc::gen::oneOf(test::unit_vector(), near_reach_edge<M>(), test::near_axis(M::rotary[0].direction));
    double swept = 0.0;
    if constexpr (p_covers_turn<M>()) {
      swept = test::sweep_min_angle_turning_p<M>(eigen::to_eigen(u));
    } else {
      swept = test::sweep_min_angle<M>(eigen::to_eigen(u));
    }
    const auto r = inverse<M>(u);
    RC_LOG() << "u = (" << u.x << ", " << u.y << ", " << u.z << "), sweep " << swept << ", gap " << r.gap.value
             << "\n";
    if (swept < 1e-12) RC_ASSERT(r.reachable());
    if (swept > 1e-9) {
      RC_ASSERT(!r.reachable());
      if constexpr (p_covers_turn<M>()) {
        RC_ASSERT(std::abs(r.gap.value - swept) <= 1e-12);
      } else {
        RC_ASSERT(r.gap.value >= swept - 1e-8);  // an upper bound when p is bounded (inverse.hpp)
      }
    }
  });
}

TEST_CASE("closed-form gaps of single machines (P7, P14, K25)", "[core][reach]") {
  using kin5::machines::dmu_80p;
  rc::prop("dmu-80p: k < 0 is unreachable with gap asin(-k) (P7)", [] {
    vec3 u = *test::unit_vector();
    if (u.z > 0) u.z = -u.z;
    RC_PRE(u.z < -1e-9);
    const auto r = inverse<dmu_80p>(u);
    RC_ASSERT(r.status == reach_status::unreachable);
    RC_ASSERT(std::abs(r.gap.value - std::asin(-u.z)) <= 1e-12);
  });
  rc::prop("sajo A in (0, 180) mapped by T is unreachable on dmu-80p; gap min(a, 180-a) (P14)", [] {
    const double a = *test::real_in(1e-6, pi - 1e-6), b = *test::real_in(-2 * pi, 2 * pi);
    // (K1) written out, then (K11): (x, y, z) -> (-x, z, y).
    const vec3 u_s{std::cos(a) * std::sin(b), -std::sin(a), std::cos(a) * std::cos(b)};
    const vec3 u_d{-u_s.x, u_s.z, u_s.y};
    const auto r = inverse<dmu_80p>(u_d);
    RC_ASSERT(r.status == reach_status::unreachable);
    RC_ASSERT(std::abs(r.gap.value - std::min(a, pi - a)) <= 1e-12);
  });
  rc::prop("sajo-12000p: u_y < -sin 30 deg is unreachable with gap acos(u_y) - 120 deg", [] {
    vec3 u = *test::unit_vector();
    RC_PRE(u.y < -0.5 - 1e-9);
    const auto r = inverse<kin5::machines::sajo_12000p>(u);
    RC_ASSERT(r.status == reach_status::unreachable);
    RC_ASSERT(std::abs(r.gap.value - (std::acos(u.y) - 2.0 * pi / 3.0)) <= 1e-12);
  });
  rc::prop("a-rotary-4axis: gap |asin(u_x)|, and A = atan2(-u_y, u_z) when u_x = 0 (K25)", [] {
    const vec3 u = *test::unit_vector();
    const auto r = inverse<kin5::machines::a_rotary_4axis>(u);
    if (std::abs(u.x) > 1e-9) {
      RC_ASSERT(r.status == reach_status::unreachable);
      RC_ASSERT(std::abs(r.gap.value - std::asin(std::abs(u.x))) <= 1e-12);
    }
    const double n = std::hypot(u.y, u.z);
    const vec3 v{0.0, u.y / n, u.z / n};
    const auto rv = inverse<kin5::machines::a_rotary_4axis>(v);
    RC_ASSERT(rv.status == reach_status::reachable);
    RC_ASSERT(rv.size() == 1u);
    // u = R(X, A) z = (0, -sin A, cos A); K25's A is measured the other way (physical, K26).
    RC_ASSERT(circular_distance(rv[0].angles[0].value, std::atan2(-v.y, v.z)) <= 1e-12);
  });
}

TEMPLATE_LIST_TEST_CASE("poles (S2): keep and approach policies", "[core][pole]", kin5::machines::every_machine) {
  using M = TestType;
  if constexpr (rotary_count<M> == 2) {
    const vec3 p = M::rotary[0].direction;
    rc::prop("keep: at u = ±p the given angle of p is kept, and FK returns the pole", [&] {
      const double kept = *test::real_in(-pi, pi);
      int poles = 0;
      for (double sign : {1.0, -1.0}) {
        inverse_options o{};
        o.pole = pole_policy::keep(radians{kept});
        const auto r = inverse<M>(sign * p, o);
        if (r.status != reach_status::pole) continue;
        ++poles;
        for (const auto& s : r) {
          RC_ASSERT(circular_distance(s.angles[0].value, kept) <= 1e-12);
          RC_ASSERT(distance(oracle<M>(s.angles), sign * p) <= 1e-12);
        }
      }
      RC_ASSERT(poles >= 1);  // every catalog two-axis machine reaches one of its poles
    });
    rc::prop("approach: the pole angle is the limit of the angles along the approach direction", [&] {
      const double phi = *test::real_in(-pi, pi);
      const double eps = *test::log_uniform(-8.0, -6.0);
      for (double sign : {1.0, -1.0}) {
        const vec3 pole = sign * p;
        const vec3 v = test::perpendicular(pole, phi);
        inverse_options o{};
        o.pole = pole_policy::approach(v);
        const auto at = inverse<M>(pole, o);
        if (at.status != reach_status::pole) continue;
        const auto near = inverse<M>(test::tilted(pole, eps, phi), o);
        for (const auto& s : at) {
          bool found = false;
          for (const auto& n : near)
            found = found || (n.branch == s.branch && circular_distance(n.angles[0].value, s.angles[0].value) <= 1e-4 &&
                              circular_distance(n.angles[1].value, s.angles[1].value) <= 1e-4);
          RC_LOG() << "branch " << s.branch << " at pole: " << s.angles[0].value << ", " << s.angles[1].value << "\n";
          RC_ASSERT(found);
        }
      }
    });
  }
}

TEST_CASE("Tian 2010 pole convention by approach (P16)", "[core][pole]") {
  using kin5::machines::dmu_80p;
  rc::prop("sajo (A, B) = (-90, b) to dmu-80p gives B = 0, C = b + 90", [] {
    const double b = *test::real_in(-2 * pi, 2 * pi);
    // The sajo tool axis leaves +Y_s along d/da (K1) at a = -90: (sin b, 0, cos b); T maps it.
    const vec3 leave_s{std::sin(b), 0.0, std::cos(b)};
    const vec3 leave_d{-leave_s.x, leave_s.z, leave_s.y};
    inverse_options o{};
    o.pole = pole_policy::approach(leave_d);
    const auto r = inverse<dmu_80p>(unit_z, o);
    RC_ASSERT(r.status == reach_status::pole);
    bool found = false;
    for (const auto& s : r)
      found = found || (s.branch == 0 && s.within_travel && std::abs(s.angles[1].value) <= 1e-12 &&
                        circular_distance(s.angles[0].value, b + pi / 2) <= 1e-12);
    RC_ASSERT(found);
  });
}

TEMPLATE_LIST_TEST_CASE("unwrap_continuous and nearest_within_travel", "[core][branch]", kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("unwrap: continuous axes land within 180 deg of previous, congruent; bounded unchanged", [] {
    const auto a = *test::angles_anywhere<M>();
    rotary_angles<M> prev{};
    for (auto& x : prev) x = *test::angle_in(-20 * pi, 20 * pi);
    const auto w = unwrap_continuous<M>(a, prev);
    for (std::size_t i = 0; i < rotary_count<M>; ++i) {
      if (M::rotary[i].travel.continuous) {
        RC_ASSERT(std::abs(w[i].value - prev[i].value) <= pi + 1e-12);
        RC_ASSERT(circular_distance(w[i].value, a[i].value) <= 1e-12);
      } else {
        RC_ASSERT(w[i].value == a[i].value);
      }
    }
  });
  rc::prop("nearest: a listed within-travel solution with the least (largest move, sum of moves)", [] {
    const vec3 u = *rc::gen::oneOf(test::unit_vector(),
                                   rc::gen::map(test::angles_within<M>(), [](auto a) { return oracle<M>(a); }));
    rotary_angles<M> prev{};
    for (std::size_t i = 0; i < rotary_count<M>; ++i)
      prev[i] = M::rotary[i].travel.continuous ? *test::angle_in(-6 * pi, 6 * pi) : *test::axis_angle_within(M::rotary[i]);
    const auto r = inverse<M>(u);
    const auto chosen = nearest_within_travel<M>(r, prev);
    RC_ASSERT(chosen.has_value() == r.reachable());
    if (!chosen) return;
    // Every within-travel candidate, continuous axes unwrapped here with std::remainder.
    auto cost = [&](const rotary_angles<M>& c) {
      double largest = 0, sum = 0;
      for (std::size_t i = 0; i < rotary_count<M>; ++i) {
        const double d = std::abs(c[i].value - prev[i].value);
        largest = std::max(largest, d);
        sum += d;
      }
      return std::pair{largest, sum};
    };
    bool is_candidate = false;
    const auto chosen_cost = cost(*chosen);
    for (const auto& s : r) {
      if (!s.within_travel) continue;
      rotary_angles<M> c = s.angles;
      for (std::size_t i = 0; i < rotary_count<M>; ++i)
        if (M::rotary[i].travel.continuous)
          c[i] = radians{prev[i].value + std::remainder(c[i].value - prev[i].value, 2.0 * pi)};
      const auto k = cost(c);
      RC_ASSERT(chosen_cost.first <= k.first + travel_tie);  // largest moves within the tie are equal
      bool same = true;
      for (std::size_t i = 0; i < rotary_count<M>; ++i) same = same && std::abs(c[i].value - (*chosen)[i].value) <= 1e-12;
      is_candidate = is_candidate || same;
    }
    RC_ASSERT(is_candidate);
    for (std::size_t i = 0; i < rotary_count<M>; ++i)
      if (M::rotary[i].travel.continuous) RC_ASSERT(std::abs((*chosen)[i].value - prev[i].value) <= pi + 1e-12);
  });
}

TEST_CASE("nearest_within_travel: equal largest moves are decided by the sum of moves", "[core][branch]") {
  using kin5::machines::ac_trunnion;
  // Both branches tilt A by 114.5861° from A = 0; the largest moves differ by one ulp. The
  // C = 72.6764° branch moves C by 72.7° instead of 107.3°, so it moves less in sum.
  const vec3 u{-0.86808798392234987, -0.27077116485630992, -0.41606036635563726};
  const auto chosen = nearest_within_travel<ac_trunnion>(inverse<ac_trunnion>(u), {radians{0.0}, radians{0.0}});
  REQUIRE(chosen.has_value());
  CHECK(std::abs((*chosen)[0].value * 180.0 / pi - 72.6764) < 1e-4);    // C
  CHECK(std::abs((*chosen)[1].value * 180.0 / pi + 114.5861) < 1e-4);  // A
}

TEMPLATE_LIST_TEST_CASE("nearest_within_travel: least largest move, ties to 1e-9 rad decided by the sum",
                        "[core][branch]", kin5::machines::every_machine) {
  using M = TestType;
  // Previous angles at zero make the two branches of an orthogonal chain tilt by exactly the same
  // amount (A = ±arccos k on ac-trunnion), the case where rounding used to decide; 20,000 fixed
  // draws so that the rare tie is met every run.
  std::mt19937_64 rng(8u);
  std::uniform_real_distribution<double> z(-1.0, 1.0), phi(-pi, pi);
  constexpr double tol = 1e-9;
  for (int n = 0; n < 20000; ++n) {
    const double zz = z(rng), r = std::sqrt(std::max(0.0, 1.0 - zz * zz)), f = phi(rng);
    const vec3 u{r * std::cos(f), r * std::sin(f), zz};
    const rotary_angles<M> prev{};
    const auto result = inverse<M>(u);
    const auto chosen = nearest_within_travel<M>(result, prev);
    REQUIRE(chosen.has_value() == result.reachable());
    if (!chosen) continue;
    auto cost = [&](const rotary_angles<M>& c) {
      double largest = 0, sum = 0;
      for (std::size_t i = 0; i < rotary_count<M>; ++i) {
        const double d = std::abs(c[i].value - prev[i].value);
        largest = std::max(largest, d);
        sum += d;
      }
      return std::pair{largest, sum};
    };
    const auto best = cost(*chosen);
    for (const auto& s : result) {
      if (!s.within_travel) continue;
      rotary_angles<M> c = s.angles;
      for (std::size_t i = 0; i < rotary_count<M>; ++i)
        if (M::rotary[i].travel.continuous) c[i] = radians{std::remainder(c[i].value - prev[i].value, 2.0 * pi)};
      const auto k = cost(c);
      INFO("u = (" << u.x << ", " << u.y << ", " << u.z << ")");
      REQUIRE(best.first <= k.first + tol);
      if (std::abs(k.first - best.first) <= tol) REQUIRE(best.second <= k.second + tol);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("principal branch: branch 0 of the full inverse gives the angles back", "[core][branch]",
                        kin5::machines::every_machine) {
  using M = TestType;
  // The definition, through every solution `inverse` returns (all branches, all 360° shifts).
  const auto by_inverse = [](const rotary_angles<M>& a) {
    inverse_options options{};
    options.pole = pole_policy::keep(a[0]);
    for (const auto& s : inverse<M>(tool_axis<M>(a), options)) {
      if (s.branch != 0) continue;
      bool same = true;
      for (std::size_t i = 0; i < rotary_count<M>; ++i)
        same = same && std::abs(math::wrap_pi(s.angles[i].value - a[i].value)) <= 1e-7;
      if (same) return true;
    }
    return rotary_count<M> == 1;
  };
  rc::prop("random angles, in and out of travel, and poses at a pole (S2)", [&] {
    rotary_angles<M> a = *rc::gen::oneOf(test::angles_within<M>(), test::angles_anywhere<M>());
    if (*rc::gen::inRange(0, 3) == 0) {  // the pole: the tool along ± the fixed axis, free angle kept
      inverse_options options{};
      options.pole = pole_policy::keep(a[0]);
      const vec3 pole = *rc::gen::arbitrary<bool>() ? M::rotary[0].direction : -1.0 * M::rotary[0].direction;
      const auto r = inverse<M>(pole, options);
      RC_CLASSIFY(r.size() > 0, "at a pole");
      if (r.size() > 0) a = r[*rc::gen::inRange<std::size_t>(0, r.size())].angles;  // else: out of reach
    }
    RC_ASSERT(on_principal_branch<M>(a) == by_inverse(a));
  });
}

TEMPLATE_LIST_TEST_CASE("inverse_into replaces what its result held", "[core][inverse]",
                        kin5::machines::every_machine) {
  using M = TestType;
  // A controller keeps one result of each inverse and hands it to every call (docs/embedding.md).
  rc::prop("a result reused over several calls is a fresh result of the last call", [] {
    const run_inputs in{.tool_length_mm = *test::real_in(0.0, 200.0)};
    const int calls = *rc::gen::inRange(2, 5);
    pose_values pose_out{};
    inverse_values axis_out{};
    tool_pose last{};
    for (int k = 0; k < calls; ++k) {
      // Poses within travel and anywhere, so that a reachable call may follow an unreachable one.
      axis_position<M> q = *test::axis_values_within<M>();
      q.rotary = *rc::gen::oneOf(test::angles_within<M>(), test::angles_anywhere<M>());
      last = forward<M>(q, in);
      inverse_into(M::model, last, in, {}, pose_out);
      inverse_into(M::model, last.axis, {}, axis_out);
    }
    const pose_values fresh = inverse(M::model, last, in);
    RC_ASSERT(pose_out.size() == fresh.size());
    RC_ASSERT(pose_out.status == fresh.status);
    RC_ASSERT(pose_out.gap.value == fresh.gap.value);
    RC_ASSERT(pose_out.linear_excess_mm == fresh.linear_excess_mm);
    for (std::size_t i = 0; i < fresh.size(); ++i) {
      RC_ASSERT(pose_out[i].joints.rotary == fresh[i].joints.rotary);
      RC_ASSERT(pose_out[i].within_travel == fresh[i].within_travel);
    }
    const inverse_values fresh_axis = inverse(M::model, last.axis);
    RC_ASSERT(axis_out.size() == fresh_axis.size());
    RC_ASSERT(axis_out.status == fresh_axis.status);
    RC_ASSERT(axis_out.gap.value == fresh_axis.gap.value);
    for (std::size_t i = 0; i < fresh_axis.size(); ++i) RC_ASSERT(axis_out[i].angles == fresh_axis[i].angles);
  });
}
