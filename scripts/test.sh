#!/usr/bin/env bash
# Sets up a fresh Debian machine, builds everything and runs every test:
# unit/property/golden/CLI/consumer tests through CTest, then each libFuzzer target for a
# bounded time under AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup-debian.sh
jobs=$(nproc 2>/dev/null || echo 2)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

# Fuzz smoke run: KIN5_FUZZ_SECONDS per reader (default 15).
seconds=${KIN5_FUZZ_SECONDS:-15}
if [ "$seconds" -gt 0 ]; then
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DKIN5_BUILD_FUZZ=ON -DKIN5_BUILD_TESTS=OFF -DKIN5_BUILD_TOOLS=OFF -DKIN5_BUILD_REACH=OFF -DKIN5_INSTALL=OFF
  cmake --build build-fuzz -j"$jobs"
  shopt -s nullglob
  for fuzzer in build-fuzz/tests/fuzz/*_fuzz; do
    echo "fuzzing $(basename "$fuzzer") for ${seconds}s"
    corpus=$(mktemp -d)
    "$fuzzer" -max_total_time="$seconds" -print_final_stats=1 "$corpus" 2>&1 | tail -n 3
    rm -rf "$corpus"
  done
fi
