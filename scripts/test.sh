#!/usr/bin/env bash
# Sets up a fresh Debian machine, builds everything and runs every test: each libFuzzer target
# for a bounded number of inputs under AddressSanitizer and UndefinedBehaviorSanitizer, then the
# unit, property, golden, CLI and consumer tests through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup-debian.sh
jobs=$(nproc 2>/dev/null || echo 2)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"

# Fuzz smoke run: KIN5_FUZZ_RUNS inputs per reader (default 150000, 0 to skip), from a fixed
# seed so that a CI run is reproducible; fuzz longer, with other seeds, by hand:
#   build-fuzz/tests/fuzz/siemens_fuzz -max_total_time=600 corpus/
runs=${KIN5_FUZZ_RUNS:-150000}
if [ "$runs" -gt 0 ]; then
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DKIN5_BUILD_FUZZ=ON -DKIN5_BUILD_TESTS=OFF -DKIN5_BUILD_TOOLS=OFF -DKIN5_BUILD_REACH=OFF -DKIN5_INSTALL=OFF
  cmake --build build-fuzz -j"$jobs"
  shopt -s nullglob
  for fuzzer in build-fuzz/tests/fuzz/*_fuzz; do
    echo "fuzzing $(basename "$fuzzer"): $runs inputs, seed 1"
    corpus=$(mktemp -d)
    if ! "$fuzzer" -seed=1 -runs="$runs" -print_final_stats=1 -artifact_prefix="$corpus/" "$corpus" >"$corpus/log" 2>&1; then
      tail -n 60 "$corpus/log"
      echo "$(basename "$fuzzer") failed; the input is in $corpus" >&2
      exit 1
    fi
    tail -n 2 "$corpus/log"
    rm -rf "$corpus"
  done
fi

# CTest last, so that its summary closes the output.
ctest --test-dir build --output-on-failure -j"$jobs"
