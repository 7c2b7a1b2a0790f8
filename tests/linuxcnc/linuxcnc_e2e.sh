#!/bin/sh
# kin5kins end to end: a headless LinuxCNC (e2e/run_program.py as its display) homes and runs a
# 5-axis tool-centre program (e2e/tcp_program.ngc) on the xyzac-trt machine, with halsampler
# recording the commanded joint positions every servo cycle (1 ms). It runs three times: with
# LinuxCNC's xyzac-trt-kins, with kin5kins, and with kin5kins given a y-offset 0.001 mm off (the
# negative control). The joints of the first two must agree to the printed decimals (1e-6), and
# the third must differ.
#
#   linuxcnc_e2e.sh MODULE RTLIB_DIR
#
# LinuxCNC loads modules only from its module directory (RTLIB_DIR): kin5kins runs in a mount
# namespace in which a copy of that directory, with kin5kins.so added, is mounted over it, so
# nothing is installed. That needs root (unshare -m); the test is skipped, saying why, without
# it, without kin5kins (no linuxcnc-uspace-dev), or without LinuxCNC.
set -u
module=$1 rtlib=$2
here=$(cd "$(dirname "$0")" && pwd)
skip() {
  echo "skipped: $1"
  exit 77
}
[ -n "$module" ] || skip "kin5kins was not built (install linuxcnc-uspace-dev, scripts/setup-debian.sh, and configure again)"
command -v linuxcnc >/dev/null 2>&1 || skip "linuxcnc is not installed (linuxcnc-uspace)"
command -v halsampler >/dev/null 2>&1 || skip "halsampler is not installed (linuxcnc-uspace)"
/usr/bin/python3 -c "import linuxcnc" 2>/dev/null || skip "LinuxCNC's Python module is not importable by /usr/bin/python3"
unshare -m true 2>/dev/null || skip "unshare -m is not permitted (the run needs root to mount kin5kins into LinuxCNC's module directory)"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 777 "$work"
[ "$(id -u)" -eq 0 ] && export RTAPI_UID="${RTAPI_UID:-65534}"
export RTAPI_FIFO_PATH="$work/rtapi_fifo"
export HOME="$work"  # the linuxcnc script leaves its logs in HOME
unset DISPLAY
mkdir "$work/modules"
cp "$rtlib"/*.so "$work/modules/" && cp "$module" "$work/modules/kin5kins.so" || exit 1

# run NAME KINEMATICS PREFIX Y_OFFSET: one LinuxCNC run; the moving part of its samples in NAME.txt
run() {
  name=$1 kins=$2 prefix=$3 y_offset=$4
  dir="$work/$name"
  mkdir "$dir"
  chmod 777 "$dir"
  {
    printf '[EMC]\nVERSION = 1.1\nMACHINE = kin5kins-e2e\n'
    printf '[DISPLAY]\nDISPLAY = %s\n' "$here/e2e/run_program.py"
    printf '[TASK]\nTASK = milltask\nCYCLE_TIME = 0.010\n'
    printf '[RS274NGC]\nPARAMETER_FILE = %s\n' "$dir/sim.var"
    printf '[EMCMOT]\nEMCMOT = motmod\nCOMM_TIMEOUT = 1.0\nSERVO_PERIOD = 1000000\n'
    printf '[EMCIO]\nEMCIO = io\nCYCLE_TIME = 0.100\nTOOL_TABLE = %s\n' "$dir/tool.tbl"
    printf '[HAL]\nHALFILE = %s\n' "$dir/machine.hal"
    printf '[TRAJ]\nCOORDINATES = X Y Z A C\nLINEAR_UNITS = mm\nANGULAR_UNITS = degree\n'
    printf 'DEFAULT_LINEAR_VELOCITY = 10\nMAX_LINEAR_VELOCITY = 100\n'
    printf '[KINS]\nKINEMATICS = %s\nJOINTS = 5\n' "$kins"
    for axis in X Y Z A C; do
      printf '[AXIS_%s]\nMIN_LIMIT = -10000\nMAX_LIMIT = 10000\nMAX_VELOCITY = 100\nMAX_ACCELERATION = 1000\n' $axis
    done
    for joint in 0 1 2 3 4; do
      type=LINEAR
      [ $joint -ge 3 ] && type=ANGULAR
      printf '[JOINT_%s]\nTYPE = %s\nHOME = 0\nMIN_LIMIT = -10000\nMAX_LIMIT = 10000\n' $joint $type
      printf 'MAX_VELOCITY = 200\nMAX_ACCELERATION = 2000\nFERROR = 1\nMIN_FERROR = 1\n'
      printf 'HOME_SEARCH_VEL = 0\nHOME_SEQUENCE = 0\n'
    done
  } >"$dir/machine.ini"
  {
    echo "loadrt [KINS]KINEMATICS"
    echo "loadrt [EMCMOT]EMCMOT servo_period_nsec=[EMCMOT]SERVO_PERIOD num_joints=[KINS]JOINTS"
    echo "loadrt sampler depth=4000 cfg=fffff"
    echo "addf motion-command-handler servo-thread"
    echo "addf motion-controller servo-thread"
    echo "addf sampler.0 servo-thread"
    for joint in 0 1 2 3 4; do
      echo "net j$joint joint.$joint.motor-pos-cmd => joint.$joint.motor-pos-fb sampler.0.pin.$joint"
    done
    echo "net estop-loop iocontrol.0.user-enable-out => iocontrol.0.emc-enable-in"
    echo "net tool-prep-loop iocontrol.0.tool-prepare => iocontrol.0.tool-prepared"
    echo "net tool-change-loop iocontrol.0.tool-change => iocontrol.0.tool-changed"
    echo "setp $prefix.x-rot-point 3"
    echo "setp $prefix.y-rot-point -4"
    echo "setp $prefix.z-rot-point 5"
    echo "setp $prefix.y-offset $y_offset"
    echo "setp $prefix.z-offset 10"
    echo "setp $prefix.tool-offset 35"
    echo "loadusr $here/e2e/sampler.sh $dir/samples.txt"
  } >"$dir/machine.hal"
  echo "T1 P1 Z0 D6 ;" >"$dir/tool.tbl"
  KIN5_E2E_PROGRAM="$here/e2e/tcp_program.ngc" KIN5_E2E_STATUS="$dir/status.txt" \
    unshare -m sh -c 'mount --bind "$1" "$2" && exec linuxcnc "$3"' sh "$work/modules" "$rtlib" "$dir/machine.ini" \
    >"$dir/linuxcnc.log" 2>&1
  if [ "$(cat "$dir/status.txt" 2>/dev/null)" != ok ] || [ ! -s "$dir/samples.txt" ]; then
    echo "the LinuxCNC run with $kins failed: $(cat "$dir/status.txt" 2>/dev/null)"
    cat "$dir/linuxcnc.log" "$HOME/linuxcnc_print.txt" 2>/dev/null | tail -40
    exit 1
  fi
  # The motion: from the sample before the first that differs from the rest position to the
  # sample after the last that differs from the end position. When each run starts moving
  # depends on the display's polling; what follows, cycle by cycle, does not.
  awk '{ line[NR] = $0 }
       END { first = 1; while (first < NR && line[first] == line[1]) first++
             last = NR; while (last > first && line[last] == line[NR]) last--
             for (i = first - 1; i <= last + 1; i++) print line[i] }' "$dir/samples.txt" >"$work/$name.txt"
}

# compare A B: exit 0 when both have the same samples to the printed decimals (1e-6, and the
# rounding of the last one); prints the count and the largest difference.
compare() {
  awk -v a="$1" -v b="$2" 'BEGIN {
    n = 0; worst = 0
    while ((getline x < a) > 0) {
      if ((getline y < b) <= 0) { print "  " a " has more samples than " b; exit 1 }
      nx = split(x, u, " "); split(y, v, " ")
      for (i = 1; i <= nx; ++i) { d = u[i] - v[i]; if (d < 0) d = -d; if (d > worst) worst = d }
      ++n
    }
    if ((getline y < b) > 0) { print "  " b " has more samples than " a; exit 1 }
    printf "  %d samples of 5 joints, largest difference %.6f\n", n, worst
    exit (n > 100 && worst <= 1.000001e-6) ? 0 : 1
  }'
}

run lcnc xyzac-trt-kins xyzac-trt-kins 20
run kin5 "kin5kins machine=xyzac-trt" kin5kins 20
run wrong "kin5kins machine=xyzac-trt" kin5kins 20.001
status=0
echo "xyzac-trt-kins against kin5kins, joints every servo cycle:"
compare "$work/lcnc.txt" "$work/kin5.txt" || status=1
echo "xyzac-trt-kins against kin5kins with y-offset 0.001 mm off (must differ):"
if compare "$work/lcnc.txt" "$work/wrong.txt"; then
  echo "  the wrong pin was not detected"
  status=1
fi
exit $status
