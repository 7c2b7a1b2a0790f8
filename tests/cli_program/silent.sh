#!/bin/sh
# The table of silent wrong outputs: cases where kin5 once exited 0 with a program that meant
# something else on the target than the source meant on its machine (issue 11, "Silent wrong
# output found"). One test per row: a tiny program written here, the kin5 command, and either
# the exit code with the error at FILE:LINE:COL, or the lines the output must (and must not) hold.
#
#   silent.sh KIN5_EXE EXAMPLES_DIR ROW
set -u

. "$(cd "$(dirname "$0")" && pwd)/harness.sh"
example="$examples/table1-sajo.mpf"

# error_at TEXT: err has a line starting with TEXT (FILE:LINE:COL: error: ...), as fixed text.
error_at() { awk -v t="$1" 'index($0, t) == 1 { f = 1 } END { exit !f }' err || { report "no line '$1...'"; show err; }; }
# has_line FILE REGEX: FILE has a whole line matching REGEX (extended).
has_line() { grep -Eq -- "^($2)\$" "$1" || { report "$1: no line '$2'"; show "$1"; }; }
# no_line FILE REGEX: FILE has no whole line matching REGEX.
no_line() { ! grep -Eq -- "^($2)\$" "$1" || { report "$1: a line '$2'"; show "$1"; }; }
# line_is FILE N REGEX: line N of FILE ('$': the last) matches REGEX (extended), whole.
line_is() { sed -n "$2p" "$1" | grep -Eq -- "^($3)\$" || { report "$1: line $2 is not '$3'"; show "$1"; }; }
# count_is FILE REGEX N: FILE has N whole lines matching REGEX.
count_is() { c=$(grep -Ec -- "^($2)\$" "$1"); [ "$c" = "$3" ] || { report "$1: $c lines '$2', not $3"; show "$1"; }; }
# nothing FILE: a refused run wrote nothing.
nothing() { [ -e "$1" ] && report "$1 written although refused"; [ -s out ] && report "stdout not empty"; return 0; }

# tnc NAME MOVE [BLOCK...]: NAME.h, a Heidenhain program for the DMU 80P (C table, B head):
# BEGIN PGM, TOOL CALL 1, M128, L MOVE on line 4, the BLOCKs (numbered on), M129, END PGM.
tnc() {
  n=$1 move=$2; shift 2
  { echo "0 BEGIN PGM $n MM"; echo '1 TOOL CALL 1 Z S4000'; echo '2 M128'; echo "3 L $move"
    k=4; for l in "$@"; do echo "$k $l"; k=$((k + 1)); done
    echo "$k M129"; echo "$((k + 1)) END PGM $n MM"; } >"$n.h"
}

case "$name" in
  # An axis word the source machine does not have is an error at the word.
  axis-a-on-dmu)
    tnc A 'X+0 Y+0 Z+50 B+10 C+0 A+30 F500'
    run 2 translate --from dmu-80p --to sajo-12000p -o a.mpf A.h
    error_at 'A.h:4:27: error: A+30: dmu-80p has no A axis'
    nothing a.mpf
    ;;
  axis-c-on-sajo)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B10 C77 F500' 'N30 TRAFOOF' 'N40 M30' >c.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o c.h c.mpf
    error_at 'c.mpf:2:27: error: C77: sajo-12000p has no C axis'
    nothing c.h
    ;;
  wrong-from)
    # The SAJO example given as a DMU 80P program: its A words name the wrong machine.
    run 2 translate --from dmu-80p --to sajo-12000p -o w.mpf "$example"
    error_at "$example:14:34: error: A-77.954: dmu-80p has no A axis"
    nothing w.mpf
    ;;
  # A source rotary value outside the source machine's own travel is an error at the word.
  outside-travel)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-150 B10 F500' 'N30 TRAFOOF' 'N40 M30' >r.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o r.h r.mpf
    error_at 'r.mpf:2:18: error: A-150: outside the travel of A on sajo-12000p, [-120°, 30°], by 30°'
    nothing r.h
    ;;
  # Tool changes: a TOOL CALL is a change (T and M6 in one block), never a bare T.
  tool-call-to-siemens)
    printf '%s\n' '0 BEGIN PGM TC MM' '1 TOOL CALL 9 Z S13000' '2 M128' '3 L X+0 Y+0 Z+50 B+10 C+0 F500' \
      '4 M129' '5 END PGM TC MM' >tc.h
    run 0 translate --from dmu-80p --to dmu-80p --to-dialect siemens -o tc.mpf tc.h
    has_line tc.mpf 'N1 S13000 T9 M6( ;.*)?'
    has_line tc.mpf 'D1'
    ;;
  tool-call-to-iso)
    printf '%s\n' '0 BEGIN PGM TC MM' '1 TOOL CALL 9 Z S13000' '2 M128' '3 L X+0 Y+0 Z+50 B+10 C+0 F500' \
      '4 M129' '5 END PGM TC MM' >tc.h
    run 0 translate --from dmu-80p --to dmu-80p --to-dialect iso -o tc.nc tc.h
    has_line tc.nc 'N1 S13000 T9 M6( \(.*\))?'
    ;;
  # A spindle speed with a fraction has no ISO spelling (S is a whole number on a Fanuc
  # control): refused at the word; Siemens, whose S is a real, keeps it.
  iso-spindle-whole)
    printf '%s\n' '0 BEGIN PGM SP MM' '1 TOOL CALL 1 Z S8000.5' '2 M128' '3 L X+0 Y+0 Z+50 B+10 C+0 F500' \
      '4 M129' '5 END PGM SP MM' >sp.h
    run 2 translate --from dmu-80p --to dmu-80p --to-dialect iso -o sp.nc sp.h
    error_at 'sp.h:2:17: error: S8000.5: iso reads a spindle speed as a whole number of revolutions per minute'
    nothing sp.nc
    printf '%s\n' 'PARTNO SP' 'UNITS/MM' 'LOAD/TOOL,1' 'SPINDL/RPM,8000.5,CLW' 'FEDRAT/MMPM,500' \
      'GOTO/0,0,50,0,0,1' 'FINI' >sp.apt
    run 2 post --machine dmu-80p --dialect iso -o sp.nc sp.apt
    error_at 'sp.apt:4:1: error: S8000.5: iso reads a spindle speed as a whole number'
    nothing sp.nc
    run 0 translate --from dmu-80p --to dmu-80p --to-dialect siemens -o sp.mpf sp.h
    has_line sp.mpf 'N1 S8000.5 T1 M6( ;.*)?'
    ;;
  # An inch program keeps its own decimals of an inch in every dialect, 5 included (an IS-C
  # control reads 0.00001 in), and never fewer than 4; --digits N writes N decimals of an inch.
  inch-precision)
    printf '%s\n' '%' 'O2000' 'G20 G90 G17' 'T1 M6' 'G43.4 H1' 'S8000 M3' 'G1 X1.2346 Y0.5 Z2. A0. C0. F20.' \
      'X1.25 Y0.50001' 'G49' 'M30' '%' >in.nc
    for d in iso linuxcnc siemens heidenhain; do
      run 0 translate --from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect $d -o in.$d in.nc
    done
    has_line in.iso 'X1.25 Y0.50001 Z2. A0. C0.'
    has_line in.linuxcnc 'X1.25 Y0.50001 Z2 A0 C0'
    has_line in.siemens 'X1.25 Y0.50001 Z2 A0 C0'
    has_line in.heidenhain '[0-9]+ L X\+1.25 Y\+0.50001 Z\+2 A\+0 C\+0'
    run 0 reverse --machine ac-trunnion --dialect iso -o in.apt in.nc
    has_line in.apt 'GOTO/1.25,0.50001,2,0,0,1'
    run 0 translate --from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect siemens --digits 3 -o d3.mpf in.nc
    has_line d3.mpf 'G1 X1.235 Y0.5 Z2 A0 C0 F20'
    has_line d3.mpf 'X1.25 Y0.5 Z2 A0 C0'
    ;;
  load-tool-apt)
    # APT LOAD/TOOL,4 is a tool change: a TOOL CALL 4 on the TNC.
    printf '%s\n' 'PARTNO TC' 'UNITS/MM' 'LOAD/TOOL,4' 'SPINDL/RPM,6000,CLW' 'FEDRAT/MMPM,500' \
      'GOTO/0,0,50,0,0,1' 'GOTO/10,0,50,0,0,1' 'FINI' >tc.apt
    run 0 post --machine dmu-80p -o tc.h tc.apt
    has_line tc.h '[0-9]+ TOOL CALL 4 Z'
    ;;
  tool-call-heidenhain)
    # Siemens T/M6 into Heidenhain: TOOL CALL n Z (the tool axis), no separate M6; a change
    # under TRAORI goes between M129 and M128 (no TOOL CALL while M128 is active).
    printf '%s\n' 'N10 T1 D1' 'N20 M6' 'N30 TRAORI' 'N40 G1 X0 Y0 Z50 A-30 B10 F500' 'N50 T2 M6' \
      'N60 G1 X1 Y0 Z50 A-30 B10' 'N70 TRAFOOF' 'N80 M30' >tt.mpf
    run 0 translate --from sajo-12000p --to dmu-80p -o tt.h tt.mpf
    has_line tt.h '[0-9]+ TOOL CALL 1 Z'
    no_line tt.h '.*M6.*'
    awk '/TOOL CALL 2 Z$/ { if (prev !~ / M129$/) bad = 1; getline; if ($0 !~ / M128$/) bad = 1; seen = 1 }
         { prev = $0 } END { exit !(seen && !bad) }' tt.h ||
      { report "TOOL CALL 2 not between M129 and M128"; show tt.h; }
    ;;
  # ISO output: G43.4 with its H register; G54 as a code.
  iso-g43-h)
    run 0 translate --from sajo-12000p --to dmu-80p --to-dialect iso -o e.nc "$example"
    has_line e.nc 'N70 G43.4 H1'
    no_line e.nc '(.* )?G43\.4( [^H].*)?'
    ;;
  # ISO output: G43.4 / G43.5 always with H, the length offset of the loaded tool; with no tool
  # change before it no register is known: refused at the block (G43.4 alone would take
  # whatever H is in effect on the control).
  iso-g43-without-tool)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B10 F500' 'N30 TRAFOOF' 'N40 M30' >nt.mpf
    run 2 translate --from sajo-12000p --to sajo-12000p --to-dialect iso -o nt.nc nt.mpf
    error_at 'nt.mpf:1:1: error: cannot write the program as iso: block cannot be written in ISO: G43.4: tool-tip tracking switched on before any tool change: no tool gives its length offset H'
    nothing nt.nc
    ;;
  # ISO tool length compensation (G43.4 H n) into the dialects that take the length with the
  # tool: H equal to the loaded tool is that tool's own length (Siemens D1, Heidenhain TOOL CALL,
  # LinuxCNC G43 H1), never a comment; H of another tool is refused at its block (Siemens,
  # Heidenhain) or at the tracked move it would apply to (LinuxCNC), nothing written.
  length-h-siemens|length-h-heidenhain|length-h-linuxcnc)
    to=${name#length-h-}
    for h in 1 2; do
      printf '%s\n' '%' 'O3000' 'G21 G90 G17' 'T1 M6' "G43.4 H$h" 'G1 X0. Y0. Z50. A0. C0. F500.' 'X10.' 'G49' \
        'M30' '%' >h$h.nc
    done
    set -- --from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect "$to"
    run 0 translate "$@" -o h1.out h1.nc
    no_line h1.out '.*H1.*iso.*|.*iso.*H1.*'
    case $to in
      siemens) has_line h1.out 'D1'; has_line h1.out 'TRAORI'; has_line h1.out 'TRAFOOF D0' ;;
      heidenhain) has_line h1.out '[0-9]+ TOOL CALL 1 Z'; has_line h1.out '[0-9]+ M128' ;;
      # G43 on a line before M428: LinuxCNC runs a line's M428 before its G43 (order of execution)
      linuxcnc) has_line h1.out 'G43 H1'; n=$(grep -nx 'G43 H1' h1.out | head -1 | cut -d: -f1)
        line_is h1.out $((${n:-0} + 1)) 'M428( \(G43\.4 H1\))?' ;;
    esac
    run 2 translate "$@" -o h2.out h2.nc
    case $to in
      siemens) error_at 'h2.nc:5:1: error: cannot write the program as siemens: tool length compensation H2 while tool 1 is loaded' ;;
      heidenhain) error_at 'h2.nc:5:1: error: cannot write the program as heidenhain: block cannot be written in heidenhain: tool length compensation H2 while tool 1 is loaded' ;;
      linuxcnc) error_at 'h2.nc:6:1: error: cannot write the program as linuxcnc: block cannot be written in LinuxCNC: a move under tracking while G43 does not hold the loaded tool' ;;
    esac
    nothing h2.out
    ;;
  # On an 840D the working plane turns the tool length (G18: along Y) and the TRAORI orientation:
  # another dialect's G18 is refused in Siemens output, and a Siemens move under G18 is refused
  # as a source, while a length may be in effect (docs/dialects/siemens.md).
  plane-length)
    printf '%s\n' '%' 'O3000' 'G21 G90 G17' 'T1 M6' 'G43.4 H1' 'G18' 'G1 X0. Y0. Z50. A0. C0. F500.' 'G49' 'M30' \
      '%' >p.nc
    run 2 translate --from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect siemens -o p.mpf p.nc
    error_at 'p.nc:6:1: error: cannot write the program as siemens: G18 while tool length compensation may be on'
    nothing p.mpf
    printf '%s\n' 'N10 T1 M6' 'N20 D1' 'N30 TRAORI' 'N40 G18' 'N50 G1 X0 Y0 Z50 A-30 B10 F500' 'N60 TRAFOOF' \
      'N70 M30' >p.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o p.h p.mpf
    error_at 'p.mpf:5:1: error: motion under G18 while tool length compensation may be on'
    nothing p.h
    ;;
  iso-g54)
    run 0 translate --from sajo-12000p --to dmu-80p --to-dialect iso -o e.nc "$example"
    has_line e.nc 'N20 G54'
    ;;
  # ISO output: a decimal point on every coordinate, angle, I J K, R and F (`X10` is 0.010 mm
  # on a Fanuc control in decimal-point-input mode); S, T, M, N, H stay whole numbers.
  iso-decimal-point)
    printf '%s\n' 'N10 T1 M6' 'N20 S4000 M3' 'N30 TRAORI' 'N40 G1 X10 Y0 Z50 A-30 B10 F500' \
      'N50 G2 X20 Y0 I5 J0' 'N60 TRAFOOF' 'N70 M30' >d.mpf
    run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect iso -o d.nc d.mpf
    has_line d.nc 'N20 S4000 M3'
    has_line d.nc 'N40 G1 X10\. Y0\. Z50\. A-30\. B10\. F500\.'
    has_line d.nc 'N50 G2 X20\. Y0\. I5\. J0\.'
    no_line d.nc '(.* )?[XYZABCIJKRF][-+]?[0-9]+( .*)?'
    ;;
  # Cutter radius compensation is translated where the part stays the same and refused, at its
  # block, elsewhere (docs/dialects/compensation.md); never passed on as a comment or dropped.
  compensation-rl)
    tnc RL0 'X+0 Y+0 Z+50 B+0 C+0 RL F500' 'L X+10 Y+5' 'L X+20 R0'
    run 0 translate --from dmu-80p --to dmu-80p --to-dialect iso -o rl0.nc RL0.h
    has_line rl0.nc 'N3 G17 G41 D1 G1 X0\. Y0\. Z50\. B0\. C0\. F500\.'
    has_line rl0.nc 'N5 G40 G1 X20\. Y5\. Z50\. B0\. C0\.'
    no_line rl0.nc '.* (RL|RR|R0)( .*)?'
    tnc RL 'X+0 Y+0 Z+50 B+10 C+0 RL F500'
    run 2 translate --from dmu-80p --to dmu-80p --to-dialect iso -o rl.nc RL.h
    error_at 'RL.h:4:1: error: cutter radius compensation: the tool axis is not along Z'
    nothing rl.nc
    ;;
  compensation-g42)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 G42 X0 Y0 Z50 A-30 B10 F500' 'N30 TRAFOOF' 'N40 M30' >g42.mpf
    run 2 translate --from sajo-12000p --to dmu-80p --to-dialect iso -o g42.nc g42.mpf
    error_at 'g42.mpf:2:8: error: G42: cutter radius compensation with no D and no tool change before it'
    nothing g42.nc
    ;;
  compensation-g41-iso)
    printf '%s\n' '%' 'O3000' 'G21 G90 G17' 'T1 M6' 'G43.4 H1' 'G1 X0. Y0. Z50. A0. C0. F500.' \
      'G41 D1 X10. Y0.' 'X20. Y10.' 'G40 X30. Y10.' 'G49' 'M30' '%' >g41.nc
    run 0 translate --from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect siemens -o g41.mpf g41.nc
    has_line g41.mpf 'D1'
    has_line g41.mpf 'G41 X10 Y0 Z50 A0 C0'
    has_line g41.mpf 'G40 X30 Y10 Z50 A0 C0'
    no_line g41.mpf '.*;.*(G4[0-2]|D[0-9]).*'
    sed 's/G41 D1/G41 D2/' g41.nc >d2.nc
    run 2 translate --from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect siemens -o d2.mpf d2.nc
    error_at 'd2.nc:7:1: error: cannot write the program as siemens: cutter radius compensation D2 while tool 1 is loaded'
    nothing d2.mpf
    ;;
  compensation-g41-linuxcnc)
    printf '%s\n' 'G21 G90 G17' 'T1 M6' 'G43' 'M428' 'G1 X0 Y0 Z50 A0 C0 F500' 'G42 X10 Y0' 'G40 X20' 'M429' 'M30' >g42.ngc
    run 2 translate --from xyzac-trt --to xyzac-trt --from-dialect linuxcnc --to-dialect iso -o g42.nc g42.ngc
    error_at "g42.ngc:6:1: error: cutter radius compensation between linuxcnc and iso: switched off (line 7) before the contour's first element"
    nothing g42.nc
    # Entered and left straight on along X: both controls place the tool alike, so it is written.
    printf '%s\n' 'G21 G90 G17' 'T1 M6' 'G43' 'M428' 'G1 X0 Y0 Z50 A0 C0 F500' 'G42 X10 Y0' 'G1 X20' 'G40 X30' 'M429' 'M30' >g42s.ngc
    run 0 translate --from xyzac-trt --to xyzac-trt --from-dialect linuxcnc --to-dialect iso -o g42s.nc g42s.ngc
    has_line g42s.nc 'G42 D1 X10\. Y0\. Z50\. A0\. C0\.'
    has_line g42s.nc 'G40 X30\. Y0\. Z50\. A0\. C0\.'
    ;;
  compensation-cutcom)
    printf '%s\n' 'PARTNO CC' 'UNITS/MM' 'LOAD/TOOL,1' 'FEDRAT/MMPM,500' 'GOTO/0,0,50,0,0,1' 'CUTCOM/LEFT,1' \
      'GOTO/10,0,50,0,0,1' 'CUTCOM/OFF' 'FINI' >cc.apt
    run 2 post --machine dmu-80p --dialect heidenhain -o cc.h cc.apt
    error_at 'cc.apt:6:1: error: CUTCOM/LEFT: cutter radius compensation'
    nothing cc.h
    ;;
  # A drilling cycle and its M99 calls are refused, never a comment plus an M99 (a subprogram
  # return on a Fanuc control).
  cycle-200-m99)
    printf '%s\n' '0 BEGIN PGM CY MM' '1 TOOL CALL 1 Z S4000' '2 CYCL DEF 200 DRILLING ~' \
      '  Q200=+2 ;SET-UP CLEARANCE ~' '  Q201=-10 ;DEPTH' '3 L X+10 Y+10 Z+50 B+0 C+0 FMAX M99' \
      '4 END PGM CY MM' >cy.h
    run 2 translate --from dmu-80p --to dmu-80p --to-dialect iso -o cy.nc cy.h
    error_at 'cy.h:3:3: error: CYCL DEF 200'
    error_at 'cy.h:6:33: error: M99: '
    nothing cy.nc
    ;;
  # A block continued with ~ after a ;comment stays one block: its M3 is on the move's block.
  continued-after-comment)
    printf '%s\n' '0 BEGIN PGM TL MM' '1 TOOL CALL 1 Z S4000' '2 M128' '3 L X+0 Y+0 Z+50 B+10 C+0 F500 ;finish ~' \
      '  M3' '4 L X+1 Y+0 Z+50' '5 M129' '6 END PGM TL MM' >TL.h
    run 0 translate --from dmu-80p --to dmu-80p --to-dialect siemens -o tl.mpf TL.h
    has_line tl.mpf 'N3 G1 X0 Y0 Z50 B10 C0 F500 M3 ; finish'
    no_line tl.mpf '(N[0-9]+ )?M3'
    ;;
  # Vendor M codes (the machine maker's meaning) are refused across dialects.
  m126)
    tnc M126 'X+0 Y+0 Z+50 B+10 C+0 F500' 'M126'
    run 2 translate --from dmu-80p --to dmu-80p --to-dialect iso -o m.nc M126.h
    error_at 'M126.h:5:3: error: M126: '
    nothing m.nc
    ;;
  m13|m117|m429)
    m=$(echo "$name" | tr m M)
    printf '%s\n' 'N10 TRAORI' "N20 G1 X0 Y0 Z50 A-30 B10 F500 $m" 'N30 TRAFOOF' 'N40 M30' >m.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o m.h m.mpf
    error_at "m.mpf:2:32: error: $m: an M function of siemens whose meaning is the machine maker's"
    nothing m.h
    ;;
  # post reads CL data only: an NC program is refused, not written as comments.
  post-nc)
    run 2 post --machine dmu-80p -o p.h "$example"
    error_at "$example: error: not APT CL data: it reads as an NC program in the siemens dialect"
    nothing p.h
    printf '%s\n' '%' 'O1000' 'G0 X0 Y0 Z50.' 'G1 X10. F500' 'M30' '%' >plain.nc
    run 2 post --machine dmu-80p -o p.h plain.nc
    # No marker: one error naming the dialect whose reader reads it, not one per line.
    error_at 'plain.nc: error: not APT CL data: it reads as an NC program in the iso dialect (no GOTO/, and its reader finds fewer errors)'
    [ "$(grep -c ' error: ' err)" = 1 ] || { report "not one error"; show err; }
    nothing p.h
    ;;
  # An empty input is an error.
  empty-input)
    : >empty.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o e.h empty.mpf
    error_at 'empty.mpf: error: empty program'
    nothing e.h
    ;;
  # The summary counts what was written: nothing when the write fails.
  summary-after-failed-write)
    [ -w /dev/full ] || { echo "no writable /dev/full: row not run"; exit 0; }
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B10 F500' 'N30 TRAFOOF' 'N40 M30' >s.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o /dev/full s.mpf
    error_at "kin5 translate: cannot write '/dev/full'"
    grep -q ' 4 written' err && { report "summary counts blocks never written"; show err; }
    error_at 'kin5 translate: 4 blocks read, 0 written'
    ;;
  # Output precision never drops below the source's: 4 decimals in, 4 out.
  precision)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X-34.9834 Y9.1006 Z118.5261 A-77.954 B3.536 F1091' 'N30 TRAFOOF' 'N40 M30' >fine.mpf
    run 0 translate --from sajo-12000p --to dmu-80p -o fine.h fine.mpf
    has_line fine.h '[0-9]+ L X\+34\.9834 Y\+118\.5261 Z\+9\.1006 .*'
    ;;
  # A modal G0 holds for the blocks after it: each is FMAX in Heidenhain (FMAX holds for its
  # block only), and an F given under G0 is the F of the next feed move, in every dialect.
  modal-rapid)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z5 A0 B0 F100' 'N30 G0 X0 Y0 Z50' 'N40 X10' 'N45 X12 F300' \
      'N50 G1 X20' 'N60 TRAFOOF' 'N70 M30' >rapid.mpf
    run 0 translate --from sajo-12000p --to dmu-80p -o rapid.h rapid.mpf
    has_line rapid.h '4 L X-10 Y\+50 Z\+0 B\+180 C\+0 FMAX'
    has_line rapid.h '5 L X-12 Y\+50 Z\+0 B\+180 C\+0 FMAX'
    has_line rapid.h '6 L X-20 Y\+50 Z\+0 B\+180 C\+0 F300'
    run 0 translate --from sajo-12000p --to sajo-12000p -o same.mpf rapid.mpf
    has_line same.mpf 'N50 G1 X20 Y0 Z50 A0 B0 F300'
    ;;
  # Framing: each output opens and closes as its controller's manual says, once, and never
  # copies the source's frame (a `%` tape mark once became `; %` and `(%)`).
  frame-siemens)
    printf '%s\n' '%' 'O1234' 'G21 G90 G94' 'T1 M6' 'G43.4 H1' 'G1 X0. Y0. Z50. A-30. B10. F500.' 'G49' 'M30' '%' >o.nc
    run 0 translate --from sajo-12000p --to sajo-12000p --from-dialect iso --to-dialect siemens -o o.mpf o.nc
    line_is o.mpf 1 '%_N_PGM_1234_MPF'
    line_is o.mpf 2 ';\$PATH=/_N_MPF_DIR'
    count_is o.mpf '.*%.*' 1
    ;;
  frame-iso)
    run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect iso -o t.nc "$example"
    line_is t.nc 1 '%'
    line_is t.nc 2 'O0001 \(TABLE1_SAJO\)'
    line_is t.nc '$' '%'
    count_is t.nc '%' 2
    count_is t.nc '.*M30.*' 1
    run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect iso --program-number 12 -o n.nc "$example"
    line_is n.nc 2 'O0012 \(TABLE1_SAJO\)'
    run 1 translate --from sajo-12000p --to sajo-12000p --program-number 12 -o s.mpf "$example"
    nothing s.mpf
    ;;
  frame-linuxcnc)
    printf '%s\n' '%' 'O1234' 'G21 G90 G94' 'T1 M6' 'G43.4 H1' 'G1 X0. Y0. Z50. A-30. B10. F500.' 'G49' 'M30' '%' >o.nc
    run 0 translate --from sajo-12000p --to sajo-12000p --from-dialect iso --to-dialect linuxcnc -o o.ngc o.nc
    line_is o.ngc 1 '%'
    line_is o.ngc '$' '%'
    count_is o.ngc '.*%.*' 2
    ;;
  # Nothing but comments after the end: a working block there never runs on the source control
  # (Siemens `M30` then `M5 M2` once became Heidenhain `M30`, `M5 M2`, `END PGM`).
  after-end)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B10 F500' 'N30 TRAFOOF' 'N40 M30' 'N50 ; done' 'N60 M5 M2' >e.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o e.h e.mpf
    error_at 'e.mpf:6:1: error: cannot write the program as heidenhain: block after the program end (line 4): the source control never runs it'
    nothing e.h
    head -n 5 e.mpf >ok.mpf  # the comment after the end stays a comment, before END PGM
    run 0 translate --from sajo-12000p --to dmu-80p -o ok.h ok.mpf
    line_is ok.h '$' '[0-9]+ END PGM ok MM'
    has_line ok.h '[0-9]+ ;done'
    count_is ok.h '[0-9]+ M30' 1
    ;;
  # G43 H n after G43.4 (Haas G234) replaces it in modal group 08: tracking ends there, so the
  # rotary move after it is machine axes with the length along Z, never a tracked tool tip
  # (it once became `; G43 H1` and a move under TRAORI).
  g43-ends-tcp)
    printf '%s\n' '%' 'O1' 'G21 G90 G17' 'T1 M6' 'G43.4 H1' 'G1 X0. Y0. Z10. A0. C0. F100.' 'G43 H1' \
      'G1 X10. A30.' 'G49' 'M30' >t.nc
    run 2 translate --from ac-trunnion --from-dialect iso --to ac-trunnion --to-dialect siemens -o t.mpf t.nc
    error_at 't.nc:8:1: error: rotary motion without tool-tip tracking'
    nothing t.mpf
    run 2 reverse --machine ac-trunnion --dialect iso -o t.apt t.nc
    error_at 't.nc:8:1: error: rotary motion without tool-tip tracking'
    nothing t.apt
    sed 's/^G43.4 H1$/G234 H1/' t.nc >h.nc
    run 2 translate --from ac-trunnion --from-dialect haas --to ac-trunnion --to-dialect siemens -o h.mpf h.nc
    error_at 'h.nc:8:1: error: rotary motion without tool-tip tracking'
    nothing h.mpf
    sed '8d' t.nc >n.nc  # no move under G43: G43 writes tracking off, then the length alone
    run 0 translate --from ac-trunnion --from-dialect iso --to ac-trunnion --to-dialect iso -o n2.nc n.nc
    has_line n2.nc 'G49'
    has_line n2.nc 'G43 H1'
    ;;
  # In inverse time (G93) F is not modal: a feed move without its own F was read and written with
  # no F, and `--feed inverse-time` wrote its first move (unknown start, no block time) without F.
  inverse-time-f)
    printf '%s\n' '%' 'O1' 'T1 M6' 'G43.4 H1' 'G93' 'G1 X0. Y0. Z10. A0. C0. F10.' 'G1 X10.' 'G94' 'G49' 'M30' >g.nc
    run 2 translate --from ac-trunnion --from-dialect iso --to ac-trunnion --to-dialect siemens -o g.mpf g.nc
    error_at 'g.nc:7:1: error: feed move in inverse time (G93) without its own F'
    nothing g.mpf
    # The 840D keeps F in G93 until another is given: the ISO output writes it in the block.
    printf '%s\n' 'N5 T1 M6' 'N10 TRAORI' 'N15 G93' 'N20 G1 X0 Y0 Z0 A-10 B20 F10' 'N30 G1 X10' 'N40 M30' >s.mpf
    run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect iso -o s.nc s.mpf
    has_line s.nc 'N30 G1 X10\. Y0\. Z0\. A-10\. B20\. F10\.'
    printf '%s\n' 'N5 T1 M6' 'N10 TRAORI' 'N20 G1 X0 Y0 Z0 A-10 B20 F100' 'N30 G1 X10 F20' 'N40 M30' >p.mpf
    run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect linuxcnc --feed inverse-time -o p.ngc p.mpf
    has_line p.ngc 'N20 G1 X0 Y0 Z0 A-10 B20 F100'
    has_line p.ngc 'N30 G1 G93 X10 Y0 Z0 A-10 B20 F2'
    run 0 translate --from sajo-12000p --from-dialect linuxcnc --to sajo-12000p -o q.mpf p.ngc  # reads back
    ;;
  # Bytes a terminal acts on never reach it from a diagnostic: the Heidenhain reader once quoted
  # ESC sequences and 0xFF as read (a program could clear the screen or fake a diagnostic).
  escaped-bytes)
    esc=$(printf '\033')
    printf '0 BEGIN PGM A MM\n1 FUNCTION TCPM F TCP AXIS POS %s[2J\n2 L X+0 Y+0 Z+50 B+10 C+0 F500 R\377\n3 END PGM %s[31m MM\n' \
      "$esc" "$esc" >e.h
    run 2 translate --from dmu-80p --to dmu-80p -o e2.h e.h
    if grep -q "$esc" err || LC_ALL=C grep -q "$(printf '\377')" err; then report "a raw ESC or 0xFF byte in a message"; show err; fi
    grep -qF '\x1B[31m' err || { report "no escaped ESC"; show err; }
    nothing e2.h
    ;;
  # Dialect markers inside comments say nothing: a Siemens program noting LinuxCNC's M428 in a
  # comment was not recognised, and was read as the machine's default dialect, LinuxCNC.
  guess-outside-comments)
    printf '%s\n' 'N10 T1 M6' 'N20 TRAORI ; M428 on LinuxCNC' 'N30 G1 X0 Y0 Z50 A-30 C0 F500' '(G234)' 'N40 TRAFOOF' 'N50 M30' >g.mpf
    run 0 translate --from xyzac-trt --to xyzac-trt -o g.ngc g.mpf
    grep -q 'reading g.mpf as siemens' err || { report "not read as siemens"; show err; }
    has_line g.ngc 'N20 M428( \(.*\))?'
    ;;
  # A LinuxCNC control acts on some comments: another dialect's `; ABORT, …` became
  # `(ABORT, …)`, which stops the program there, and `; PY, …` would run Python.
  linuxcnc-active-comment)
    printf '%s\n' 'N5 T1 M6' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 C0 F500 ; ABORT, stop here' '; PY, x=1' \
      'N30 G1 X10 ; MSG, hello' 'N40 TRAFOOF' 'N50 M30' >a.mpf
    run 0 translate --from xyzac-trt --to xyzac-trt --from-dialect siemens --to-dialect linuxcnc -o a.ngc a.mpf
    has_line a.ngc 'N20 G1 X0 Y0 Z50 A-30 C0 F500 \(- ABORT, stop here\)'
    has_line a.ngc '\(- PY, x=1\)'
    has_line a.ngc 'N30 G1 X10 .*\(- MSG, hello\)'
    run 0 translate --from xyzac-trt --to xyzac-trt --from-dialect linuxcnc -o b.ngc a.ngc  # reads back
    ;;
  # LinuxCNC's `(ABORT, …)` stops the program there with an error; it was refused (and, before
  # that, written as a comment with the moves after it). Each NC dialect now writes its alarm
  # stop before the next move, and the output reads back through kin5 to the same abort: its
  # message, after the first move and before the second. APT CL data have no alarm: refused.
  linuxcnc-abort)
    printf '%s\n' '%' 'G21 G90 G17' 'T1 M6 G43' 'M428' 'G1 X0 Y0 Z10 A0 C0 F100' '(probe) (ABORT, probe failed)' \
      'G1 X10 A30' 'M429' 'M2' '%' >a.ngc
    for d in linuxcnc iso haas siemens heidenhain; do
      run 0 translate --from xyzac-trt --to xyzac-trt --from-dialect linuxcnc --to-dialect "$d" -o "a.$d" a.ngc
      case $d in
        linuxcnc) alarm='\(probe\) \(ABORT, probe failed\)' ;;
        iso | haas) alarm='#3000=1 \(probe failed\)' ;;
        siemens) alarm='SETAL\(65000,"probe failed"\) ; probe' ;;
        heidenhain) alarm='[0-9]+ FN 14: ERROR = 1 ;probe failed' ;;
      esac
      count_is "a.$d" "$alarm" 1
      run 0 translate --from xyzac-trt --to xyzac-trt --from-dialect "$d" --to-dialect linuxcnc -o "b.$d.ngc" "a.$d"
      count_is "b.$d.ngc" '(N[0-9]+ )?(\([^()]*\) )?\(ABORT, probe failed\)' 1
      # the abort between the two moves, as in the source (block numbers where the source had them)
      awk '/^(N[0-9]+ )?G1 X0 /{m=NR} /^(N[0-9]+ )?(\([^()]*\) )?\(ABORT, probe failed\)$/{a=NR} /^(N[0-9]+ )?G1 X10 /{n=NR}
           END{exit !(m && a > m && n > a)}' \
        "b.$d.ngc" || { report "b.$d.ngc: the abort is not between the moves"; show "b.$d.ngc"; }
    done
    run 2 reverse --machine xyzac-trt --dialect linuxcnc -o a.apt a.ngc
    error_at 'a.ngc:6:1: error: cannot write the program as apt: block cannot be written in APT: an alarm stop'
    nothing a.apt
    ;;
  # A Siemens unit switch after motion (G700 after G710) was written as G20 after motion, which
  # ISO, Haas and LinuxCNC refuse, and refused by the Heidenhain writer: each now writes the
  # program in its first unit, the blocks after the switch converted, and reads it back.
  unit-switch)
    printf '%s\n' 'N10 G710 G90 G17' 'N20 T1 M6' 'N30 TRAORI' 'N40 G1 X0 Y0 Z50 A-30 B10 F500' \
      'N50 G700 X1 F20' 'N60 Y0.5' 'N70 TRAFOOF' 'N80 M30' >u.mpf
    for d in iso haas linuxcnc heidenhain; do
      run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect "$d" -o "u.$d" u.mpf
      no_line "u.$d" '.*G20.*'
      run 0 reverse --machine sajo-12000p --dialect "$d" -o "u-$d.apt" "u.$d"
    done
    has_line u.iso 'N50 X25\.4 Y0\. Z50\. A-30\. B10\. F508\.'
    has_line u.heidenhain '[0-9]+ L X\+25\.4 Y\+0 Z\+50 A-30 B\+10 F508( M128)?'
    ;;
  # ISO G49 is Siemens D0, which kin5 read as a word it could not translate (into APT: refused).
  g49-siemens)
    printf '%s\n' '%' 'O1' 'G21 G90 G17' 'T1 M6' 'G43.4 H1' 'G1 X0. Y0. Z50. A-30. B10. F500.' 'G49' 'M30' '%' >g.nc
    run 0 translate --from sajo-12000p --to sajo-12000p --from-dialect iso --to-dialect siemens -o g.mpf g.nc
    has_line g.mpf 'TRAFOOF D0'
    run 0 reverse --machine sajo-12000p --dialect siemens -o g.apt g.mpf
    run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect iso -o g2.nc g.mpf
    has_line g2.nc 'G49( \(siemens: D0\))?'
    ;;
  # A translation to the same machine is the identity: the plan once broke a tie of rotary
  # travel toward branch 0 (ac-trunnion A10 C0 became A-10 C180; bc-trunnion B-20 C10, B20 C-170).
  same-machine-branch)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A10 C0 F500' 'N30 G1 X10 A20 C30' 'N40 TRAFOOF' 'N50 M30' >ac.mpf
    run 0 translate --from ac-trunnion --to ac-trunnion --to-dialect siemens -o ac-out.mpf ac.mpf
    has_line ac-out.mpf 'N20 G1 X0 Y0 Z50 A10 C0 F500'
    has_line ac-out.mpf 'N30 G1 X10 Y0 Z50 A20 C30'
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 B-20 C10 F500' 'N30 TRAFOOF' 'N40 M30' >bc.mpf
    run 0 translate --from bc-trunnion --to bc-trunnion --to-dialect siemens -o bc-out.mpf bc.mpf
    has_line bc-out.mpf 'N20 G1 X0 Y0 Z50 B-20 C10 F500'
    ;;
  # A rotary sweep of 180° or more under tool-tip tracking keeps its travel: the control turns
  # the axes linearly, so B0 then B350 sweeps the tool round the part, where B-10 (least travel)
  # swept it 10° the other way, and a full turn became no motion.
  sweep-same-machine)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B0 F500' 'N30 G1 X10 B350' 'N40 G1 X20 B710' 'N50 TRAFOOF' 'N60 M30' >s.mpf
    run 0 translate --from sajo-12000p --to sajo-12000p -o s-out.mpf s.mpf
    has_line s-out.mpf 'N30 G1 X10 Y0 Z50 A-30 B350'
    has_line s-out.mpf 'N40 G1 X20 Y0 Z50 A-30 B710'
    no_line err '.*warning.*'
    ;;
  # Into the DMU 80P, whose C table turns about the SAJO's B axis under the paper's setup, the
  # sweep is followed by C; into the DMU 50V, whose axes cannot turn the tool round the SAJO's
  # Y axis, the block is refused where the sweep is.
  sweep-other-machine)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B0 F500' 'N30 G1 X10 B350' 'N40 TRAFOOF' 'N50 M30' >s.mpf
    run 0 translate --from sajo-12000p --to dmu-80p --to-dialect siemens -o d.mpf s.mpf
    has_line d.mpf 'N20 G1 X0 Y50 Z0 B90 C54.736 F500'
    has_line d.mpf 'N30 G1 X-10 Y50 Z0 B90 C404.736'
    run 2 translate --from sajo-12000p --to dmu-50v -o v.h s.mpf
    error_at "s.mpf:3:1: error: dmu-50v cannot follow this block's rotary sweep (B turns by 350.000° from B=0.000)"
    nothing v.h
    ;;
  # Into APT CL data, where one GOTO says only where the tool axis ends, a full turn of B is
  # written as GOTO points along it (8 per half turn), not as no turn at all.
  sweep-reverse)
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B0 F500' 'N30 G1 X16 B360' 'N40 TRAFOOF' 'N50 M30' >s.mpf
    run 0 reverse --machine sajo-12000p -o s.apt s.mpf
    count_is s.apt 'GOTO/.*' 17
    has_line s.apt 'GOTO/8,0,50,-?0,0\.5,-0\.866[0-9]*'
    has_line s.apt 'GOTO/16,0,50,-?0,0\.5,0\.866[0-9]*'
    ;;
  # --feed inverse-time copied a source G94 beside the G93 feed: `G1 G94 … F40.5`, the time's
  # inverse read as mm/min. The output's feed mode is the policy's, in every dialect with G93.
  inverse-time-no-source-g94)
    printf '%s\n' 'T1 M6' 'G43 M428' 'G0 X80 Y50 Z60 B160 C-20' \
      'G1 X87.774 Y60.348 Z54.153 B160.985 C-26.687 F3577' \
      'G1 G94 X130.708 Y-10.422 Z34.038 B143.485 C132.564 F3449' 'M429' 'M30' >g.ngc
    for d in haas iso linuxcnc siemens; do
      run 0 translate --from bc-nutating-table --from-dialect linuxcnc --to dmu-50v --to-dialect "$d" \
        --feed inverse-time -o "g-$d.nc" g.ngc
      no_line "g-$d.nc" '.*G94.*'
      has_line "g-$d.nc" '(G1 )?G93 (G1 )?X87\.774 .* F[0-9.]+'
      has_line "g-$d.nc" 'G1 X130\.708 Y-10\.422 Z34\.038 .* F40\.5'
    done
    ;;
  # `reverse` wrote the GOTO of a straight move ending elsewhere on the circle of the arc before
  # it straight after that arc's CIRCLE, which kin5's APT reader refuses as ambiguous.
  circle-then-chord)
    printf '%s\n' '%' 'O0001' 'G21 G90 G17' 'T1 M6' 'G234 H1' 'G0 X30. Y0. Z99.475 B0 C0' 'G1 Z99. F500' \
      'G2 X0. Y-30. I-30. J0.' 'G1 X-30. Y0. Z90.' 'G49' 'M30' '%' >c.nc
    run 0 reverse --machine xyzbc-trt --dialect haas -o c.apt c.nc
    run 0 post --machine xyzbc-trt --dialect haas -o c2.nc c.apt
    has_line c2.nc 'G2 X0\. Y-30\. I-30\. J0\.'
    has_line c2.nc 'G1 X-30\. Y0\. Z90\. .*'
    ;;
  # `post` wrote FEDRAT/INVERS as `G93 F12.3` on its own line and the moves after it without F,
  # where every inverse-time NC move needs its own; into Heidenhain the second move was refused.
  post-fedrat-invers)
    printf '%s\n' 'UNIT/MM' 'LOADTL/1' 'RAPID' 'GOTO/0,0,50,0,0,1' 'FEDRAT/MMPM,500' 'GOTO/10,0,50,0,0,1' \
      'FEDRAT/INVERS,12.3' 'GOTO/20,0,50,0,0.1,0.995' 'GOTO/30,0,50,0,0.2,0.98' 'FEDRAT/MMPM,600' \
      'GOTO/40,0,50,0,0.2,0.98' 'FINI' >f.apt
    for d in iso linuxcnc siemens; do
      run 0 post --machine dmu-50v --dialect "$d" -o "f-$d.nc" f.apt
      no_line "f-$d.nc" 'G93 F.*'
      count_is "f-$d.nc" 'G1 X[23]0\.? .* F12\.3' 2
    done
    run 0 post --machine dmu-50v --dialect heidenhain -o f.h f.apt
    count_is f.h '[0-9]+ L X\+[23]0 .* F123' 2
    ;;
  *)
    echo "silent.sh: unknown row '$name'" >&2
    exit 2
    ;;
esac
exit "$fail"
