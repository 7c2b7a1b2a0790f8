#!/usr/bin/env bash
# Installs kin5's build and test dependencies from Debian's packages. Safe to run again.
set -euo pipefail
packages=(
  build-essential cmake pkg-config ninja-build
  libeigen3-dev            # kin5::eigen (oracle, interop)
  catch2                   # Catch2 v2 test runner
  librapidcheck-dev        # property tests
  coinor-libipopt-dev      # kin5::reach
  libbenchmark-dev         # bench/
  libcli11-dev             # command-line tool
  libtomlplusplus-dev      # machine files (TOML)
  clang libclang-rt-14-dev # libFuzzer targets
  chromium fonts-dejavu-core libpng-dev  # the sphere maps checked in a browser (tests/match)
  python3                  # JSON reports parsed back (tests/cli_program/report.sh)
  linuxcnc-uspace          # rs274, the oracle of LinuxCNC expressions (tests/property/interp); halrun
  linuxcnc-uspace-dev      # kin5kins, the LinuxCNC kinematics module (tools/kin5kins, tests/linuxcnc)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
