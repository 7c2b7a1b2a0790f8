/// @file inverse.hpp
/// Inverse kinematics of a machine type: a unit tool axis → every set of commanded rotary
/// angles that produces it, each flagged within or outside the axes' travel.
///
/// Output ranges: a continuous axis is reported in (−180°, 180°]; a bounded axis is reported at
/// every 360° shift of the angle that lies within its travel (so `ac-head` C ∈ [−360°, 360°]
/// can give two or three solutions per branch), or, when no shift fits, once, at the shift
/// nearest to the travel and flagged outside it. Unwrapping a continuous axis next to a previous
/// block is the job of `branch.hpp`.
///
/// An unreachable axis never gives NaN: the result says `unreachable` and carries the angular
/// gap to the reachable set (exact when only the carried axis q is bounded, an upper bound when
/// the fixed axis p is bounded too; kin5::reach computes it exactly).
#pragma once

#include <cstddef>
#include <optional>

#include "forward.hpp"

namespace kin5 {

/// One solution of the inverse: commanded rotary angles in `M::rotary` order.
template <machine M>
struct axis_solution {
  rotary_angles<M> angles{};
  bool within_travel = false;
  int branch = 0;  ///< 0 for the + branch of (G3), 1 for the − branch
};

/// Options for `inverse`.
struct inverse_options {
  /// How to choose the free angle at a pole (S2). `keep` takes a *commanded* angle of the
  /// fixed axis p here (the previous block's), not a ψ.
  pole_policy pole = pole_policy::keep(radians{0.0});
  /// A tool axis this close (angle) to the reachable set is treated as reachable.
  radians reach_tolerance{1e-9};
  /// An angle this far outside a travel limit is taken as on it (and clamped to it).
  radians travel_slack{1e-9};
};

/// Most solutions one tool axis can have on M: two branches (one on a 4-axis machine), times,
/// for each bounded axis, the number of 360° shifts its travel can hold.
template <machine M>
constexpr std::size_t max_solutions() {
  std::size_t n = rotary_count<M> == 2 ? 2 : 1;
  for (const auto& a : M::rotary)
    if (!a.travel.continuous)
      n *= static_cast<std::size_t>((a.travel.upper.value - a.travel.lower.value) / 360.0) + 1;
  return n;
}

/// Every solution for one tool axis.
template <machine M>
struct inverse_result {
  static constexpr std::size_t capacity = max_solutions<M>();

  reach_status status = reach_status::unreachable;
  radians gap{};  ///< angle from the requested axis to what the machine can reach; 0 if reachable
  std::array<axis_solution<M>, capacity> items{};
  std::size_t count = 0;

  constexpr const axis_solution<M>* begin() const { return items.data(); }
  constexpr const axis_solution<M>* end() const { return items.data() + count; }
  constexpr std::size_t size() const { return count; }
  constexpr const axis_solution<M>& operator[](std::size_t i) const { return items[i]; }
  /// Whether at least one solution lies within the travel of every axis.
  constexpr bool reachable() const { return status != reach_status::unreachable; }
  /// The first solution within travel, if any.
  constexpr std::optional<rotary_angles<M>> first_within_travel() const {
    for (const auto& s : *this)
      if (s.within_travel) return s.angles;
    return std::nullopt;
  }
};

namespace detail {

// The shifts of `commanded` by multiples of 2π that lie within `travel`, or the one nearest it.
struct shifted_values {
  std::array<radians, 4> value{};
  std::size_t count = 0;
  bool within = false;
};

constexpr shifted_values shifts_within(const rotary_travel& travel, radians commanded, radians slack) {
  shifted_values out{};
  if (travel.continuous) {
    out.value[0] = math::wrap_pi(commanded);
    out.count = 1;
    out.within = true;
    return out;
  }
  constexpr double two_pi = 2.0 * pi;
  const double lo = to_radians(travel.lower).value, hi = to_radians(travel.upper).value;
  // The first shift at or above lo − slack, then every further turn up to hi + slack.
  double v = lo + math::wrap_pi(commanded.value - lo);
  if (v < lo - slack.value) v += two_pi;
  for (; v <= hi + slack.value && out.count < out.value.size(); v += two_pi) out.value[out.count++] = {math::clamp(v, lo, hi)};
  if (out.count > 0) {
    out.within = true;
    return out;
  }
  // None fits: report the shift closest to the travel.
  const double mid = 0.5 * (lo + hi);
  const double near = mid + math::wrap_pi(commanded.value - mid);
  out.value[0] = {near};
  out.count = 1;
  return out;
}

// Distance from `commanded` (any shift) to `travel`, radians.
constexpr double distance_to_travel(const rotary_travel& travel, radians commanded) {
  if (travel.continuous) return 0.0;
  const double lo = to_radians(travel.lower).value, hi = to_radians(travel.upper).value;
  const double mid = 0.5 * (lo + hi);
  const double near = mid + math::wrap_pi(commanded.value - mid);
  double best = near < lo ? lo - near : (near > hi ? near - hi : 0.0);
  for (double k : {-1.0, 1.0}) {
    const double v = near + k * 2.0 * pi;
    const double d = v < lo ? lo - v : (v > hi ? v - hi : 0.0);
    if (d < best) best = d;
  }
  return best;
}

// Range of ∠(p, R(q, ψq) t) for ψq over the carried axis' travel ((G5) with a bounded q).
constexpr std::array<double, 2> latitude_image(const two_axis_geometry& g, const rotary_axis& axis_q) {
  if (axis_q.travel.continuous) return {g.theta_min.value, g.theta_max.value};
  const double a = axis_q.psi(to_radians(axis_q.travel.lower)).value;
  const double b = axis_q.psi(to_radians(axis_q.travel.upper)).value;
  const double lo = a < b ? a : b, hi = a < b ? b : a;
  auto latitude = [&](double psi_q) { return angle_between(g.p, g.tool_axis({0.0}, {psi_q})).value; };
  double mn = latitude(lo), mx = mn;
  auto take = [&](double x) { const double l = latitude(x); mn = l < mn ? l : mn; mx = l > mx ? l : mx; };
  take(hi);
  // Interior extremes at ψq = δ + kπ.
  double k0 = (lo - g.delta.value) / pi;
  long long k = static_cast<long long>(k0) - 1;
  for (int i = 0; i < 16; ++i, ++k) {
    const double x = g.delta.value + static_cast<double>(k) * pi;
    if (x >= lo && x <= hi) take(x);
  }
  return {mn, mx};
}

}  // namespace detail

/// All commanded angle sets of machine M whose tool axis is `u` (unit, workpiece frame).
/// (G1)–(G5) with each ψ turned into the commanded angle by its axis' sense.
template <machine M>
constexpr inverse_result<M> inverse(const vec3& u, const inverse_options& options = {}) {
  inverse_result<M> out{};
  constexpr auto g = geometry<M>();
  two_axis_solution raw{};
  if constexpr (rotary_count<M> == 2) {
    pole_policy policy = options.pole;
    if (policy.rule == pole_policy::kind::keep) policy.psi_p = M::rotary[0].psi(policy.psi_p);
    raw = g.solve(u, policy, options.reach_tolerance);
  } else {
    raw = g.solve(u, options.reach_tolerance);
  }
  out.gap = raw.gap;
  if (raw.count == 0) return out;

  bool any_within = false;
  for (std::size_t b = 0; b < raw.count; ++b) {
    rotary_angles<M> commanded{};
    commanded[0] = M::rotary[0].commanded(raw.branch[b].psi_p);
    if constexpr (rotary_count<M> == 2) commanded[1] = M::rotary[1].commanded(raw.branch[b].psi_q);

    std::array<detail::shifted_values, rotary_count<M>> shifts{};
    bool within = true;
    for (std::size_t i = 0; i < rotary_count<M>; ++i) {
      shifts[i] = detail::shifts_within(M::rotary[i].travel, commanded[i], options.travel_slack);
      within = within && shifts[i].within;
    }
    any_within = any_within || within;
    // Cartesian product of the shifts.
    std::array<std::size_t, rotary_count<M>> idx{};
    while (true) {
      axis_solution<M> s{};
      for (std::size_t i = 0; i < rotary_count<M>; ++i) s.angles[i] = shifts[i].value[idx[i]];
      s.within_travel = within;
      s.branch = static_cast<int>(b);
      bool duplicate = false;
      for (const auto& other : out) {
        bool same = true;
        for (std::size_t i = 0; i < rotary_count<M>; ++i)
          same = same && math::abs(other.angles[i].value - s.angles[i].value) <= 1e-12;
        duplicate = duplicate || same;
      }
      if (!duplicate && out.count < out.items.size()) out.items[out.count++] = s;
      std::size_t i = 0;
      while (i < rotary_count<M> && ++idx[i] == shifts[i].count) idx[i++] = 0;
      if (i == rotary_count<M>) break;
    }
  }

  if (any_within) {
    out.status = raw.status;
    return out;
  }
  // Outside travel: the gap through the carried axis' latitude image, else through p's travel.
  out.status = reach_status::unreachable;
  const double theta = angle_between(g.p, normalized(u)).value;
  if constexpr (rotary_count<M> == 2) {
    const auto image = detail::latitude_image(g, M::rotary[1]);
    const double lat_gap = theta < image[0] ? image[0] - theta : (theta > image[1] ? theta - image[1] : 0.0);
    if (lat_gap > options.reach_tolerance.value) {
      out.gap = {lat_gap};
      return out;
    }
  }
  double best = pi;
  for (std::size_t b = 0; b < raw.count; ++b) {
    if constexpr (rotary_count<M> == 2) {
      if (detail::distance_to_travel(M::rotary[1].travel, M::rotary[1].commanded(raw.branch[b].psi_q)) >
          options.travel_slack.value)
        continue;
    }
    const double d = detail::distance_to_travel(M::rotary[0].travel, M::rotary[0].commanded(raw.branch[b].psi_p));
    // Turning u about p by d moves it through 2·asin(sin θ · sin(d/2)).
    const double moved = 2.0 * math::asin(math::clamp(math::sin(theta) * math::sin(0.5 * d), -1.0, 1.0));
    best = moved < best ? moved : best;
  }
  out.gap = {best};
  return out;
}

}  // namespace kin5
