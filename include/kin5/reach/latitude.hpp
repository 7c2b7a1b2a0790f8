/// @file reach/latitude.hpp
/// Latitudes: the angle between a tool axis and a fixed direction, the quantity every reach
/// question of kin5 turns on. Two tools:
///
/// * `latitude_curve`: turning t about a unit axis a by ψ, the cosine of the angle to a fixed
///   unit direction d obeys the latitude equation (G2), whose roots (G3) generalise Tian et al.
///   2010 eqs (6) and (10):
///       κ(ψ) = d · R(a, ψ) t = c₀ + ρ cos(ψ − δ),
///       c₀ = (d·a)(a·t),  α = d·t − c₀,  β = d·(a × t),  ρ = √(α² + β²),  δ = atan2(β, α),
///   with its roots ψ = δ ± arccos((k − c₀)/ρ) (G3) and its extremes at ψ = δ and δ + π;
/// * `angle_set`: a union of closed intervals of angles in [0, π], e.g. the latitudes a machine
///   reaches about its fixed axis (G5), with the distance from an angle to the set (the gap).
///
/// Closed form only; the standard library and the core, no Ipopt.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "../core/math.hpp"
#include "../core/units.hpp"
#include "../core/vec.hpp"

namespace kin5::reach {

/// κ(ψ) = d · R(a, ψ) t = c₀ + ρ cos(ψ − δ) (see the file comment).
struct latitude_curve {
  double c0 = 0.0;
  double rho = 0.0;
  radians delta{};

  static constexpr latitude_curve make(const vec3& d, const vec3& a, const vec3& t) {
    const double c0 = dot(d, a) * dot(a, t);
    const double alpha = dot(d, t) - c0, beta = dot(d, cross(a, t));
    return {c0, math::sqrt(alpha * alpha + beta * beta), {math::atan2(beta, alpha)}};
  }
  /// κ at ψ.
  constexpr double kappa(radians psi) const { return c0 + rho * math::cos(psi.value - delta.value); }
  /// Every ψ in (−π, π] with κ(ψ) = k: none, one (a tangency, |k − c₀| = ρ) or two.
  constexpr std::array<double, 2> roots(double k, std::size_t& count) const {
    count = 0;
    if (!(rho > 1e-15)) return {};
    const double c = (k - c0) / rho;
    if (c > 1.0 + 1e-13 || c < -1.0 - 1e-13) return {};
    if (1.0 - math::abs(c) < 1e-14) {  // a tangency: one double root, not two 1e-7 apart
      count = 1;
      return {math::wrap_pi(c > 0 ? delta.value : delta.value + pi), 0.0};
    }
    const double half = math::acos(c);
    count = half > 0.0 && half < pi ? 2 : 1;
    return {math::wrap_pi(delta.value + half), math::wrap_pi(delta.value - half)};
  }
};

/// A closed interval of angles, radians.
struct angle_interval {
  double lo = 0.0;
  double hi = 0.0;
};

/// A union of closed intervals of angles in [0, π], kept sorted and disjoint.
class angle_set {
 public:
  angle_set() = default;
  /// The single interval [lo, hi].
  static angle_set between(double lo, double hi) {
    angle_set s;
    s.add(lo, hi);
    return s;
  }
  /// Adds [lo, hi] (in either order), merging overlapping intervals.
  void add(double lo, double hi) {
    if (hi < lo) std::swap(lo, hi);
    parts_.push_back({lo, hi});
    std::sort(parts_.begin(), parts_.end(), [](const auto& x, const auto& y) { return x.lo < y.lo; });
    std::vector<angle_interval> merged;
    for (const auto& p : parts_) {
      if (!merged.empty() && p.lo <= merged.back().hi) merged.back().hi = std::max(merged.back().hi, p.hi);
      else merged.push_back(p);
    }
    parts_ = merged;
  }
  bool empty() const { return parts_.empty(); }
  const std::vector<angle_interval>& parts() const { return parts_; }
  /// Angle from θ to the set (0 inside; π when the set is empty).
  double gap(double theta) const {
    double best = pi;
    for (const auto& p : parts_) {
      const double d = theta < p.lo ? p.lo - theta : (theta > p.hi ? theta - p.hi : 0.0);
      best = std::min(best, d);
    }
    return best;
  }
  /// Whether θ lies in the set, to `tolerance`.
  bool contains(double theta, double tolerance) const { return gap(theta) <= tolerance; }
  /// The ends of every interval: where a latitude enters or leaves the set.
  std::vector<double> edges() const {
    std::vector<double> out;
    for (const auto& p : parts_) {
      out.push_back(p.lo);
      if (p.hi > p.lo) out.push_back(p.hi);
    }
    return out;
  }

 private:
  std::vector<angle_interval> parts_;
};

/// The latitudes ∠(d, R(a, ψ) t) for ψ in [lo, hi] (radians, lo ≤ hi), split by the half turn
/// of ψ − δ they fall in: `by_half[0]` collects ψ − δ ∈ [0, π] (mod 2π), `by_half[1]` the rest.
/// On each half turn κ is monotonic, so each piece's image is the interval between its ends.
/// With d = p, a = q this is each (G3) branch's share of the reach (G5) within q's travel.
inline std::array<angle_set, 2> latitudes_by_half_turn(const latitude_curve& c, double lo, double hi) {
  std::array<angle_set, 2> out;
  auto latitude = [&](double psi) { return math::acos(math::clamp(c.kappa({psi}), -1.0, 1.0)); };
  // Half turns [δ + kπ, δ + (k+1)π]; the first one that reaches past lo.
  double k = std::floor((lo - c.delta.value) / pi);
  for (int guard = 0; guard < 16; ++guard, k += 1.0) {
    const double start = c.delta.value + k * pi, end = start + pi;
    if (start > hi) break;
    const double a = std::max(start, lo), b = std::min(end, hi);
    if (a <= b) {
      const long long ki = static_cast<long long>(k);
      out[((ki % 2) + 2) % 2].add(latitude(a), latitude(b));
    }
  }
  return out;
}

}  // namespace kin5::reach
