#!/bin/sh
# Runs one realistic program of tests/programs as README.md there says a user would, and checks
# what kin5 does with it today: exit 0 with the lines that carry its constructs, or exit 2 with
# its first error at the line and column given and nothing written. A program refused today for
# a construct not yet translated is a row here too, so that no change lets it through unnoticed.
#
#   check.sh KIN5_EXE PROGRAMS_DIR NAME        (NAME: dialect/file under PROGRAMS_DIR)
#
# Built on the CLI tests' harness (../cli_program/harness.sh: exe, name, a fresh directory,
# report, show, run).
set -u
# shellcheck source=../cli_program/harness.sh
. "$(dirname "$0")/../cli_program/harness.sh"
program=$examples/$name

# expect CODE WHERE ARGS...: `run` kin5 ARGS on the program, writing written.out; with CODE 2,
# WHERE is LINE:COL and the first error's words after it, and nothing may be written.
expect() {
  code=$1 where=$2
  shift 2
  rm -f written.out
  run "$code" "$@" -o written.out "$program"
  if [ "$code" = 2 ]; then
    first=$(grep -m 1 ': error: ' err)
    case $first in
      "$program:$where"*) ;;
      *) report "first error is not $name:$where: $first" ;;
    esac
    [ -e written.out ] && report "an output was written"
  fi
  return 0
}
# has PATTERN...: each (grep -E) is a line of the output.
has() {
  for p in "$@"; do grep -Eq -- "$p" written.out 2>/dev/null || report "no line matching '$p'"; done
}

# z_home_file MACHINE Z: home.toml, the bundled MACHINE's file with its Z home at Z (the catalog
# states no home: docs/machine-files.md).
z_home_file() {
  sed "/^\[linear.Z\]/a home_mm = $2" "$examples/../../machines/$1.toml" >home.toml
}

case $name in
  heidenhain/bracket_5axis.h)
    expect 2 "12:1: error: preset 1: a work offset of heidenhain" translate --from dmu-80p --to sajo-12000p
    # Mapped: refused where compensation is switched on, as the paper's setup turns the XY plane.
    expect 2 "23:1: error: cutter radius compensation: the setup between the machines turns the XY plane" \
      translate --from dmu-80p --to sajo-12000p --work-offset-map 1=G54 ;;
  heidenhain/housing_inch.h)
    expect 2 "4:1: error: preset 4" translate --from dmu-80p --to sajo-12000p
    expect 0 - translate --from dmu-80p --to sajo-12000p --work-offset-map 4=G57
    has '^N0 G700$' '^N3 G57' 'TRAORI' ;;
  heidenhain/drill_cycle_refused.h)
    expect 2 "7:3: error: CYCL DEF 200 is not supported" translate --from dmu-80p --to sajo-12000p ;;
  heidenhain/named_tools.h)
    expect 0 - translate --from dmu-80p --to sajo-12000p
    has '^N5 F1200 S8000 T="MILL_D10" M6 ' '^N15 S14000 T="BALL-R3" M6 ' '^N14 TRAFOOF$' '^D1$' '^N17 TRAORI$'
    expect 2 '6:1: error: a tool called by name ("MILL_D10") in heidenhain has no number in iso; --tool-map MILL_D10=N' \
      translate --from dmu-80p --to sajo-12000p --to-dialect iso
    expect 0 - translate --from dmu-80p --to sajo-12000p --to-dialect iso --tool-map MILL_D10=1 --tool-map BALL-R3=2
    has '^N5 F1200. S8000 T1 M6 ' '^N7 G43.4 H1$' '^N15 S14000 T2 M6 ' '^N17 G43.4 H2$' ;;
  heidenhain/swarf_flow.h)
    # Run as the TNC runs it: three passes of the section repeat, each 1.5 deeper, the corner
    # subprogram in each, eight points of the FN 12 loop; no label or call is written.
    expect 0 - translate --from dmu-80p --to ac-trunnion
    has '^N16 G1 X-40 Y-40 Z-1\.5 .* F400$' '^N16 G1 X-40 Y-40 Z-3 .* F400$' '^N16 G1 X-40 Y-40 Z-4\.5 .* F400$' \
      '^N40 G1 X-40 Y40 Z-4\.5 ' '^N27 G1 X10 Y-17\.321 Z-6 ' '^N27 G1 X-17\.321 Y10 Z-6 '
    [ "$(grep -c '^N27 G1' written.out)" = 8 ] || report "not eight points"
    grep -Eq 'LBL [0-9"]' written.out && report "a label or call written" ;;
  heidenhain/tilted_plane_refused.h)
    expect 2 "5:3: error: PLANE SPATIAL changes the working frame" translate --from dmu-80p --to sajo-12000p ;;
  siemens/impeller_traori.mpf)
    # The named tools go into Heidenhain as TOOL CALL "…": compensation under the paper's setup stops it.
    expect 2 "35:1: error: cutter radius compensation: the setup between the machines turns the XY plane" \
      translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1
    # Between the same machine and dialect the constants are substituted.
    expect 0 - translate --from sajo-12000p --to sajo-12000p
    has '^N110 G0 X-25.5 Y14.2 Z120 A-20 B35$' '^N130 G1 .* Z2.0245 .* F400$' '^N140 G1 .* F1850.5$' \
      '^N180 G0 .* Z120 ' '^N280 G41 G1 X-50 Y-40 ' '^N60 T="BALL_D8_L90" M6$' ;;
  siemens/cover_inch_g700.mpf)
    expect 2 "5:5: error: G55: a work offset of siemens" translate --from sajo-12000p --to dmu-80p
    expect 0 - translate --from sajo-12000p --to dmu-80p --work-offset-map G55=2
    has '^0 BEGIN PGM COVER_INCH INCH$' 'Q339=\+2' ;;
  siemens/basic_system_refused.mpf)
    expect 2 "11:13: error: F under G70 is in the control's basic unit system" translate --from sajo-12000p --to dmu-80p ;;
  siemens/mcall_refused.mpf)
    expect 2 "10:5: error: MCALL CYCLE81: a modal cycle call is not supported" translate --from sajo-12000p --to dmu-80p ;;
  iso/manifold_g43_4.nc)
    expect 2 "7:5: error: G54: a work offset of iso" translate --from ac-trunnion --from-dialect iso --to dmu-80p
    # Its closing G91 G28 Z0. is the retract to Z's home, which the catalog's dmu-80p does not state.
    expect 2 "41:1: error: a move to the reference point (G28) of Z needs the target machine's home of Z: give home_mm in [linear.Z]" \
      translate --from ac-trunnion --from-dialect iso --to dmu-80p --work-offset-map G54=1
    z_home_file dmu-80p 0
    expect 0 - translate --from ac-trunnion --from-dialect iso --to-file home.toml --work-offset-map G54=1
    has '^42 L Z\+0 FMAX M91$' ;;
  iso/blade_inch_g93.nc)
    expect 2 "5:5: error: G54.1 P3: a work offset of iso" translate --from ac-trunnion --from-dialect iso --to dmu-80p
    expect 0 - translate --from ac-trunnion --from-dialect iso --to sajo-12000p --to-dialect iso
    has 'G20$' '^N20 G54\.1 P3$' '^N90 G93$'
    # Into Haas: G154 P3 (the same additional offset), TCPC G234 H9, still inch.
    expect 0 - translate --from ac-trunnion --from-dialect iso --to ac-trunnion --to-dialect haas
    has '^N10 G90 G17 G40 G49 G94 G20$' '^N20 G154 P3$' '^N60 G234 H9$' '^N90 G93$' ;;
  haas/umc_inch_g234.nc)
    # Read as Haas by its G234 (not as ISO, where G234 is an unknown word).
    expect 2 "9:5: error: unknown word 'G234'" translate --from bc-trunnion --from-dialect iso --to dmu-80p
    expect 2 "5:5: error: G55: a work offset of haas" translate --from bc-trunnion --to dmu-80p
    expect 2 "18:1: error: a move to the reference point (G28) of Z needs the target machine's home of Z: give home_mm in [linear.Z]" \
      translate --from bc-trunnion --to dmu-80p --work-offset-map G55=2
    z_home_file dmu-80p 0
    expect 0 - translate --from bc-trunnion --to-file home.toml --work-offset-map G55=2
    has '^17 L Z\+0 FMAX M91$' ;;
  haas/hub_g154.nc)
    expect 2 "7:5: error: G154 P5: a work offset of haas" translate --from bc-trunnion --to dmu-80p
    expect 0 - translate --from bc-trunnion --to dmu-80p --work-offset-map G154P5=5
    has 'Q339=\+5' '^6 TOOL CALL 3 Z$' ' FMAX M128$' '^13 L X\+22.5 .* F315.2$' 'CYCL DEF 9.1 DWELL 0.5$'
    # Into ISO the same selection is G54.1 P5, TCPC G43.4 H3, the dwell G4 X seconds.
    expect 0 - translate --from bc-trunnion --to bc-trunnion --to-dialect iso
    has '^N30 G54.1 P5$' '^N70 G0 G43.4 H3 X20\. ' '^N100 G93 .* F120\.$' '^N140 G4 X0.5$' '^N160 G49$' ;;
  iso/slots_macro.nc)
    expect 2 "6:5: error: G54: a work offset of iso" translate --from ac-trunnion --from-dialect iso --to dmu-80p
    # executed: three slots 1.25 mm apart in depth (M98 in a WHILE loop), two holes by G65 with X Y Z
    expect 0 - translate --from ac-trunnion --from-dialect iso --to dmu-80p --work-offset-map G54=1
    has '^15 L X-30 Y-10 Z-1.25 B\+0 C\+0 F300$' '^22 L X\+30 Y-10 Z-2.5 B\+0 C\+0 F900$' \
      '^27 L X-30 Y-10 Z-3.75 ' '^30 ;#100 = 3$' '^33 L X\+20 Y\+15 Z-2.5 B\+0 C\+0 F200$' '^36 L X-20 Y\+15 Z-2.5 ' \
      '^38 L X-20 Y\+15 Z\+50 B\+0 C\+0 FMAX$'
    # and back into ISO: the executed program, its assignments as the numbers they assigned
    expect 0 - translate --from ac-trunnion --from-dialect iso --to ac-trunnion --to-dialect iso
    has '^#102 = -2\.5$' '^N20 G1 X-30\. Y-10\. Z-3\.75 A0\. C0\. F300\.$' '^N20 G1 X-20\. Y15\. Z-2\.5 A0\. C0\. F200\.$' ;;
  iso/integers_refused.nc)
    expect 2 "8:4: error: X10 without a decimal point" \
      translate --from ac-trunnion --from-dialect iso --to dmu-80p --work-offset-map G54=1 ;;
  linuxcnc/boss_chamfer.ngc)
    expect 0 - translate --from xyzac-trt --to dmu-80p --work-offset-map G54=1
    has 'Q339=\+1' ' TOOL CALL 8 Z$' ' M128' ;;
  linuxcnc/trunnion_m428.ngc)
    expect 2 "14:1: error: cutter radius compensation between linuxcnc and siemens" \
      translate --from xyzac-trt --to sajo-12000p --work-offset-map G54=G54 ;;
  linuxcnc/plate_tangent_comp.ngc)
    # Entered and left straight on along the bottom edge: compensation goes into the TNC and ISO.
    expect 0 - translate --from xyzac-trt --to dmu-80p --work-offset-map G54=1
    has '^16 L X\+30 Y-25 Z-4 B\+0 C\+0 RL F1500$' '^19 C X-40 Y-15 DR-$' '^30 L X\+10 Y-25 Z-4 B\+0 C\+0 R0$'
    expect 0 - translate --from xyzac-trt --to xyzac-trt --to-dialect iso
    has '^G41 D6 G1 X30\. Y-25\. Z-4\. A0\. C0\. F1500\.$' '^G2 X-40\. Y-15\. I0\. J10\.$' '^G40 G1 X10\. Y-25\. '
    ;;
  linuxcnc/g12_1_tcp.ngc)
    expect 0 - translate --from xyzac-trt --to dmu-80p --work-offset-map G55=2
    has ' TOOL CALL 3 Z$' ' M128' ;;
  linuxcnc/constants.ngc)
    expect 2 "7:1: error: G54: a work offset of linuxcnc" translate --from xyzac-trt --to dmu-80p
    expect 0 - translate --from xyzac-trt --to dmu-80p --work-offset-map G54=1
    has '^12 L X\+0 Y\+0 Z\+45 B\+0 C-105.004 FMAX$' '^13 L .* Z\+2 .* F300$' '^14 L X\+12 Y\+6 Z\+2 .* F1250$' \
      '^15 L X\+12 Y\+6 Z\+45 ' ;;
  linuxcnc/oword_while.ngc)
    expect 2 "4:1: error: G54: a work offset of linuxcnc" translate --from xyzac-trt --to dmu-80p
    # executed: three passes, each 1 mm deeper; the loop's counter is a comment
    expect 0 - translate --from xyzac-trt --to dmu-80p --work-offset-map G54=1
    has '^11 L X\+0 Y\+0 Z-1 B\+0 C\+0 F300$' '^17 L X\+20 Y\+0 Z-2 B\+0 C\+0 F900$' '^21 L X\+0 Y\+0 Z-3 ' \
      '^25 ;#1 = 3$' '^26 M129$' ;;
  linuxcnc/zero_feed_refused.ngc)
    expect 2 "12:1: error: feed move in inverse time (G93) without its own F" translate --from xyzac-trt --to dmu-80p --work-offset-map G54=1 ;;
  apt/blade_multax.cls)
    expect 2 "22:1: error: CUTCOM/LEFT: cutter radius compensation is not supported in CL data" post --machine dmu-80p ;;
  apt/hub_inch_inverse.cls)
    expect 2 "6:1: error: M7: an M function of apt" post --machine dmu-80p
    expect 0 - post --machine sajo-12000p
    has '^G700$' '^G93$' '^G1 X1\.0375 .* F95\.5$' ;;
  apt/drill_cycle_refused.cls)
    expect 2 "9:1: error: CYCLE/DRILL: fixed cycles are not supported" post --machine dmu-80p ;;
  apt/loadtool_creo.cls)
    expect 0 - post --machine dmu-80p
    has ' TOOL CALL 12 Z$' ;;
  *)
    report "no row for $name in check.sh: say what kin5 must do with it"
    ;;
esac
exit "$fail"
