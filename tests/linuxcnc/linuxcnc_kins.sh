#!/bin/sh
# kin5kins against LinuxCNC's own modules for the same machines, every entry point called
# directly under halrun by kins_probe, on random geometries (the module pins) and random joint
# vectors and world positions, for both kinematics types and both type orders (sparm).
#
#   linuxcnc_kins.sh agree    PROBE MODULE RTLIB_DIR   forward and inverse agree within 1e-9
#   linuxcnc_kins.sh negative PROBE MODULE RTLIB_DIR   one geometry pin of kin5kins off by
#                                                      0.001 mm: the comparison must find it
# (RTLIB_DIR: LinuxCNC's module directory, where its modules are loaded from.)
# Exit 77 (skipped) when kin5kins was not built (no linuxcnc-uspace-dev) or halrun is absent.
# KIN5_LINUXCNC_SEED fixes the seed; otherwise it is drawn and printed.
set -u
mode=$1 probe=$2 module=$3 rtlib=$4
if [ -z "$probe" ] || [ -z "$module" ]; then
  echo "skipped: kin5kins was not built (install linuxcnc-uspace-dev, scripts/setup-debian.sh, and configure again)"
  exit 77
fi
if ! command -v halrun >/dev/null 2>&1; then
  echo "skipped: halrun is not installed (linuxcnc-uspace)"
  exit 77
fi
seed=${KIN5_LINUXCNC_SEED:-$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')}
echo "seed $seed (KIN5_LINUXCNC_SEED=$seed repeats this run)"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# rtapi_app refuses to run as root unless told a user to fall back to, and its socket must be
# somewhere that user may write.
chmod 777 "$work"
if [ "$(id -u)" -eq 0 ]; then
  export RTAPI_UID="${RTAPI_UID:-65534}"
fi
export RTAPI_FIFO_PATH="$work/rtapi_fifo"
unset DISPLAY

geometries=8
poses=200
# machine, LinuxCNC's module, its geometry pins, the pin the negative control moves
# (xyzab_tdr_kins has no sparm: its type 0 is always identity)
cases="xyzac-trt xyzac-trt-kins x-rot-point,y-rot-point,z-rot-point,y-offset,z-offset,tool-offset y-offset
xyzbc-trt xyzbc-trt-kins x-rot-point,y-rot-point,z-rot-point,x-offset,z-offset,tool-offset x-offset
xyzab-tdr xyzab_tdr_kins x-rot-point,y-rot-point,z-rot-point,x-offset,z-offset,tool-offset-z z-offset
bridgemill 5axiskins pivot-length pivot-length"

status=0
hal="$work/probe.hal"
: >"$hal"
n=0
echo "$cases" | while read -r machine kins pins moved; do
  sparms="default identityfirst"
  [ "$kins" = xyzab_tdr_kins ] && sparms=default
  for sparm in $sparms; do
    n=$((n + 1))
    extra=""
    [ "$sparm" = identityfirst ] && extra="sparm=identityfirst"
    offset=""
    [ "$mode" = negative ] && offset="--offset $moved=0.001"
    echo "loadusr -w $probe run $rtlib/$kins.so $kins $pins $seed $geometries $poses $work/$n.lcnc $extra" >>"$hal"
    echo "loadusr -w $probe run $module kin5kins $pins $seed $geometries $poses $work/$n.kin5 machine=$machine $extra $offset" >>"$hal"
    echo "$n $machine $sparm" >>"$work/cases"
  done
done
if ! halrun -f "$hal" >"$work/halrun.log" 2>&1; then
  echo "halrun failed:"
  cat "$work/halrun.log"
  exit 1
fi
while read -r n machine sparm; do
  result=$("$probe" compare "$work/$n.lcnc" "$work/$n.kin5" 1e-9)
  agreed=$?
  if [ "$mode" = agree ]; then
    echo "$machine (sparm $sparm) against LinuxCNC's module: $result"
    [ $agreed -eq 0 ] || status=1
  else
    if [ $agreed -eq 0 ]; then
      echo "$machine (sparm $sparm): a geometry pin off by 0.001 mm was not detected: $result"
      status=1
    else
      echo "$machine (sparm $sparm): the moved pin is detected: $(echo "$result" | head -1)"
    fi
  fi
done <"$work/cases"
exit $status
