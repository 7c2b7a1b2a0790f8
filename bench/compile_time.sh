#!/bin/sh
# Compile time of an 11-line consumer of kin5::tool_axis<dmu_80p> (tests/consumer/main.cpp with
# its #include replaced), once per header given, at -O2: the median of RUNS compilations of the
# CPU time (user + system) and the elapsed time of `c++ -std=c++20 -O2 -c`.
#
#   bench/compile_time.sh [HEADER...]      (default: kin5/kinematics.hpp kin5/kin5.hpp)
#
# Environment: CXX (default c++), RUNS (default 3), KIN5_INCLUDE (default: include/ of this
# tree; point it at another tree's include/ to compare with an older layout).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
cxx=${CXX:-c++}
runs=${RUNS:-3}
include=${KIN5_INCLUDE:-$root/include}
[ "$#" -gt 0 ] || set -- kin5/kinematics.hpp kin5/kin5.hpp

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-32s %10s %10s\n' "header" "cpu s" "elapsed s"
for header in "$@"; do
  # "a+b" stands for two headers included one after the other.
  includes=$(echo "$header" | tr '+' '\n' | sed 's|.*|#include <&>|')
  awk -v inc="$includes" '/^#include <kin5\/kin5.hpp>$/ { print inc; next } { print }' \
    "$root/tests/consumer/main.cpp" >"$work/main.cpp"
  : >"$work/times"
  i=0
  while [ "$i" -lt "$runs" ]; do
    i=$((i + 1))
    /usr/bin/time -f '%U %S %e' -o "$work/time" "$cxx" -std=c++20 -O2 -I"$include" -c "$work/main.cpp" \
      -o "$work/main.o"
    awk '{ printf "%.2f %.2f\n", $1 + $2, $3 }' "$work/time" >>"$work/times"
  done
  cpu=$(cut -d' ' -f1 "$work/times" | sort -n | sed -n "$(((runs + 1) / 2))p")
  elapsed=$(cut -d' ' -f2 "$work/times" | sort -n | sed -n "$(((runs + 1) / 2))p")
  printf '%-32s %10s %10s\n' "$header" "$cpu" "$elapsed"
done
