// Benchmark of inverse<M>, per call, for each catalog machine, against
//   closed_form/<id>   the machine's specialised closed form (closed_forms.hpp), and
//   eigen_newton/<id>  an Eigen transform chain solved by Levenberg–Marquardt (eigen_newton.hpp).
//
// Every benchmark cycles through the same 1024 reachable unit tool axes per machine, drawn once
// from a fixed seed: rotary angles uniform within travel (0.5° inside bounded limits), u from
// forward kinematics, poles (|p × u| < 0.05) left out. Each call's angles are summed into a
// checksum so that no solution can be optimised away. Before timing, the baselines are checked
// against inverse<M> on every input; a mismatch aborts with exit code 1.
//
// bench/run.sh builds Release, runs this and prints the ratios.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <kin5/kin5.hpp>

#include "closed_forms.hpp"
#include "eigen_newton.hpp"

namespace {

using namespace kin5;
constexpr std::size_t sample_count = 1024;  // a power of two, for the cheap index wrap

template <machine M>
const std::vector<vec3>& samples() {
  static const std::vector<vec3> v = [] {
    std::vector<vec3> out;
    std::mt19937_64 rng(20101u + static_cast<unsigned>(M::id.size()));
    const vec3 p = M::rotary[0].direction;
    while (out.size() < sample_count) {
      rotary_angles<M> a{};
      for (std::size_t i = 0; i < rotary_count<M>; ++i) {
        const auto& tr = M::rotary[i].travel;
        const double lo = tr.continuous ? -pi : to_radians(tr.lower).value + 0.5 * bench::deg;
        const double hi = tr.continuous ? pi : to_radians(tr.upper).value - 0.5 * bench::deg;
        a[i] = {std::uniform_real_distribution<double>(lo, hi)(rng)};
      }
      const vec3 u = tool_axis<M>(a);
      if (norm(cross(p, u)) < 0.05) continue;
      out.push_back(u);
    }
    return out;
  }();
  return v;
}

// Same commanded angles (radians) to 1e-9.
template <std::size_t N>
bool same_angles(const std::array<radians, N>& a, const std::array<double, N>& b) {
  for (std::size_t i = 0; i < N; ++i)
    if (std::fabs(a[i].value - b[i]) > 1e-9) return false;
  return true;
}

// Checks closed_form<M> (same within-travel solutions as inverse<M>, each reproducing u) and
// counts the Newton solves that do not converge. Returns false on a closed-form mismatch.
template <machine M>
bool validate() {
  std::size_t newton_failures = 0;
  double newton_iterations = 0;
  for (const vec3& u : samples<M>()) {
    const auto inv = inverse<M>(u);
    const auto cf = bench::closed_form<M>::solve(u);
    std::size_t cf_within = 0, inv_within = 0;
    for (const auto& s : inv) inv_within += s.within_travel;
    for (std::size_t k = 0; k < cf.count; ++k) {
      rotary_angles<M> a{};
      for (std::size_t i = 0; i < rotary_count<M>; ++i) a[i] = {cf.angles[k][i]};
      if (norm(tool_axis<M>(a) - u) > 1e-9) {
        std::fprintf(stderr, "%s: closed form solution %zu does not reproduce u\n", M::id.data(), k);
        return false;
      }
      if (!cf.within[k]) continue;
      ++cf_within;
      bool found = false;
      for (const auto& s : inv) found = found || (s.within_travel && same_angles(s.angles, cf.angles[k]));
      if (!found) {
        std::fprintf(stderr, "%s: closed form solution %zu not among inverse's\n", M::id.data(), k);
        return false;
      }
    }
    if (cf_within != inv_within) {
      std::fprintf(stderr, "%s: closed form has %zu solutions within travel, inverse %zu\n", M::id.data(),
                   cf_within, inv_within);
      return false;
    }
    const auto nr = bench::eigen_newton<M>::solve(u);
    newton_failures += !(nr.residual < 1e-9);
    newton_iterations += nr.iterations;
  }
  std::fprintf(stderr, "%-22s closed form agrees with inverse on %zu inputs; Newton: %zu not converged, %.1f iterations on average\n",
               M::id.data(), samples<M>().size(), newton_failures, newton_iterations / sample_count);
  return true;
}

template <machine M>
void bm_inverse(benchmark::State& state) {
  const auto& v = samples<M>();
  std::size_t i = 0;
  double checksum = 0;
  for (auto _ : state) {
    const auto r = inverse<M>(v[i]);
    for (const auto& s : r)
      if (s.within_travel)
        for (const auto& a : s.angles) checksum += a.value;
    benchmark::DoNotOptimize(checksum);
    i = (i + 1) & (sample_count - 1);
  }
}

template <machine M>
void bm_closed_form(benchmark::State& state) {
  const auto& v = samples<M>();
  std::size_t i = 0;
  double checksum = 0;
  for (auto _ : state) {
    const auto r = bench::closed_form<M>::solve(v[i]);
    for (std::size_t k = 0; k < r.count; ++k)
      if (r.within[k])
        for (double a : r.angles[k]) checksum += a;
    benchmark::DoNotOptimize(checksum);
    i = (i + 1) & (sample_count - 1);
  }
}

template <machine M>
void bm_eigen_newton(benchmark::State& state) {
  const auto& v = samples<M>();
  std::size_t i = 0;
  double checksum = 0;
  for (auto _ : state) {
    const auto r = bench::eigen_newton<M>::solve(v[i]);
    for (double a : r.commanded) checksum += a;
    benchmark::DoNotOptimize(checksum);
    i = (i + 1) & (sample_count - 1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool ok = true;
  // A machine without a closed form fails the build in closed_forms.hpp, naming it; the guards
  // keep that the only error.
  machines::for_each_machine([&]<class M>() {
    if constexpr (bench::has_closed_form<M>) ok = validate<M>() && ok;
  });
  if (!ok) return 1;
  machines::for_each_machine([&]<class M>() {
    if constexpr (bench::has_closed_form<M>) {
      const std::string id(M::id);
      benchmark::RegisterBenchmark(("inverse/" + id).c_str(), bm_inverse<M>);
      benchmark::RegisterBenchmark(("closed_form/" + id).c_str(), bm_closed_form<M>);
      benchmark::RegisterBenchmark(("eigen_newton/" + id).c_str(), bm_eigen_newton<M>);
    }
  });
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
