#!/usr/bin/env bash
# Sets up a fresh Debian machine, builds the kin5 tool and translates the bundled Table 1
# program from the SAJO 12000P (Siemens) to the DMU 80P (Heidenhain), printing the result.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup-debian.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target kin5_cli -j"$(nproc 2>/dev/null || echo 2)"
./build/tools/kin5/kin5 translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1 examples/table1-sajo.mpf
