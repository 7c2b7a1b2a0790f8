#!/bin/sh
# The translation benchmark in process (translate_bench.cpp, Google Benchmark): builds it in
# Release and prints the median CPU time of one translation of the spiral program and of the
# parse+format floor on the same text, and their ratio. No file I/O on either side, so the ratio
# is larger than run.sh's file-to-file one, for which the goals (<= 1.5, never > 3) are set.
#
#   bench/translate/gbench.sh [--blocks=N] [extra Google Benchmark flags]
#
# Environment: KIN5_BENCH_BUILD_DIR (default: build-bench in the source tree),
#              KIN5_BENCH_REPETITIONS (default 5, at least 2), KIN5_BENCH_MIN_TIME (seconds, default 0.5).
# If the build or the benchmark fails, it says which and why (the build log's last lines) and
# exits 1.
set -eu

root=$(cd "$(dirname "$0")/../.." && pwd)
build=${KIN5_BENCH_BUILD_DIR:-$root/build-bench}
reps=${KIN5_BENCH_REPETITIONS:-5}
min_time=${KIN5_BENCH_MIN_TIME:-0.5}

. "$root/bench/quietly.sh"
# The table shows medians, which Google Benchmark reports only over two or more repetitions.
[ "$reps" -ge 2 ] 2>/dev/null || { echo "$0: KIN5_BENCH_REPETITIONS must be 2 or more (the table shows medians), not '$reps'" >&2; exit 1; }

generator=""
if command -v ninja >/dev/null 2>&1; then generator="-G Ninja"; fi
# shellcheck disable=SC2086
quietly "$build/configure.log" "configuring $build (cmake)" \
  cmake -S "$root" -B "$build" $generator -DCMAKE_BUILD_TYPE=Release -DKIN5_BUILD_BENCH=ON \
  -DKIN5_BUILD_TESTS=OFF -DKIN5_BUILD_TOOLS=OFF -DKIN5_BUILD_REACH=OFF -DKIN5_INSTALL=OFF
quietly "$build/build.log" "building kin5_bench_translate" cmake --build "$build" --target kin5_bench_translate -j2

csv="$build/bench/translate/translate.csv"
"$build/bench/translate/kin5_bench_translate" --benchmark_format=csv --benchmark_repetitions="$reps" \
  --benchmark_report_aggregates_only=true --benchmark_min_time="$min_time" \
  --benchmark_enable_random_interleaving=true "$@" >"$csv" || {
  echo "$0: kin5_bench_translate failed (exit status $?); its messages are above" >&2; exit 1; }

# CSV columns: name,iterations,real_time,cpu_time,time_unit,...; names like "parse_baseline_median".
awk -F, '
  $1 ~ /_median"?$/ { name = $1; gsub(/"/, "", name); sub(/_median$/, "", name); t[name] = $4; unit = $5 }
  END {
    tr = "translate/sajo-12000p/dmu-80p"
    printf "%-32s %12s\n", "benchmark", "cpu (median)"
    printf "%-32s %12.2f %s\n", tr, t[tr], unit
    printf "%-32s %12.2f %s\n", "parse_baseline", t["parse_baseline"], unit
    printf "ratio translate/baseline: %.2f (in memory; the goals are set for run.sh, file to file)\n", t[tr] / t["parse_baseline"]
  }' "$csv"
