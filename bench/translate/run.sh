#!/bin/sh
# Times `kin5 translate` end to end (file to file) against a parse+format-only baseline on one
# core, and measures peak memory per block.
#
#   bench/translate/run.sh [BLOCKS]          (default 1000000)
#
# Steps: a Release build of the kin5 tool and of this directory's two helpers; a BLOCKS-block
# SAJO 12000P program (kin5_bench_gen_program); then, pinned to CPU 0 with taskset, RUNS runs
# each of
#   kin5 translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1 -o OUT IN
#   kin5_bench_parse_baseline IN OUT
# under /usr/bin/time -v. Prints the median elapsed and user+system seconds of each, their
# ratio (goal <= 1.5, never > 3), and the largest maximum resident set size divided by BLOCKS
# (goal <= 200 bytes/block).
#
# Environment: KIN5_BENCH_BUILD_DIR (default: build-bench-translate in the source tree),
#              RUNS (default 3), CPU (default 0),
#              INSTRUCTIONS=1: also count the instructions both programs execute on the first
#              20,000 lines, under valgrind's callgrind: a figure that, unlike time, does not
#              move with the load of a shared machine.
# If a build or a run fails, it says which and why (the build log's last lines, the program's
# messages) and exits 1.
set -eu

root=$(cd "$(dirname "$0")/../.." && pwd)
build=${KIN5_BENCH_BUILD_DIR:-$root/build-bench-translate}
blocks=${1:-1000000}
runs=${RUNS:-3}
cpu=${CPU:-0}

. "$root/bench/quietly.sh"

generator=""
if command -v ninja >/dev/null 2>&1; then generator="-G Ninja"; fi
# shellcheck disable=SC2086
quietly "$build/kin5/configure.log" "configuring $build/kin5 (cmake)" \
  cmake -S "$root" -B "$build/kin5" $generator -DCMAKE_BUILD_TYPE=Release -DKIN5_BUILD_TOOLS=ON \
  -DKIN5_BUILD_TESTS=OFF -DKIN5_BUILD_REACH=OFF -DKIN5_BUILD_BENCH=OFF -DKIN5_INSTALL=OFF
quietly "$build/kin5/build.log" "building the kin5 tool" cmake --build "$build/kin5" --target kin5_cli -j2
# shellcheck disable=SC2086
quietly "$build/helpers/configure.log" "configuring $build/helpers (cmake)" \
  cmake -S "$root/bench/translate" -B "$build/helpers" $generator -DCMAKE_BUILD_TYPE=Release
quietly "$build/helpers/build.log" "building the helpers" cmake --build "$build/helpers" -j2

kin5=$(find "$build/kin5" -name kin5 -type f -perm -u+x | head -n 1)
gen="$build/helpers/kin5_bench_gen_program"
baseline="$build/helpers/kin5_bench_parse_baseline"
data="$build/data"
mkdir -p "$data"
input="$data/spiral-$blocks.mpf"
if [ ! -s "$input" ]; then
  quietly "$data/gen.log" "writing the $blocks-block program" "$gen" "$blocks" "$input.part"
  mv "$input.part" "$input"
fi

# measure NAME COMMAND...: RUNS runs; appends "NAME elapsed_s cpu_s maxrss_kb" per run.
measure() {
  name=$1; shift
  i=0
  while [ "$i" -lt "$runs" ]; do
    i=$((i + 1))
    taskset -c "$cpu" /usr/bin/time -v "$@" 2>"$data/time.txt" >/dev/null || {
      cat "$data/time.txt" >&2; echo "$0: $name failed; its messages and times are above" >&2; exit 1; }
    awk -v n="$name" -F': ' '
      /Elapsed \(wall clock\)/ { k = split($2, t, ":"); e = 0; for (j = 1; j <= k; ++j) e = e * 60 + t[j] }
      /User time/ { u = $2 } /System time/ { s = $2 } /Maximum resident/ { m = $2 }
      END { printf "%s %.3f %.3f %d\n", n, e, u + s, m }' "$data/time.txt" >>"$data/results.txt"
  done
}

: >"$data/results.txt"
measure translate "$kin5" translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1 -o "$data/out.h" "$input"
measure baseline "$baseline" "$input" "$data/baseline.out"

echo "input: $input ($blocks motion blocks, $(wc -c <"$input" | tr -d ' ') bytes); $runs runs each on CPU $cpu"
awk -v blocks="$blocks" '
  function median(a, n,   i, j, t) {
    for (i = 2; i <= n; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  { n[$1]++; e[$1, n[$1]] = $2; c[$1, n[$1]] = $3; if ($4 > m[$1]) m[$1] = $4 }
  END {
    printf "%-10s %12s %12s %14s %12s\n", "program", "elapsed s", "user+sys s", "max RSS MiB", "bytes/block"
    for (p = 1; p <= 2; ++p) {
      name = p == 1 ? "translate" : "baseline"
      for (i = 1; i <= n[name]; ++i) { ea[i] = e[name, i]; ca[i] = c[name, i] }
      me[name] = median(ea, n[name]); mc[name] = median(ca, n[name])
      printf "%-10s %12.3f %12.3f %14.1f %12.0f\n", name, me[name], mc[name], m[name] / 1024, m[name] * 1024 / blocks
    }
    printf "ratio translate/baseline: %.2f elapsed, %.2f user+sys (goal <= 1.5, never > 3)\n",
           me["translate"] / me["baseline"], mc["translate"] / mc["baseline"]
  }' "$data/results.txt"

if [ "${INSTRUCTIONS:-0}" = 1 ] && command -v valgrind >/dev/null 2>&1; then
  head -n 20000 "$input" >"$data/prefix.mpf"
  ti=$(valgrind --tool=callgrind --callgrind-out-file="$data/callgrind.translate" \
         "$kin5" translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1 -o "$data/prefix.h" "$data/prefix.mpf" 2>&1 >/dev/null |
       awk '/Collected/ { print $NF }')
  bi=$(valgrind --tool=callgrind --callgrind-out-file="$data/callgrind.baseline" \
         "$baseline" "$data/prefix.mpf" "$data/prefix.out" 2>&1 >/dev/null | awk '/Collected/ { print $NF }')
  awk -v t="$ti" -v b="$bi" 'BEGIN {
    printf "instructions on the first 20000 lines: translate %d, baseline %d, ratio %.2f\n", t, b, t / b }'
fi
