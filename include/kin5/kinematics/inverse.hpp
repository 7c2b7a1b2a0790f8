/// @file inverse.hpp
/// Inverse kinematics of the orientation: a unit tool axis → every set of commanded rotary
/// angles that produces it, each flagged within or outside the axes' travel; (G1)–(G5) with each
/// ψ turned into the commanded angle by its axis' sense. `inverse(m, u)` takes a machine value,
/// `inverse<M>(u)` a machine type (same code, with a result sized for M).
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

/// One solution of the inverse: commanded rotary angles in chain order.
template <std::size_t N>
struct basic_axis_solution {
  std::array<radians, N> angles{};
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
  /// A linear axis value this far outside its travel (mm) is taken as within it.
  double linear_slack_mm = 1e-6;
};

/// Most solutions one tool axis can have on machine `m`: two branches (one on a 4-axis machine),
/// times, for each bounded axis, the number of 360° shifts its travel can hold.
constexpr std::size_t max_solutions(const machine_model& m) {
  std::size_t n = m.rotary_count == 2 ? 2 : 1;
  for (std::size_t i = 0; i < m.rotary_count; ++i)
    if (!m.rotary(i).travel.continuous)
      n *= static_cast<std::size_t>((m.rotary(i).travel.upper.value - m.rotary(i).travel.lower.value) / 360.0) + 1;
  return n;
}

/// `max_solutions` of machine type M.
template <machine_description M>
constexpr std::size_t max_solutions() {
  return max_solutions(M::model);
}

/// Most solutions of any valid machine: two branches, four shifts of each of two bounded axes.
inline constexpr std::size_t max_solutions_any = 2 * 4 * 4;

/// Every solution for one tool axis: up to `Capacity` solutions of N rotary angles.
template <std::size_t N, std::size_t Capacity>
struct basic_inverse_result {
  static constexpr std::size_t capacity = Capacity;

  reach_status status = reach_status::unreachable;
  radians gap{};  ///< angle from the requested axis to what the machine can reach; 0 if reachable
  std::array<basic_axis_solution<N>, Capacity> items{};
  std::size_t count = 0;

  constexpr const basic_axis_solution<N>* begin() const { return items.data(); }
  constexpr const basic_axis_solution<N>* end() const { return items.data() + count; }
  constexpr std::size_t size() const { return count; }
  constexpr const basic_axis_solution<N>& operator[](std::size_t i) const { return items[i]; }
  /// Whether at least one solution lies within the travel of every axis.
  constexpr bool reachable() const { return status != reach_status::unreachable; }
  /// The first solution within travel, if any.
  constexpr std::optional<std::array<radians, N>> first_within_travel() const {
    for (const auto& s : *this)
      if (s.within_travel) return s.angles;
    return std::nullopt;
  }
};

/// The inverse of a machine known at run time.
using inverse_values = basic_inverse_result<2, max_solutions_any>;
/// One solution for machine type M.
template <machine_description M>
using axis_solution = basic_axis_solution<rotary_count<M>>;
/// The inverse for machine type M, sized for it.
template <machine_description M>
using inverse_result = basic_inverse_result<rotary_count<M>, max_solutions<M>()>;

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

// Range of ∠(p, R(q, ψq) t) for ψq over the carried axis' travel (G5 with a bounded q).
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

// Appends every combination of the shifts of branch `b` to `out`, skipping duplicates.
template <std::size_t N, std::size_t Capacity>
constexpr void add_shifts(std::size_t n, const std::array<shifted_values, N>& shifts, bool within, int b,
                          basic_inverse_result<N, Capacity>& out) {
  std::array<std::size_t, N> idx{};
  while (true) {
    basic_axis_solution<N> s{};
    for (std::size_t i = 0; i < n; ++i) s.angles[i] = shifts[i].value[idx[i]];
    s.within_travel = within;
    s.branch = b;
    bool duplicate = false;
    for (const auto& other : out) {
      bool same = true;
      for (std::size_t i = 0; i < n; ++i) same = same && math::abs(other.angles[i].value - s.angles[i].value) <= 1e-12;
      duplicate = duplicate || same;
    }
    if (!duplicate && out.count < Capacity) out.items[out.count++] = s;
    std::size_t i = 0;
    while (i < n && ++idx[i] == shifts[i].count) idx[i++] = 0;
    if (i == n) break;
  }
}

// The gap of an axis every branch of which lies outside travel (see the file comment).
template <std::size_t N>
constexpr radians outside_travel_gap(const machine_model& m, const vec3& u, const two_axis_solution& raw,
                                     const inverse_options& options) {
  const double theta = angle_between(m.rotary(0).direction, normalized(u)).value;
  if (N >= 2 && m.rotary_count == 2) {
    const auto image = latitude_image(m.orientation, m.rotary(1));
    const double lat_gap = theta < image[0] ? image[0] - theta : (theta > image[1] ? theta - image[1] : 0.0);
    if (lat_gap > options.reach_tolerance.value) return {lat_gap};
  }
  double best = pi;
  for (std::size_t b = 0; b < raw.count; ++b) {
    if (m.rotary_count == 2 &&
        distance_to_travel(m.rotary(1).travel, m.rotary(1).commanded(raw.branch[b].psi_q)) > options.travel_slack.value)
      continue;
    const double d = distance_to_travel(m.rotary(0).travel, m.rotary(0).commanded(raw.branch[b].psi_p));
    // Turning u about p by d moves it through 2·asin(sin θ · sin(d/2)).
    const double moved = 2.0 * math::asin(math::clamp(math::sin(theta) * math::sin(0.5 * d), -1.0, 1.0));
    best = moved < best ? moved : best;
  }
  return {best};
}

}  // namespace detail

/// Every commanded angle set of machine `m` whose tool axis is `u` (unit, table frame at the
/// zero pose), written into `out` (N >= m.rotary_count; see `max_solutions` for the capacity),
/// replacing what it held: a controller may keep one result and reuse it on every call.
template <std::size_t N, std::size_t Capacity>
constexpr void inverse_into(const machine_model& m, const vec3& u, const inverse_options& options,
                            basic_inverse_result<N, Capacity>& out) noexcept {
  out.status = reach_status::unreachable;  // the header only: the items past `count` are not read
  out.gap = radians{0.0};
  out.count = 0;
  const std::size_t n = m.rotary_count < N ? m.rotary_count : N;
  two_axis_solution raw{};
  if (n == 2) {
    pole_policy policy = options.pole;
    if (policy.rule == pole_policy::kind::keep) policy.psi_p = m.rotary(0).psi(policy.psi_p);
    raw = m.orientation.solve(u, policy, options.reach_tolerance);
  } else {
    raw = m.orientation_single.solve(u, options.reach_tolerance);
  }
  out.gap = raw.gap;
  if (raw.count == 0) return;

  bool any_within = false;
  for (std::size_t b = 0; b < raw.count; ++b) {
    std::array<radians, 2> commanded{m.rotary(0).commanded(raw.branch[b].psi_p),
                                     n == 2 ? m.rotary(1).commanded(raw.branch[b].psi_q) : radians{}};
    std::array<detail::shifted_values, N> shifts{};
    bool within = true;
    for (std::size_t i = 0; i < n; ++i) {
      shifts[i] = detail::shifts_within(m.rotary(i).travel, commanded[i], options.travel_slack);
      within = within && shifts[i].within;
    }
    any_within = any_within || within;
    detail::add_shifts(n, shifts, within, static_cast<int>(b), out);
  }
  if (any_within) {
    out.status = raw.status;
    return;
  }
  out.status = reach_status::unreachable;
  out.gap = detail::outside_travel_gap<N>(m, u, raw, options);
}

/// Every commanded angle set of machine `m` whose tool axis is `u` (unit, table frame at the
/// zero pose): (G1)–(G5).
constexpr inverse_values inverse(const machine_model& m, const vec3& u, const inverse_options& options = {}) noexcept {
  inverse_values out{};
  inverse_into(m, u, options, out);
  return out;
}

/// Every commanded angle set of machine type M whose tool axis is `u`.
template <machine M>
constexpr inverse_result<M> inverse(const vec3& u, const inverse_options& options = {}) noexcept {
  inverse_result<M> out{};
  inverse_into(M::model, u, options, out);
  return out;
}

}  // namespace kin5
