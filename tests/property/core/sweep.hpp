/// @file sweep.hpp
/// A brute-force reach oracle: the smallest angle between a requested tool axis and every tool
/// axis the Eigen chain (`kin5::eigen::chain_tool_axis`) produces within the axes' travel, by a
/// dense grid over the rotary axes followed by Levenberg–Marquardt refinement of the best cells.
/// Shares no code with kin5's solver or inverse.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <kin5/eigen.hpp>

namespace kin5::test {

/// Angle between two nonzero vectors, radians (atan2 form, accurate near 0 and π).
inline double angle_between_eigen(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// The commanded range swept for a rotary axis: its travel, or one turn if continuous.
inline std::array<double, 2> swept_range(const rotary_axis& a) {
  if (a.travel.continuous) return {-pi, pi};
  return {a.travel.lower.value * pi / 180.0, a.travel.upper.value * pi / 180.0};
}

/// min over commanded angles within travel of ∠(chain_tool_axis(angles), u), radians.
template <machine M>
double sweep_min_angle(const Eigen::Vector3d& u, int grid = 91) {
  constexpr std::size_t n = rotary_count<M>;
  std::array<std::array<double, 2>, n> range{};
  for (std::size_t i = 0; i < n; ++i) range[i] = swept_range(M::rotary[i]);
  auto f = [&](const std::array<double, n>& x) {
    rotary_angles<M> a{};
    for (std::size_t i = 0; i < n; ++i) a[i] = radians{x[i]};
    return angle_between_eigen(eigen::chain_tool_axis<M>(a), u);
  };
  auto clamp_into = [&](std::array<double, n> x) {
    for (std::size_t i = 0; i < n; ++i)
      if (!M::rotary[i].travel.continuous) x[i] = std::clamp(x[i], range[i][0], range[i][1]);
    return x;
  };

  // Grid: uniform, plus rows at 10^-k inside each limit of a bounded axis, so that poles and
  // reach edges on a limit (dmu-80p B = 0 and 180°) get starting cells on both sides.
  std::array<std::vector<double>, n> values{};
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < grid; ++k) values[i].push_back(range[i][0] + (range[i][1] - range[i][0]) * k / (grid - 1.0));
    if (M::rotary[i].travel.continuous) continue;
    for (int e = 1; e <= 10; ++e) {
      values[i].push_back(range[i][0] + std::pow(10.0, -e));
      values[i].push_back(range[i][1] - std::pow(10.0, -e));
    }
  }
  std::vector<std::pair<double, std::array<double, n>>> cells;
  std::array<std::size_t, n> idx{};
  while (true) {
    std::array<double, n> x{};
    for (std::size_t i = 0; i < n; ++i) x[i] = values[i][idx[i]];
    cells.emplace_back(f(x), x);
    std::size_t i = 0;
    while (i < n && ++idx[i] == values[i].size()) idx[i++] = 0;
    if (i == n) break;
  }
  const std::size_t keep = std::min<std::size_t>(8, cells.size());
  std::partial_sort(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(keep), cells.end(),
                    [](const auto& a, const auto& b) { return a.first < b.first; });

  // Levenberg–Marquardt on the chord r(x) = chain(x) − u (|r| = 2 sin(angle/2), so the same
  // minimiser), central-difference Jacobian, bounded axes held by an active set.
  // A cell on a travel limit also starts once nudged inside: at a pole on a limit (dmu-80p B = 0)
  // the limit axis's gradient may point outwards while the other axis has none.
  std::vector<std::array<double, n>> starts;
  for (std::size_t c = 0; c < keep; ++c) {
    starts.push_back(cells[c].second);
    std::array<double, n> nudged = cells[c].second;
    bool moved = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (M::rotary[i].travel.continuous) continue;
      if (nudged[i] <= range[i][0]) { nudged[i] = range[i][0] + 1e-3; moved = true; }
      if (nudged[i] >= range[i][1]) { nudged[i] = range[i][1] - 1e-3; moved = true; }
    }
    if (moved) starts.push_back(nudged);
  }
  double best = cells.front().first;
  for (std::array<double, n> x : starts) {
    auto residual = [&](const std::array<double, n>& y) {
      rotary_angles<M> a{};
      for (std::size_t i = 0; i < n; ++i) a[i] = radians{y[i]};
      return Eigen::Vector3d(eigen::chain_tool_axis<M>(a) - u);
    };
    Eigen::Vector3d r = residual(x);
    double lambda = 1e-3;
    for (int iter = 0; iter < 200; ++iter) {
      Eigen::Matrix<double, 3, static_cast<int>(n)> J;
      for (std::size_t i = 0; i < n; ++i) {
        std::array<double, n> xp = x, xm = x;
        xp[i] += 1e-6;
        xm[i] -= 1e-6;
        J.col(static_cast<int>(i)) = (residual(xp) - residual(xm)) / 2e-6;
      }
      const Eigen::Matrix<double, static_cast<int>(n), 1> g = J.transpose() * r;
      // Active set: a bounded axis on a limit whose descent direction points outside is held.
      std::array<bool, n> free{};
      for (std::size_t i = 0; i < n; ++i) {
        free[i] = true;
        if (M::rotary[i].travel.continuous) continue;
        if ((x[i] <= range[i][0] && g(static_cast<int>(i)) > 0) || (x[i] >= range[i][1] && g(static_cast<int>(i)) < 0))
          free[i] = false;
      }
      Eigen::Matrix<double, static_cast<int>(n), static_cast<int>(n)> H = J.transpose() * J;
      bool accepted = false;
      for (int tries = 0; tries < 30 && !accepted; ++tries) {
        Eigen::Matrix<double, static_cast<int>(n), static_cast<int>(n)> A = H;
        Eigen::Matrix<double, static_cast<int>(n), 1> b = -g;
        for (std::size_t i = 0; i < n; ++i) {
          const int k = static_cast<int>(i);
          A(k, k) += lambda * (H(k, k) + 1e-12);
          if (!free[i]) {
            A.row(k).setZero();
            A.col(k).setZero();
            A(k, k) = 1.0;
            b(k) = 0.0;
          }
        }
        const Eigen::Matrix<double, static_cast<int>(n), 1> step = A.ldlt().solve(b);
        std::array<double, n> y = x;
        for (std::size_t i = 0; i < n; ++i) y[i] += step(static_cast<int>(i));
        y = clamp_into(y);
        const Eigen::Vector3d ry = residual(y);
        if (ry.squaredNorm() < r.squaredNorm()) {
          x = y;
          r = ry;
          lambda = std::max(lambda * 0.3, 1e-12);
          accepted = true;
        } else {
          lambda *= 10.0;
        }
      }
      if (!accepted) break;
    }
    best = std::min(best, f(x));
  }
  return best;
}

/// The same minimum when p's travel covers a full turn: turning about p keeps the latitude
/// ∠(p, ·) and reaches every azimuth, so the answer is min over q's travel of
/// |∠(p, chain(0, q)) − ∠(p, u)|, found on a dense grid of q, with bisection where the latitude
/// crosses ∠(p, u) and golden-section refinement otherwise. Accurate to ~1e-14 rad, also at
/// reach edges and poles on a limit, where the two-axis refinement above stalls.
template <machine M>
double sweep_min_angle_turning_p(const Eigen::Vector3d& u, int grid = 2001) {
  const Eigen::Vector3d p = eigen::to_eigen(M::rotary[0].direction);
  const double theta_u = angle_between_eigen(p, u);
  auto g = [&](double x) {
    rotary_angles<M> a{};
    if constexpr (rotary_count<M> == 2) a[1] = radians{x};
    return angle_between_eigen(p, eigen::chain_tool_axis<M>(a)) - theta_u;
  };
  if constexpr (rotary_count<M> == 1) {
    return std::abs(g(0.0));
  } else {
    const auto range = swept_range(M::rotary[1]);
    double best = std::abs(g(range[0]));
    double g_prev = g(range[0]);
    for (int k = 1; k < grid; ++k) {
      const double x = range[0] + (range[1] - range[0]) * k / (grid - 1.0);
      const double gx = g(x);
      if ((gx <= 0) != (g_prev <= 0)) return 0.0;  // the latitude crosses θ_u: reachable
      best = std::min(best, std::abs(gx));
      g_prev = gx;
    }
    // No crossing: |g| has one sign; refine its minimum around the best grid samples.
    const double h = (range[1] - range[0]) / (grid - 1.0);
    for (int k = 0; k < grid; ++k) {
      const double x = range[0] + h * k;
      const double here = std::abs(g(x));
      if (here > best + 4.0 * h) continue;  // |g| is 1-Lipschitz in x: only near-best cells
      double lo = std::max(range[0], x - h), hi = std::min(range[1], x + h);
      constexpr double phi = 0.6180339887498949;
      for (int it = 0; it < 80; ++it) {
        const double m1 = hi - phi * (hi - lo), m2 = lo + phi * (hi - lo);
        if (std::abs(g(m1)) < std::abs(g(m2))) hi = m2; else lo = m1;
      }
      best = std::min({best, std::abs(g(lo)), std::abs(g(hi))});
    }
    return best;
  }
}

}  // namespace kin5::test
