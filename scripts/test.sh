#!/usr/bin/env bash
# Sets up a fresh Debian machine, builds everything (the benchmark programs too, not run) and
# runs every test: each libFuzzer target for a bounded number of inputs under AddressSanitizer
# and UndefinedBehaviorSanitizer, the CLI tests against a sanitizer build of the tool, then the
# unit, property, golden, CLI and consumer tests through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage prints its wall time and the CPU time of its processes so far, for the CI budget
# (docs/performance.md, "CI time").
stage_start=$SECONDS
stage_times=$(mktemp)
stage_done() {
  times >"$stage_times"  # in this shell, not a subshell: its children's CPU so far
  echo "== stage $1: $((SECONDS - stage_start)) s (CPU of all stages so far, user and system: $(tail -n 1 "$stage_times"))"
  stage_start=$SECONDS
}
./scripts/setup-debian.sh
stage_done setup
jobs=$(nproc 2>/dev/null || echo 2)

# The benchmark programs are built with the rest (not run): a benchmark that no longer compiles,
# such as a catalog machine without a closed form in bench/closed_forms.hpp, fails CI.
# The test programs are compiled at -O1 (KIN5_TEST_OPTIMIZATION): 40 % less compile time than
# -O3 for a test translation unit, for a little more run time; the tool, the library and the
# benchmark programs keep Release's -O3 (docs/performance.md, "CI time").
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DKIN5_BUILD_BENCH=ON -DKIN5_TEST_OPTIMIZATION=-O1
cmake --build build -j"$jobs"
stage_done build

# Fuzz smoke run: KIN5_FUZZ_RUNS inputs per reader (default 150000, 0 to skip) and
# KIN5_PIPELINE_FUZZ_RUNS through the whole pipeline (read, translate, write; default 1000, at
# most 45 seconds: its inputs reach 1.25 MiB), from a fixed seed so that a CI run is
# reproducible; fuzz longer, with other seeds, by hand (docs/reliability.md):
#   build-fuzz/tests/fuzz/siemens_fuzz -max_total_time=600 corpus/
runs=${KIN5_FUZZ_RUNS:-150000}
pipeline_runs=${KIN5_PIPELINE_FUZZ_RUNS:-1000}
if [ "$runs" -gt 0 ]; then
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DKIN5_BUILD_FUZZ=ON -DKIN5_BUILD_TESTS=OFF -DKIN5_BUILD_TOOLS=OFF -DKIN5_BUILD_REACH=OFF -DKIN5_BUILD_LINUXCNC=OFF -DKIN5_INSTALL=OFF
  cmake --build build-fuzz -j"$jobs"
  stage_done fuzz-build
  # One fuzzer per core at a time, the slowest (Siemens: its inputs loop up to the executed-line
  # bound) first; each prints its log's end when it finishes, the whole log when it fails.
  fuzz_one() {
    local fuzzer=$1 n=$KIN5_FUZZ_N max_len=0 seconds=0  # 0: libFuzzer chooses the length; no time limit
    # the pipeline: inputs long enough to cross the block store's first 1 MiB chunk
    [ "$(basename "$fuzzer")" = pipeline_fuzz ] && n=$KIN5_PIPELINE_FUZZ_N max_len=1310720 seconds=45
    [ "$n" -gt 0 ] || return 0
    local corpus
    corpus=$(mktemp -d)
    if ! "$fuzzer" -seed=1 -runs="$n" -max_len="$max_len" -max_total_time="$seconds" -print_final_stats=1 \
      -artifact_prefix="$corpus/" "$corpus" >"$corpus/log" 2>&1; then
      tail -n 60 "$corpus/log"
      echo "$(basename "$fuzzer") failed; the input is in $corpus" >&2
      return 1
    fi
    echo "fuzzed $(basename "$fuzzer"): $n inputs, seed 1: $(grep -m1 "^Done" "$corpus/log")"
    rm -rf "$corpus"
  }
  export -f fuzz_one
  export KIN5_FUZZ_N=$runs KIN5_PIPELINE_FUZZ_N=$pipeline_runs
  fuzzers=(build-fuzz/tests/fuzz/siemens_fuzz)
  for fuzzer in build-fuzz/tests/fuzz/*_fuzz; do [ "$fuzzer" = "${fuzzers[0]}" ] || fuzzers+=("$fuzzer"); done
  if ! printf '%s\n' "${fuzzers[@]}" | xargs -P "$jobs" -I{} bash -c 'fuzz_one "$1"' _ {}; then
    echo "a fuzz target failed (above)" >&2
    exit 1
  fi
  stage_done fuzz
fi

# The command-line tests once more against an AddressSanitizer + UndefinedBehaviorSanitizer
# build of the tool alone (-O1; KIN5_SANITIZE=0 skips it): memory errors in the tool's own code
# and on its file, signal and limit paths, which the fuzzers (library only) do not reach.
cli_tests='^(cli|cli_program|cli_program reliability|cli_program silent|bad): '
ran_cli_tests=()
if [ "${KIN5_SANITIZE:-1}" != 0 ]; then
  sanitize="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DCMAKE_CXX_FLAGS="$sanitize" -DCMAKE_EXE_LINKER_FLAGS="$sanitize" -DKIN5_BUILD_REACH=OFF -DKIN5_BUILD_LINUXCNC=OFF -DKIN5_INSTALL=OFF
  cmake --build build-asan -j"$jobs" --target kin5_cli
  stage_done sanitizer-build
  ctest --test-dir build-asan --output-on-failure -j"$jobs" -R "$cli_tests"
  ran_cli_tests=(-E "$cli_tests")
  stage_done sanitizer-tests
fi

# CTest last, so that its summary closes the output; the command-line tests that passed against
# the sanitizer build are not run twice.
ctest --test-dir build --output-on-failure -j"$jobs" "${ran_cli_tests[@]}"
stage_done tests
