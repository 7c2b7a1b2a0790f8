// Benchmark of the controller-grade calls (docs/embedding.md) as a servo loop makes them: one
// call at a time, each timed alone. For every catalog machine, 10^6 random joint vectors
// (rotary angles uniform within travel, slides uniform within travel; a tool of 100 mm), and
// their poses by forward kinematics, drawn from a fixed seed:
//   forward/<id>          forward(m, q, in): joints -> tool tip and axis (G6)
//   inverse_pose/<id>     inverse_into(m, pose, in, {}, out): tool pose -> every joint solution
//   linear_axes_for/<id>  linear_axes_for(m, rotary, tip, in): the slides for a tip at given
//                         rotary angles (G7), the inverse a tool-centre control makes each cycle
// Each call is timed with std::chrono::steady_clock into a list of 10^6 durations; the counters
// are the median, the 99.9th percentile and the worst of them (ns), and clock_ns, the median
// of an empty timed region, which every figure includes. The worst case also holds whatever
// the system did meanwhile (an interrupt, a preemption): on an idle, isolated core it is the
// call's; on a shared machine it is an upper bound. Nothing here asserts a time.
//
//   cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DKIN5_BUILD_BENCH=ON
//   cmake --build build-bench --target kin5_bench_controller
//   build-bench/bench/kin5_bench_controller --benchmark_counters_tabular=true
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <kin5/kinematics.hpp>
#include <kin5/machines/catalog.hpp>

namespace {

using namespace kin5;
using steady = std::chrono::steady_clock;

constexpr std::size_t pose_count = 1'000'000;
constexpr run_inputs tool{.tool_length_mm = 100.0};

struct sample {
  axis_values joints;
  tool_pose pose;
};

// A value uniform within [lo, hi], or within ±500 mm where the travel is unbounded.
double uniform_within(std::mt19937_64& rng, double lo, double hi) {
  if (!(hi - lo < 1e6)) lo = -500.0, hi = 500.0;
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

std::vector<sample> samples_for(const machine_model& m) {
  std::vector<sample> out(pose_count);
  std::mt19937_64 rng(30u + m.geometry.id.size());
  for (auto& s : out) {
    for (std::size_t i = 0; i < 3; ++i) {
      const double v = uniform_within(rng, m.linear(i).travel.lower_mm, m.linear(i).travel.upper_mm);
      (i == 0 ? s.joints.xyz_mm.x : i == 1 ? s.joints.xyz_mm.y : s.joints.xyz_mm.z) = v;
    }
    for (std::size_t i = 0; i < m.rotary_count; ++i) {
      const auto& tr = m.rotary(i).travel;
      const double lo = tr.continuous ? -pi : to_radians(tr.lower).value;
      const double hi = tr.continuous ? pi : to_radians(tr.upper).value;
      s.joints.rotary[i] = radians{std::uniform_real_distribution<double>(lo, hi)(rng)};
    }
    s.pose = forward(m, s.joints, tool);
  }
  return out;
}

// The median of an empty timed region: what the clock adds to every figure.
double clock_cost_ns() {
  std::vector<std::int64_t> ns(100'000);
  for (auto& d : ns) {
    const auto t0 = steady::now();
    const auto t1 = steady::now();
    d = std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count();
  }
  std::nth_element(ns.begin(), ns.begin() + ns.size() / 2, ns.end());
  return static_cast<double>(ns[ns.size() / 2]);
}

// Times `call(s)` once per sample; reports the total as the iteration's time and the median,
// 99.9th percentile and worst per call as counters.
template <class Call>
void time_each(benchmark::State& state, const std::vector<sample>& samples, Call call) {
  std::vector<std::int64_t> ns(samples.size());
  for (auto _ : state) {
    std::int64_t total = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const auto t0 = steady::now();
      call(samples[i]);
      const auto t1 = steady::now();
      ns[i] = std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count();
      total += ns[i];
    }
    state.SetIterationTime(static_cast<double>(total) * 1e-9);
  }
  const auto at = [&](double q) {
    const auto k = ns.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(ns.size() - 1));
    std::nth_element(ns.begin(), k, ns.end());
    return static_cast<double>(*k);
  };
  state.counters["calls"] = static_cast<double>(ns.size());
  state.counters["median_ns"] = at(0.5);
  state.counters["p999_ns"] = at(0.999);
  state.counters["worst_ns"] = static_cast<double>(*std::max_element(ns.begin(), ns.end()));
  state.counters["clock_ns"] = clock_cost_ns();
}

void bench_forward(benchmark::State& state, const machine_model* m) {
  const auto samples = samples_for(*m);
  time_each(state, samples, [&](const sample& s) {
    tool_pose p = forward(*m, s.joints, tool);
    benchmark::DoNotOptimize(p);
  });
}

void bench_inverse_pose(benchmark::State& state, const machine_model* m) {
  const auto samples = samples_for(*m);
  pose_values out{};
  time_each(state, samples, [&](const sample& s) {
    inverse_into(*m, s.pose, tool, {}, out);
    benchmark::DoNotOptimize(out);
  });
}

void bench_linear_axes_for(benchmark::State& state, const machine_model* m) {
  const auto samples = samples_for(*m);
  time_each(state, samples, [&](const sample& s) {
    vec3 xyz = linear_axes_for(*m, s.joints.rotary, s.pose.tip_mm, tool);
    benchmark::DoNotOptimize(xyz);
  });
}

const bool registered = [] {
  for (const machine_model* m : machines::catalog_models) {
    const std::string id(m->geometry.id);
    for (auto [name, f] : {std::pair{"forward/", &bench_forward}, std::pair{"inverse_pose/", &bench_inverse_pose},
                           std::pair{"linear_axes_for/", &bench_linear_axes_for}})
      benchmark::RegisterBenchmark((name + id).c_str(), f, m)
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kNanosecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
