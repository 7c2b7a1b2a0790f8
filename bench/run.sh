#!/bin/sh
# Builds the kin5 benchmarks in Release and prints, per catalog machine, the median CPU time per
# call of inverse<M>, of its closed form and of the Eigen Levenberg–Marquardt baseline, and the
# ratios inverse / closed form (goal <= 1.2) and Newton / inverse (goal >= 20).
#
#   bench/run.sh [extra Google Benchmark flags]
#
# Environment: KIN5_BENCH_BUILD_DIR (default: build-bench in the source tree),
#              KIN5_BENCH_REPETITIONS (default 5, at least 2), KIN5_BENCH_MIN_TIME (seconds, default 0.2).
# If the build or the benchmark fails, it says which and why (the build log's last lines) and
# exits 1.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build=${KIN5_BENCH_BUILD_DIR:-$root/build-bench}
reps=${KIN5_BENCH_REPETITIONS:-5}
min_time=${KIN5_BENCH_MIN_TIME:-0.2}

. "$root/bench/quietly.sh"
# The table shows medians, which Google Benchmark reports only over two or more repetitions.
[ "$reps" -ge 2 ] 2>/dev/null || { echo "$0: KIN5_BENCH_REPETITIONS must be 2 or more (the table shows medians), not '$reps'" >&2; exit 1; }

generator=""
if command -v ninja >/dev/null 2>&1; then generator="-G Ninja"; fi
# shellcheck disable=SC2086
quietly "$build/configure.log" "configuring $build (cmake)" \
  cmake -S "$root" -B "$build" $generator -DCMAKE_BUILD_TYPE=Release -DKIN5_BUILD_BENCH=ON \
  -DKIN5_BUILD_TESTS=OFF -DKIN5_BUILD_TOOLS=OFF -DKIN5_BUILD_REACH=OFF -DKIN5_INSTALL=OFF
quietly "$build/build.log" "building kin5_bench_inverse" cmake --build "$build" --target kin5_bench_inverse -j2

# Its start-up check prints one line per machine on stderr, and why it stops if a baseline
# disagrees with inverse<M>.
csv="$build/bench/inverse.csv"
"$build/bench/kin5_bench_inverse" --benchmark_format=csv --benchmark_repetitions="$reps" \
  --benchmark_report_aggregates_only=true --benchmark_min_time="$min_time" \
  --benchmark_enable_random_interleaving=true "$@" >"$csv" || {
  echo "$0: kin5_bench_inverse failed (exit status $?); its messages are above" >&2; exit 1; }

# Machines in catalog order, from the registered names "inverse/<id>".
order=$("$build/bench/kin5_bench_inverse" --benchmark_list_tests=true 2>/dev/null | sed -n 's|^inverse/||p' | tr '\n' ' ')

# CSV columns: name,iterations,real_time,cpu_time,time_unit,...; names like "inverse/dmu-80p_median".
awk -F, -v ids="$order" '
  BEGIN { n = split(ids, order, " ") }
  $1 ~ /_median"?$/ {
    name = $1; gsub(/"/, "", name); sub(/_median$/, "", name)
    split(name, part, "/")
    t[part[1], part[2]] = $4
  }
  END {
    printf "%-22s %12s %12s %14s %14s %14s\n", "machine", "inverse ns", "closed ns", "newton ns", "inv/closed", "newton/inv"
    for (k = 1; k <= n; ++k) {
      id = order[k]
      printf "%-22s %12.1f %12.1f %14.1f %14.2f %14.1f\n", id, t["inverse", id], t["closed_form", id],
             t["eigen_newton", id], t["inverse", id] / t["closed_form", id], t["eigen_newton", id] / t["inverse", id]
    }
  }' "$csv"
