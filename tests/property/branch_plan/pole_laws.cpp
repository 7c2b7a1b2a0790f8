// (P31) Rotary continuity at the poles: on paths of tool axes that cross, graze or jitter about
// a pole of any bundled machine, no planned block turns the rotary axes by more than the move
// needs — the least travel from where the previous block left them to a pose of the block's
// tool axis (to the pole itself, free angle kept, within `pole_zone` of it) — plus 1e-4 rad;
// and every planned tool axis is the block's to within `pole_zone`.
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kinematics.hpp>
#include <kin5/kinematics/branch_plan.hpp>
#include <kin5/machines/every_machine.hpp>

#include "angle_generators.hpp"

namespace {

using namespace kin5;

/// 10^x for x uniform in [lo, hi].
rc::Gen<double> log_uniform(double lo, double hi) {
  return rc::gen::map(test::uniform(lo, hi), [](double x) { return std::pow(10.0, x); });
}

/// Two unit vectors normal to `n` and to each other.
std::array<vec3, 2> tangent_basis(const vec3& n) {
  const vec3 seed = std::abs(n.x) < 0.9 ? vec3{1, 0, 0} : vec3{0, 1, 0};
  const vec3 e1 = normalized(seed - dot(seed, n) * n);
  return {e1, cross(n, e1)};
}

/// The rotary travel of a step as the machine makes it, Σ|Δ| (radians; the planner unwraps
/// continuous axes next to the previous block, so this is the short way round).
template <machine M>
double travel(const rotary_angles<M>& from, const rotary_angles<M>& to) {
  double sum = 0.0;
  for (std::size_t i = 0; i < rotary_count<M>; ++i) sum += std::abs(to[i].value - from[i].value);
  return sum;
}

/// What the move from `from` to tool axis `u` needs: the least travel to a within-travel pose of
/// M giving `u`, or, when `u` is within the pole zone of `pole`, giving the pole (free angle kept).
template <machine M>
double need(const rotary_angles<M>& from, const vec3& u, const vec3& pole) {
  double best = 1e300;
  inverse_options keep{};
  keep.pole = pole_policy::keep(from[0]);
  for (const auto& s : inverse<M>(u, keep))
    if (s.within_travel) best = std::min(best, rotary_step_cost<M>(from, s.angles));
  if (angle_between(u, pole).value <= pole_zone.value)
    for (const auto& s : inverse<M>(pole, keep))
      if (s.within_travel) best = std::min(best, rotary_step_cost<M>(from, s.angles));
  return best;
}

/// A path near a pole of M within travel: a straight line through it or past it (miss distance
/// 0, inside the pole zone, or beyond), tool axes alternating either side of it, or a line
/// ending at it; with its pole.
template <machine M>
std::pair<std::vector<vec3>, vec3> near_pole_path() {
  constexpr auto g = geometry<M>();
  const vec3 pole = *rc::gen::element(1.0, -1.0) * g.p;
  RC_PRE(inverse<M>(pole).first_within_travel().has_value());
  const auto [e1, e2] = tangent_basis(pole);
  const double phi = *test::uniform(-pi, pi);
  const vec3 along = std::cos(phi) * e1 + std::sin(phi) * e2, across = cross(pole, along);
  const auto n = *rc::gen::inRange<std::size_t>(2, 13);
  const int kind = *rc::gen::inRange(0, 3);
  const double miss = *rc::gen::inRange(0, 3) == 0 ? 0.0 : *log_uniform(-12, -1.5);
  const double reach = *log_uniform(-9, -0.7);  // half length of the line, or the jitter
  std::vector<vec3> path;
  for (std::size_t k = 0; k < n; ++k) {
    const double f = static_cast<double>(k) / static_cast<double>(n - 1);
    const double s = kind == 0 ? reach * (2.0 * f - 1.0) : kind == 1 ? (k % 2 ? reach : -reach) : reach * (1.0 - f);
    path.push_back(normalized(pole + s * along + miss * across));
  }
  return {path, pole};
}

}  // namespace

TEST_CASE("(P31) near a pole no block turns the rotary axes by more than the move needs") {
  machines::for_each_machine_in<machines::every_machine>([]<class M>() {
    if constexpr (rotary_count<M> == 2) {
      rc::prop(std::string("crossing, grazing, jittering about a pole of ") + std::string(M::id), [] {
        const auto [axes, pole] = near_pole_path<M>();
        const auto plan = plan_rotary_path<M>(std::span<const vec3>(axes));
        for (const auto& a : plan.angles) RC_PRE(a.has_value());
        for (std::size_t k = 0; k < axes.size(); ++k) {
          RC_ASSERT(angle_between(tool_axis<M>(*plan.angles[k]), axes[k]).value <= pole_zone.value + 1e-9);
          if (k == 0) continue;
          const double moved = travel<M>(*plan.angles[k - 1], *plan.angles[k]);
          RC_ASSERT(moved <= need<M>(*plan.angles[k - 1], axes[k], pole) + 1e-4);
        }
      });
    }
  });
}

TEST_CASE("(P31) the pole zone: a tool axis alternating 1e-9 rad about the pole keeps C") {
  using M = machines::dmu_80p;  // pole +Z: B = 0, C free; B cannot go below 0
  std::vector<vec3> axes{normalized(vec3{0.5, 0.0, 1.0})};
  for (int k = 0; k < 8; ++k) axes.push_back(normalized(vec3{k % 2 ? 1e-9 : -1e-9, 1e-10, 1.0}));
  const auto plan = plan_rotary_path<M>(std::span<const vec3>(axes));
  for (std::size_t k = 2; k < axes.size(); ++k) {
    REQUIRE(plan.angles[k].has_value());
    CHECK(travel<M>(*plan.angles[k - 1], *plan.angles[k]) <= 1e-9);  // without the zone: C turns 180°
  }
}
