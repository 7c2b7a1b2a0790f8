// The closed-form matchability of every ordered catalog pair (reach/pair_geometry.hpp,
// reach/pair_regions.hpp) against the core solver: `inverse` (solutions enumerated with their
// 360° shifts, flagged within travel) and `classify` (matchability.hpp). For each pair, 10,000
// source poses read off their row's regions and 10,000 tool axes classified for the map; each
// class must be what the solver says. Draws within 1e-7 rad of a class boundary are skipped:
// there the two sides use different tolerances (1e-9 in latitude, 1e-9 in angle).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>
#include <string>
#include <vector>

#include <kin5/machines/catalog.hpp>
#include <kin5/reach/pair_regions.hpp>
#include <kin5/translate/setup.hpp>

#include "../core/generators.hpp"

using namespace kin5;
using namespace kin5::reach;

namespace {

constexpr int draws_per_case = 100;  // × RapidCheck's 100 cases = 10,000 draws per pair
constexpr double near = 1e-7;

template <class F>
void for_each_pair(F&& f) {
  for (const machine_model* from : machines::catalog_models)
    for (const machine_model* to : machines::catalog_models) f(*from, *to);
}

/// A value of the range: uniform, or exactly one of `specials`.
rc::Gen<double> in_range_or(commanded_range r, std::vector<double> specials) {
  specials.push_back(r.lo), specials.push_back(r.hi);
  return rc::gen::weightedOneOf<double>({{9, test::real_in(r.lo, r.hi)}, {1, rc::gen::elementOf(specials)}});
}

/// Swept angles where the class of the row may change: the branch meets of the source.
std::vector<double> branch_points(const machine_model& from) {
  std::vector<row_point> pts;
  if (from.rotary_count == 2) {
    const latitude_curve own = carried_curve(from, from.rotary(0).direction);
    for (double e : {own.delta.value, own.delta.value + pi})
      reach::detail::add_shifts(pts, e, from.rotary(1).psi_per_commanded(), range_of(from.rotary(1)), 0);
  }
  std::vector<double> out;
  for (const auto& p : pts) out.push_back(p.at);
  return out;
}

/// The region of `row` holding swept angle s, or null within `near` of a class boundary.
const region* region_at(const pose_row& row, double s) {
  for (const auto& p : row.points)
    if (p.boundary && std::abs(p.at - s) < near) return nullptr;
  for (const auto& r : row.regions) {
    const bool above = r.lo_included ? s >= r.lo : s > r.lo;
    const bool below = r.hi_included ? s <= r.hi : s < r.hi;
    if (above && below) return &r;
  }
  return nullptr;
}

std::string pair_name(const machine_model& from, const machine_model& to) {
  return std::string(from.geometry.id) + " -> " + std::string(to.geometry.id);
}

void poses_agree_with_classify(const machine_model& from, const machine_model& to) {
  const mat3 R = default_setup(from.geometry.id, to.geometry.id).rotation;
  const pair_geometry g(from, to, R);
  const commanded_range fixed_range = range_of(from.rotary(0));
  const commanded_range swept_range = range_of(from.rotary(from.rotary_count - 1));
  const std::string name = pair_name(from, to);
  rc::prop(name + ": each pose has the class of its region", [&] {
    const double fixed = *in_range_or(fixed_range, {0.0, pi / 2, -pi / 2});
    const pose_row row = row_regions(g, fixed);
    const auto swept = *rc::gen::container<std::vector<double>>(draws_per_case, in_range_or(swept_range, branch_points(from)));
    for (double s : swept) {
      const region* r = region_at(row, s);
      if (!r) continue;
      const rotary_values pose = reach::detail::pose_on_row(from, row, s);
      radians gap{};
      const matchability solver = classify(from, to, pose, R, &gap);
      RC_ASSERT(solver == r->match);
      if (solver == matchability::unreachable) RC_ASSERT(gap.value <= r->worst_gap_rad + 1e-9);
    }
  });
}

/// Latitude margin of u_s from every band edge of the pair (π when nothing is banded).
double margin(const pair_geometry& g, const vec3& u_s) {
  double m = pi;
  if (g.band_target)
    for (double e : g.target_band.edges()) m = std::min(m, std::abs(angle_between(g.target_axis_in_source, u_s).value - e));
  if (g.band_source)
    for (const auto& band : g.source_bands)
      for (double e : band.edges()) m = std::min(m, std::abs(angle_between(g.from().rotary(0).direction, u_s).value - e));
  return m;
}

void orientations_agree_with_inverse(const machine_model& from, const machine_model& to) {
  const mat3 R = default_setup(from.geometry.id, to.geometry.id).rotation;
  const pair_geometry g(from, to, R);
  const vec3 p_s = from.rotary(0).direction, d = g.target_axis_in_source;
  const std::vector<vec3> specials{p_s, -1.0 * p_s, d, -1.0 * d, unit_x, unit_y, unit_z, -1.0 * unit_z};
  const auto unit = rc::gen::weightedOneOf<vec3>({{19, test::unit_vector()}, {1, rc::gen::elementOf(specials)}});
  const std::string name = pair_name(from, to);
  rc::prop(name + ": a tool axis classified reachable is solved within travel, and no other", [&] {
    const auto axes = *rc::gen::container<std::vector<vec3>>(draws_per_case, unit);
    for (const vec3& u : axes) {
      if (margin(g, u) < near) continue;
      radians gap{};
      const orientation_class c = g.classify_orientation(u, &gap);
      const auto source = inverse(from, u);
      const bool source_holds = source.reachable();
      RC_ASSERT(source_holds == (c != orientation_class::not_on_source));
      if (!source_holds) continue;
      // Which branches hold u (away from the source's poles, where `inverse` keeps one).
      if (norm(cross(p_s, u)) > 1e-6) {
        unsigned bits = 0;
        for (const auto& s : source)
          if (s.within_travel) bits |= 1u << s.branch;
        RC_ASSERT(bits == g.source_branches(u));
      }
      const auto target = inverse(to, R * u);
      RC_ASSERT(target.reachable() == (c != orientation_class::unreachable));
      // The band's gap is exact; inverse's is exact too when only q is bounded, an upper bound
      // otherwise.
      if (!target.reachable()) RC_ASSERT(gap.value <= target.gap.value + 1e-9);
    }
  });
}

}  // namespace

TEST_CASE("Pose regions of every pair agree with classify (10,000 draws per pair)", "[reach][match]") {
  for_each_pair(poses_agree_with_classify);
}

TEST_CASE("Map classes of every pair agree with inverse (10,000 draws per pair)", "[reach][match]") {
  for_each_pair(orientations_agree_with_inverse);
}
