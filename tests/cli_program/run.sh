#!/bin/sh
# End-to-end tests of `kin5 translate`, `kin5 reverse` and `kin5 post`.
#
#   run.sh KIN5_EXE EXAMPLES_DIR TEST_NAME
#
# Each test runs the built tool on a program (the shipped examples, or one written below),
# then checks the exit code, stdout/stderr and the output file. Expected numbers are typed from
# docs/golden.md (Table 1 and its feed column), docs/matchability.md, (K1), (K7) or worked by hand, never taken
# from kin5's own output. Numbers are read back from the written program by awk.
set -u

. "$(cd "$(dirname "$0")" && pwd)/harness.sh"

# words FILE: for every motion line, "X Y Z A B C F" values as NAME=VALUE pairs on one line
# (Siemens, ISO and Heidenhain words such as X-34.983, X+34.983, B17.067; comments dropped).
words() {
  awk '{
    sub(/;.*/, ""); sub(/\(.*\)/, "")
    out = ""
    for (i = 1; i <= NF; ++i) {
      w = toupper(substr($i, 1, 1)); v = substr($i, 2)
      if (index("XYZABCF", w) && v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)$/) out = out " " w "=" (v + 0)
    }
    if (out != "") print out
  }' "$1"
}

# value LINE NAME: the number of NAME=... in LINE (empty if absent).
value() { printf '%s\n' "$1" | awk -v n="$2" '{ for (i = 1; i <= NF; ++i) if (index($i, n "=") == 1) print substr($i, length(n) + 2) }'; }

# near A B TOL: |A - B| <= TOL.
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }

# near360 A B TOL: A and B equal modulo 360 within TOL.
near360() {
  awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = (a - b) % 360; if (d < 0) d += 360; if (d > 180) d = 360 - d; exit !(d <= t) }'
}

# line_with FILE NAME VALUE: the first words() line whose NAME is VALUE (within 1e-6).
line_with() {
  words "$1" | while IFS= read -r l; do
    v=$(value "$l" "$2")
    if [ -n "$v" ] && near "$v" "$3" 1e-6; then printf '%s\n' "$l"; break; fi
  done
}

# Table 1 (docs/golden.md): SAJO X Y Z A B F -> DMU X Y Z B C.
table1='-34.983 9.100 118.526 -77.954 3.536 1091 34.983 118.526 9.100 17.067 87.479
-33.824 9.118 117.545 -77.913 4.027 1093 33.824 117.545 9.118 17.126 87.950
-32.674 9.153 116.558 -77.918 4.588 1094 32.674 116.558 9.153 17.118 88.513
-31.531 9.203 115.567 -77.963 5.158 1096 31.531 115.567 9.203 17.054 89.106'

# check_table1 FILE [FEEDS]: the four Table 1 rows are in FILE: X Y Z exact (to 1e-6), B and C
# within 0.001 deg, F as FEEDS (default: the SAJO feeds, the tcp policy) within 1 mm/min.
check_table1() {
  file=$1 feeds=${2:-"1091 1093 1094 1096"}
  n=0
  printf '%s\n' "$table1" | while read -r sx sy sz sa sb sf dx dy dz db dc; do
    n=$((n + 1))
    f=$(echo "$feeds" | awk -v k="$n" '{ print $k }')
    l=$(line_with "$file" X "$dx")
    if [ -z "$l" ]; then echo "row $n: no block with X=$dx" >&2; exit 1; fi
    for pair in "Y $dy 1e-6" "Z $dz 1e-6" "B $db 0.001" "F $f 1"; do
      set -- $pair
      v=$(value "$l" "$1")
      if [ -z "$v" ] || ! near "$v" "$2" "$3"; then echo "row $n: $1=$v, expected $2 (tolerance $3): $l" >&2; exit 1; fi
    done
    v=$(value "$l" C)
    if [ -z "$v" ] || ! near360 "$v" "$dc" 0.001; then echo "row $n: C=$v, expected $dc (mod 360, tolerance 0.001): $l" >&2; exit 1; fi
  done
}

example="$examples/table1-sajo.mpf"
# The example selects G54, which has no certain equivalent on a TNC (presets) nor in CL data:
# the runs below say what it is there (docs/user-guide.md, work offsets).
g54="--work-offset-map G54=1"
no_g54="--work-offset-map G54="

case "$name" in
  example)
    # Table 1, sajo -> dmu, default feed policy (tcp: F kept).
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o table1.h "$example"
    [ -s table1.h ] || report "table1.h not written"
    [ -s out ] && report "stdout not empty with -o"
    check_table1 table1.h || { report "Table 1 values"; show table1.h; }
    ;;
  block-time)
    # (K17) f_d = f_s l_d / l_s on consecutive rows: docs/golden.md gives 1089.25, 1094.48, 1102.02 for
    # rows 2-4; row 1 comes from a pure 50 mm approach (no rotary change): F kept, 1091.
    run 0 translate --from sajo-12000p --to dmu-80p $g54 --feed block-time -o bt.h "$example"
    check_table1 bt.h "1091 1089.25 1094.48 1102.02" || { report "block-time feeds"; show bt.h; }
    ;;
  crlf)
    # Read as bytes: the example with CRLF line ends gives the same motion.
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o lf.h "$example"
    awk '{ printf "%s\r\n", $0 }' "$example" >crlf.mpf
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o crlf.h crlf.mpf
    check_table1 crlf.h || { report "Table 1 values from CRLF input"; show crlf.h; }
    words lf.h >a; words crlf.h >b
    cmp -s a b || report "CRLF and LF inputs give different motion"
    ;;
  stdin-stdout)
    # '-' in and out: the same program as file to file.
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o file.h "$example"
    "$exe" translate --from sajo-12000p --to dmu-80p $g54 - <"$example" >piped.h 2>err
    [ $? = 0 ] || { report "stdin run failed"; show err; }
    check_table1 piped.h || { report "Table 1 values through a pipe"; show piped.h; }
    words file.h >a; words piped.h >b
    cmp -s a b || { report "stdin/stdout and file/file motion differ"; show file.h piped.h; }
    "$exe" translate --from sajo-12000p --to dmu-80p $g54 -o - "$example" >dash.h 2>err
    words dash.h >c
    cmp -s a c || report "-o - differs from -o file"
    # Errors in stdin are named <stdin>.
    printf 'N10 TRAORI\nN20 TRANS X1\n' | "$exe" translate --from sajo-12000p --to dmu-80p $g54 - >out 2>err
    [ $? = 2 ] || report "bad stdin: exit code"
    grep -q '^<stdin>:2:5: error: ' err || { report "bad stdin: no <stdin>:2:5 error"; show err; }
    ;;
  summary)
    # The example has 23 lines, one block each; 6 of them move (the approach, the four rows
    # and the retract), all directly reachable.
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o s.h "$example"
    grep -Eq '23 blocks read, 23 written, [0-9]+ passed through; 6 direct, 0 other-branch, 0 unreachable' err ||
      { report "summary line"; show err; }
    ;;
  bad-input)
    # Errors at known places, every one reported as FILE:LINE:COL: error: at the first byte of
    # the offending word: a number that is not one (X1.2.3), an unknown word (YY), a frame
    # change with motion (TRANS, not supported).
    printf '%s\n' 'N10 G17 G90 G94' 'N20 TRAORI' 'N30 G1 X1.2.3 Y0 Z0 F100' 'N40 G1 X0 Y0 Z5' \
      'N50 G1 X1 Y2 Z3 YY F100' 'N60 G1 X0 Y0 TRANS' 'N70 M30' >bad.mpf
    echo keep >bad.h
    cp bad.h before.h
    run 2 translate --from sajo-12000p --to dmu-80p $g54 -o bad.h bad.mpf
    for where in 'bad.mpf:3:8: error: ' 'bad.mpf:5:17: error: ' 'bad.mpf:6:14: error: '; do
      grep -Fq -- "$where" err || report "missing '$where...'"
    done
    n=$(grep -c ': error: ' err)
    [ "$n" = 3 ] || report "$n errors reported, expected 3"
    grep -v ': error: ' err | grep -Ev '^kin5 translate: ' | grep -q . && report "stray stderr lines"
    [ -s out ] && report "stdout not empty"
    cmp -s bad.h before.h || report "existing output changed"
    [ "$fail" = 0 ] || show err
    ;;
  unreachable)
    # A > 0 cannot be reached on the DMU (docs/matchability.md): gap exactly A, for every B. Three such
    # blocks among reachable ones; A = -100 is reachable (other branch, C + 180).
    printf '%s\n' 'N10 G17 G90 G94' 'N20 TRAORI' 'N30 G1 X0 Y0 Z50 A-45 B30 F1000' \
      'N40 G1 X1 Y0 Z50 A5 B30' 'N50 G1 X2 Y0 Z50 A-30 B60' 'N60 G1 X3 Y0 Z50 A10 B200' \
      'N70 G1 X4 Y0 Z50 A-100 B20' 'N80 G1 X5 Y0 Z50 A20 B0' 'N90 TRAFOOF' 'N100 M30' >up.mpf
    run 3 translate --from sajo-12000p --to dmu-80p $g54 -o up.h up.mpf
    for pair in '4 5' '6 10' '8 20'; do
      set -- $pair
      l=$(grep -E "^up\.mpf:$1:[0-9]+: error: " err)
      [ -n "$l" ] || { report "line $1 not listed"; continue; }
      echo "$l" | grep -q 'dmu-80p cannot reach this block' || report "line $1: not called unreachable: $l"
      g=$(echo "$l" | sed -n 's/.*tool axis \([0-9.]*\).* outside.*/\1/p')
      { [ -n "$g" ] && near "$g" "$2" 0.001; } || report "line $1: gap '$g', expected $2"
      echo "$l" | grep -Eq "A=?$2([^0-9]|$)" || report "line $1: source angle A$2 not shown: $l"
    done
    n=$(grep -c ': error: ' err)
    [ "$n" = 3 ] || report "$n errors, expected 3"
    grep -Eq '1 other-branch, 3 unreachable' err || report "summary counts"
    [ -e up.h ] && report "up.h created on failure"
    [ -s out ] && report "stdout not empty"
    [ "$fail" = 0 ] || show err
    ;;
  unreachable-runs)
    # Consecutive unreachable blocks are one error per run, with its worst block; a comment
    # inside a run does not split it, a reachable block does. A > 0 on the DMU: gap A (as above).
    {
      printf '%s\n' 'N10 G17 G90 G94' 'N20 TRAORI' 'G1 X0 Y0 Z50 A-45 B30 F1000'
      awk 'BEGIN { for (i = 0; i < 20000; ++i) { if (i == 10000) print "; midway"; printf "G1 X%d Y0 Z50 A%d B30\n", i % 100, 5 + i % 20 } }'
      printf '%s\n' 'G1 X1 Y0 Z50 A-30 B30' 'G1 X2 Y0 Z50 A7 B30' 'G1 X3 Y0 Z50 A8 B30' 'G1 X4 Y0 Z50 A-30 B30' \
        'G1 X5 Y0 Z50 A9 B30' 'N90 TRAFOOF' 'N100 M30'
    } >runs.mpf
    run 3 translate --from sajo-12000p --to dmu-80p -o runs.h runs.mpf
    [ "$(wc -l <err)" = 5 ] || report "$(wc -l <err) lines on stderr, expected 5 (3 errors, summary, total)"
    grep -qx 'runs.mpf:4:1: error: dmu-80p cannot reach the 20000 blocks of lines 4-20004; the worst, at line 23: tool axis 24.000° outside the reach of dmu-80p' err ||
      report "run of lines 4-20004 not one error with its worst block"
    grep -qx 'runs.mpf:20006:1: error: dmu-80p cannot reach the 2 blocks of lines 20006-20007; the worst, at line 20007: tool axis 8.000° outside the reach of dmu-80p' err ||
      report "run of lines 20006-20007 not one error"
    grep -Eq '^runs.mpf:20009:1: error: dmu-80p cannot reach this block \(A=9(\.0+)? B=30(\.0+)?\): tool axis 9.000° outside' err ||
      report "a block alone is not its own error"
    grep -q ' 3 direct, 0 other-branch, 20003 unreachable$' err || report "summary counts"
    grep -q '^kin5 translate: 20003 blocks cannot be reached on dmu-80p; nothing written$' err || report "total"
    [ "$fail" = 0 ] || show err
    ;;
  no-partial)
    # A failing run leaves an existing OUT byte for byte as it was, creates no new OUT, and
    # leaves no temporary file behind; a successful one replaces OUT.
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A10 B0 F500' 'N30 M30' >up.mpf
    printf 'previous contents\n' >out.h
    cp out.h before.h
    run 3 translate --from sajo-12000p --to dmu-80p $g54 -o out.h up.mpf
    cmp -s out.h before.h || report "exit 3 changed out.h"
    run 3 translate --from sajo-12000p --to dmu-80p $g54 -o new.h up.mpf
    [ -e new.h ] && report "exit 3 created new.h"
    run 2 translate --from sajo-12000p --to dmu-80p $g54 -o new.h missing.mpf
    [ -e new.h ] && report "exit 2 created new.h"
    [ "$(ls -A | grep -c kin5)" = 0 ] || report "temporary files left: $(ls -A)"
    chmod 640 out.h
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o out.h "$example"
    check_table1 out.h || report "out.h not replaced on success"
    [ "$(stat -c %a out.h)" = 640 ] || report "out.h lost its permissions: $(stat -c %a out.h)"
    [ "$(ls -A | grep -c kin5)" = 0 ] || report "temporary files left: $(ls -A)"
    ;;
  missing-input)
    run 2 translate --from sajo-12000p --to dmu-80p $g54 -o x.h does-not-exist.mpf
    grep -q "does-not-exist.mpf" err || report "path not named"
    [ -e x.h ] && report "x.h created"
    mkdir adir
    run 2 translate --from sajo-12000p --to dmu-80p $g54 adir
    grep -q "adir" err || report "directory not named"
    ;;
  usage)
    run 1 translate --from sajo-12000p --to no-such-machine "$example"
    grep -q "unknown machine 'no-such-machine'" err || report "unknown machine message"
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --feed fast "$example"
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --to-dialect fanuc "$example"
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --to-dialect apt "$example"
    run 1 translate --from sajo-12000p "$example"
    run 1 translate --from sajo-12000p --to dmu-80p $g54
    run 1 post --machine dmu-80p --dialect klingon "$examples/cl-path.apt"
    # Heidenhain has no inverse-time feed (G93): an argument error, found before reading.
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --feed inverse-time "$example"
    grep -q 'inverse-time' err || report "inverse-time message"
    ;;
  inverse-time)
    # With a dialect that has G93 the translation runs and switches G93 on.
    run 0 translate --from sajo-12000p --to dmu-80p --to-dialect siemens --feed inverse-time -o it.mpf "$example"
    grep -q 'G93' it.mpf || { report "no G93 in the output"; show it.mpf; }
    ;;
  both-ways)
    # Table 1 back again: DMU 80P -> SAJO 12000P on the translated program returns the SAJO
    # columns (K13; docs/golden.md: within 0.00055 deg of the table), B compared modulo 360.
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o there.h "$example"
    run 0 translate --from dmu-80p --to sajo-12000p --work-offset-map 1=G54 -o back.mpf there.h
    grep -q ' G54$' back.mpf || { report "preset 1 not back to G54"; show back.mpf; }
    printf '%s\n' "$table1" | while read -r sx sy sz sa sb rest; do
      l=$(line_with back.mpf X "$sx")
      [ -n "$l" ] || { echo "no block with X=$sx" >&2; exit 1; }
      { near "$(value "$l" Y)" "$sy" 1e-6 && near "$(value "$l" Z)" "$sz" 1e-6 &&
        near "$(value "$l" A)" "$sa" 0.001 && near360 "$(value "$l" B)" "$sb" 0.001; } ||
        { echo "expected X=$sx Y=$sy Z=$sz A=$sa B=$sb: $l" >&2; exit 1; }
    done || { report "SAJO values"; show back.mpf; }
    ;;
  guess-dialect)
    # A Heidenhain program given for the SAJO (whose default is siemens) is recognised by
    # BEGIN PGM and M128, with a note, and read as Heidenhain.
    printf '%s\n' '0 BEGIN PGM T1 MM' '1 TOOL CALL 1 Z S4000' '2 M128' \
      '3 L X-34.983 Y+9.1 Z+118.526 A-77.954 B+3.536 F1091' \
      '4 L X-33.824 Y+9.118 Z+117.545 A-77.913 B+4.027 F1093' \
      '5 L X-32.674 Y+9.153 Z+116.558 A-77.918 B+4.588 F1094' \
      '6 L X-31.531 Y+9.203 Z+115.567 A-77.963 B+5.158 F1096' '7 M129' '8 END PGM T1 MM' >t1.h
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o t1-dmu.h t1.h
    grep -q 'as heidenhain' err || report "no note on the recognised dialect"
    check_table1 t1-dmu.h || { report "Table 1 values from a Heidenhain source"; show t1-dmu.h; }
    # Told explicitly, kin5 reads it as Siemens, and fails on the Heidenhain words.
    run 2 translate --from sajo-12000p --to dmu-80p $g54 --from-dialect siemens -o t1-dmu.h t1.h
    ;;
  reverse)
    # NC -> CL: GOTO/x,y,z,i,j,k with (i,j,k) = (cos A sin B, -sin A, cos A cos B) (K1).
    run 0 reverse --machine sajo-12000p $no_g54 -o t.apt "$example"
    printf '%s\n' "$table1" | while read -r sx sy sz sa sb rest; do
      l=$(grep -E "^GOTO/" t.apt | awk -F'[/,]' -v x="$sx" '{ d = $2 - x; if (d < 0) d = -d; if (d < 1e-6) { print; exit } }')
      [ -n "$l" ] || { echo "no GOTO at X=$sx" >&2; exit 1; }
      echo "$l" | awk -F'[/,]' -v y="$sy" -v z="$sz" -v a="$sa" -v b="$sb" 'BEGIN { r = atan2(0, -1) / 180 } {
        i = cos(a * r) * sin(b * r); j = -sin(a * r); k = cos(a * r) * cos(b * r)
        e = 0; d[1] = $3 - y; d[2] = $4 - z; d[3] = $5 - i; d[4] = $6 - j; d[5] = $7 - k
        for (n = 1; n <= 5; ++n) { t = d[n] < 0 ? -d[n] : d[n]; if (t > (n < 3 ? 1e-6 : 1e-6)) e = 1 }
        if (NF != 7 || e) { print "bad GOTO: " $0 > "/dev/stderr"; exit 1 } }' || exit 1
    done || { report "GOTO values"; show t.apt; }
    ;;
  post)
    # CL -> DMU 80P: B = arccos(2k - 1) (K7) for each tool axis of the example; the cut is at
    # Z10, Y-20, X 0..40. With k = 0.9516840, 0.9768268, 0.9852558 (hand-normalised vectors):
    # B = 25.3956, 17.5121, 13.9488 deg (arccos(2k-1), worked out separately).
    run 0 post --machine dmu-80p -o p.h "$examples/cl-path.apt"
    for pair in '0 25.3956' '10 17.5121' '20 13.9488' '30 17.5121' '40 25.3956'; do
      set -- $pair
      l=$(words p.h | while IFS= read -r w; do
            x=$(value "$w" X); z=$(value "$w" Z)
            if [ -n "$x" ] && [ -n "$z" ] && near "$x" "$1" 1e-6 && near "$z" 10 1e-6; then echo "$w"; break; fi
          done)
      b=$(value "$l" B)
      { [ -n "$b" ] && near "$b" "$2" 0.001; } || report "X=$1: B=$b, expected $2"
    done
    [ "$fail" = 0 ] || show p.h err
    ;;
  source-checks)
    # A program must fit its own machine (translate/source_checks.hpp): the SAJO 12000P has A
    # and B, A travels over [-120, 30] deg. A C word, an A past -120 and the Table 1 example
    # given with the wrong --from are errors at the word, and nothing is written.
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 B10 F500' 'N30 G1 X1 C77' 'N40 G1 X2 A-150' 'N50 M30' >foreign.mpf
    run 2 translate --from sajo-12000p --to dmu-80p $g54 -o f.h foreign.mpf
    grep -q '^foreign\.mpf:3:11: error: C77: sajo-12000p has no C axis' err || { report "C77 not refused at 3:11"; show err; }
    grep -q '^foreign\.mpf:4:11: error: A-150: outside the travel of A on sajo-12000p, \[-120°, 30°\]' err ||
      { report "A-150 not refused at 4:11"; show err; }
    [ -e f.h ] && report "f.h written"
    run 2 translate --from dmu-80p --to sajo-12000p -o w.mpf "$example"
    grep -q "^.*table1-sajo\.mpf:14:[0-9]*: error: A-77.954: dmu-80p has no A axis" err ||
      { report "wrong --from not detected"; show err; }
    # Within the angle tolerance a value past the edge is on it; the default, half a unit of the
    # 4th decimal, is 0.00005 deg: 0.0004 past is refused.
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-120.0004 B10 F500' 'N30 M30' >edge.mpf
    run 0 translate --from sajo-12000p --to sajo-12000p --to-dialect siemens --angle-tolerance 0.001 -o e.mpf edge.mpf
    run 2 translate --from sajo-12000p --to sajo-12000p --to-dialect siemens -o e.mpf edge.mpf
    ;;
  unset-rotary)
    # A rotary axis with no value at a motion is refused (its pose would be a guess), unless
    # allowed by name.
    printf '%s\n' 'N10 TRAORI' 'N20 G1 X0 Y0 Z50 A-30 F500' 'N30 G1 X1 B10' 'N40 M30' >unset.mpf
    run 2 translate --from sajo-12000p --to dmu-80p $g54 -o u.h unset.mpf
    grep -q '^unset\.mpf:2:1: error: rotary axis B has no value yet' err || { report "unset B not refused"; show err; }
    grep -q -- '--allow unset-rotary' err || report "the option is not named"
    run 0 translate --from sajo-12000p --to dmu-80p $g54 --allow unset-rotary -o u.h unset.mpf
    grep -q '^unset\.mpf:2:1: warning: rotary axis B has no value yet.*allowed' err || { report "no allowed warning"; show err; }
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --allow everything -o u.h unset.mpf
    ;;
  empty-input)
    # No block at all: an input error, nothing written.
    : >empty.mpf
    printf '\n  \n\n' >blank.mpf
    for f in empty.mpf blank.mpf; do
      run 2 translate --from sajo-12000p --to dmu-80p $g54 -o e.h "$f"
      grep -q "^$f: error: empty program" err || { report "$f: no empty-program error"; show err; }
      [ -e e.h ] && report "$f: e.h written"
    done
    ;;
  post-nc)
    # post reads CL data: an NC program given to it is refused, by its markers or because no
    # statement of it is APT, never written as comments.
    run 2 post --machine dmu-80p -o p.h "$example"
    grep -q 'not APT CL data: it reads as an NC program in the siemens dialect' err || { report "Siemens program accepted"; show err; }
    printf '%s\n' '%' 'O1000' 'G0 X0 Y0 Z50.' 'G1 X10. F500' 'M30' '%' >plain.nc
    run 2 post --machine dmu-80p -o p.h plain.nc
    # Without markers: no GOTO/ and the ISO reader finds fewer errors than APT's, so one error
    # names the dialect it reads as, not one APT error per line.
    grep -q "^plain.nc: error: not APT CL data: it reads as an NC program in the iso dialect" err || { report "plain ISO accepted"; show err; }
    [ "$(grep -c 'error:' err)" = 1 ] || { report "not one error"; show err; }
    [ -e p.h ] && report "p.h written"
    ;;
  summary-after-write)
    # The summary comes after the output is committed and counts what OUT holds: nothing when
    # the device is full.
    if [ -w /dev/full ]; then
      run 2 translate --from sajo-12000p --to dmu-80p $g54 -o /dev/full "$example"
      grep -q "cannot write '/dev/full'" err || { report "no write error"; show err; }
      grep -q '23 written' err && { report "summary counts blocks never written"; show err; }
      grep -Eq '23 blocks read, 0 written' err || { report "summary line"; show err; }
    fi
    ;;
  precision)
    # A source with 4 decimals keeps them in the output (the TNC reads 4); --digits 2 rounds.
    sed 's/X-34.983 Y9.100/X-34.9834 Y9.1006/' "$example" >fine.mpf
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o fine.h fine.mpf
    l=$(line_with fine.h X 34.9834)
    [ -n "$l" ] || { report "X34.9834 not kept"; show fine.h; }
    near "$(value "$l" Z)" 9.1006 1e-9 || report "Z9.1006 not kept: $l"
    run 0 translate --from sajo-12000p --to dmu-80p $g54 --digits 2 -o d2.h fine.mpf
    [ -n "$(line_with d2.h X 34.98)" ] || { report "--digits 2"; show d2.h; }
    ;;
  m-codes)
    # An M function whose meaning is the machine maker's (Heidenhain M126, shortest rotary path)
    # is refused at its word in another dialect, or dropped knowingly with --m-map; M3 and M8
    # mean the same everywhere and are carried.
    printf '%s\n' '0 BEGIN PGM M MM' '1 TOOL CALL 3 Z S8000' '2 M128' '3 L X+0 Y+0 Z+50 B+10 C+0 F500 M3' \
      '4 M126' '5 L X+1 M8' '6 M129' '7 END PGM M MM' >m.h
    run 2 translate --from dmu-80p --to dmu-80p --to-dialect iso -o m.nc m.h
    grep -q '^m\.h:5:3: error: M126: ' err || { report "M126 not refused at 5:3"; show err; }
    grep -q -- '--m-map 126=' err || report "the option is not named"
    [ -e m.nc ] && report "m.nc written"
    run 0 translate --from dmu-80p --to dmu-80p --to-dialect iso --m-map 126= -o m.nc m.h
    grep -q 'M126' m.nc && { report "M126 written"; show m.nc; }
    grep -q 'M3' m.nc && grep -q 'M8' m.nc || { report "M3 or M8 lost"; show m.nc; }
    run 1 translate --from dmu-80p --to dmu-80p --to-dialect iso --m-map 126 -o m.nc m.h
    ;;
  work-offsets)
    # The example's G54 (line 8, column 5) has no certain equivalent on a TNC (presets) nor in
    # CL data: refused at the word, naming the option, nothing written. Mapped, it is Cycle 247
    # with Q339; into ISO it is G54 itself (both select the first settable zero offset).
    run 2 translate --from sajo-12000p --to dmu-80p -o w.h "$example"
    grep -q 'table1-sajo\.mpf:8:5: error: G54: a work offset of siemens with no certain equivalent in heidenhain' err ||
      { report "G54 into heidenhain not refused at 8:5"; show err; }
    grep -q -- '--work-offset-map G54=' err || report "the option is not named"
    [ -e w.h ] && report "w.h written"
    run 2 reverse --machine sajo-12000p -o w.apt "$example"
    grep -q 'table1-sajo\.mpf:8:5: error: G54: .* in apt' err || { report "G54 into apt not refused"; show err; }
    run 0 translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1 -o p.h "$example"
    grep -q ' CYCL DEF 247 DATUM SETTING ~$' p.h && grep -q '^  Q339=+1$' p.h || { report "no preset 1"; show p.h; }
    run 0 translate --from sajo-12000p --to dmu-80p --to-dialect iso -o i.nc "$example"
    grep -q '^N20 G54$' i.nc || { report "G54 not written into iso"; show i.nc; }
    # Back from the TNC program: preset 1 is refused into Siemens, or mapped to G55.
    run 2 translate --from dmu-80p --to dmu-80p --to-dialect siemens -o s.mpf p.h
    grep -q '^p\.h:[0-9]*:1: error: preset 1: ' err || { report "preset 1 into siemens not refused"; show err; }
    run 0 translate --from dmu-80p --to dmu-80p --to-dialect siemens --work-offset-map 1=G55 -o s.mpf p.h
    grep -q ' G55$' s.mpf || { report "preset 1 not written as G55"; show s.mpf; }
    # A mapping to a selection the target lacks, and one that is not a selection.
    run 2 translate --from sajo-12000p --to dmu-80p --work-offset-map G54=G55 -o w.h "$example"
    grep -q 'G54: --work-offset-map gives G55, which heidenhain does not select' err || { report "unwritable map"; show err; }
    run 1 translate --from sajo-12000p --to dmu-80p --work-offset-map G54=G53 -o w.h "$example"
    run 1 translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1,G54=2 -o w.h "$example"
    ;;
  linuxcnc)
    # tests/programs/linuxcnc/boss_chamfer.ngc, written for LinuxCNC's xyzac-trt sim (tracking by
    # M428, identity by M429 around the tool change, G43 after each M6), to the DMU 80P and back,
    # each machine in its own dialect by default. There: M128 / M129 and TOOL CALL, no ISO word.
    # Back: LinuxCNC's words again (%, M428, M429 before the second M6), and every motion block
    # at the source's pose: X Y Z within 1e-4 mm, A C within 0.001 deg (C modulo 360).
    src="$examples/../tests/programs/linuxcnc/boss_chamfer.ngc"
    run 0 translate --from xyzac-trt --to dmu-80p --work-offset-map G54=1 -o there.h "$src"
    grep -q ' M128' there.h && grep -q ' M129' there.h && grep -q ' TOOL CALL 3 Z$' there.h &&
      ! grep -q '^[0-9]* [^;]*\(G43\.4\|M428\)' there.h || { report "not heidenhain tracking"; show there.h; }
    run 0 translate --from dmu-80p --to xyzac-trt --work-offset-map 1=G54 -o back.ngc there.h
    grep -q '^%$' back.ngc && grep -q ' G54$' back.ngc && ! grep -q 'G43\.[45]\|G49$' back.ngc ||
      { report "not LinuxCNC framing and offsets"; show back.ngc; }
    awk '/^[^(]*M429/ { off = NR } / T3 M6/ { change = NR; before = off } /^[^(]*M428/ { if (change && !on) on = NR }
         END { exit !(before && on) }' back.ngc ||
      { report "no M429 before the second M6 and M428 after it"; show back.ngc; }
    poses() { words "$1" | awk '{ for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
                                 if ($0 ~ /[XYZAC]=/) print v["X"], v["Y"], v["Z"], v["A"], v["C"] }'; }
    poses "$src" >src.poses
    poses back.ngc >back.poses
    [ "$(wc -l <src.poses)" = "$(wc -l <back.poses)" ] && [ "$(wc -l <src.poses)" -gt 20 ] ||
      { report "motion blocks: $(wc -l <src.poses) in, $(wc -l <back.poses) back"; show back.ngc; }
    paste -d ' ' src.poses back.poses | while read -r x y z a c bx by bz ba bc; do
      { near "$x" "$bx" 1e-4 && near "$y" "$by" 1e-4 && near "$z" "$bz" 1e-4 && near "$a" "$ba" 0.001 &&
        near360 "$c" "$bc" 0.001; } || { echo "pose $x $y $z $a $c came back as $bx $by $bz $ba $bc" >&2; exit 1; }
    done || report "poses not kept"
    ;;
  machine-coordinates)
    # A move in machine coordinates is translated by its distance from each axis' home, which the
    # machine files give (home_mm); without it the move is refused naming the key. G30, M92 and
    # LinuxCNC's G28 are refused; so is a rotary positioning before any retract.
    printf '%s\n' 'N10 G54' 'N20 SUPA G0 Z0' 'N30 TRAORI' 'N40 G1 X0 Y0 Z50 A-45 B30 F500' 'N50 M30' >mc.mpf
    run 2 translate --from sajo-12000p --to dmu-80p --to-dialect iso -o mc.nc mc.mpf
    grep -q "^mc\.mpf:2:1: error: a move in machine coordinates (G53, SUPA, M91) of Z needs the source machine's home of Z: give home_mm in \[linear\.Z\]" err ||
      { report "SUPA move without a home not refused by its key"; show err; }
    printf '%s\n' '%' 'O1' 'G54' 'G43.4 H1' 'G1 X0 Y0 Z50. B10. C20. F500' 'G49' 'G91 G28 Z0' 'G90' 'M30' '%' >mc.nc
    run 2 translate --from dmu-80p --to dmu-80p --from-dialect iso --to-dialect siemens -o mc.mpf mc.nc
    grep -q "^mc\.nc:7:1: error: a move to the reference point (G28) of Z needs the target machine's home of Z" err ||
      { report "G28 into a target without a home not refused by its key"; show err; }
    printf '%s\n' '%' 'O1' 'G90 G21 G94' 'G30 G91 Z0' 'G90' 'M30' '%' >g30.nc
    run 2 translate --from dmu-80p --to dmu-80p --from-dialect iso -o g30.h g30.nc
    grep -q '^g30\.nc:4:1: error: a move to the second reference point (G30) is not translated' err || { report "G30 not refused"; show err; }
    printf '%s\n' '%' 'G21 G90' 'G91 G28 Z0' 'G90' 'M2' '%' >g28.ngc
    run 2 translate --from xyzbc-trt --to xyzbc-trt --from-dialect linuxcnc -o g28.out.ngc g28.ngc
    grep -q '^g28\.ngc:3:1: error: a move to the position the control keeps for G28 (LinuxCNC) is not translated: LinuxCNC keeps it in parameters #5161-#5166' err ||
      { report "LinuxCNC G28 not refused"; show err; }
    ;;
  home-moves)
    # The CAM safe start in every NC dialect: retract, park, rotary positioning with tracking off,
    # tracking on, approach, cut, retract, park. Source: the B/C trunnion with its homes at machine
    # zero; target: the A/C trunnion whose homes are X100 Y-50 Z-10 (machine files). Expected by
    # hand: the retract Z-10 (M140 MB MAX: the top of Z's travel, 0), the park 200 mm and 100 mm
    # from the homes, X-100 Y-150; the positioning B30 C45 is u = (sin30 cos45, sin30 sin45, cos30)
    # (tool-relative B about Y, C about Z), and on the A/C trunnion (physical A about X carrying C
    # about Z) u = (sinA sinC, sinA cosC, cosA); the tip under tracking is unchanged (no setup).
    machines="$examples/../machines"
    awk '/^\[linear\.[XYZ]\]/ { print; print "home_mm = 0"; next } /^letter = "[BC]"/ { print; print "home_deg = 0"; next } { print }' \
      "$machines/bc-trunnion.toml" | sed 's/^id = "bc-trunnion"/id = "shop-bc"/' >bc.toml
    awk '/^\[linear\.X\]/ { print; print "home_mm = 100"; next } /^\[linear\.Y\]/ { print; print "home_mm = -50"; next }
         /^\[linear\.Z\]/ { print; print "home_mm = -10"; next } { print }' \
      "$machines/ac-trunnion.toml" | sed 's/^id = "ac-trunnion"/id = "shop-ac"/' >ac.toml
    printf '%s\n' '%' 'O1000' 'G90 G17 G21 G94' 'G53 G0 Z0.' 'G91 G28 X0. Y0.' 'G91 G28 B0. C0.' 'G90' 'T1 M6' 'S8000 M3' \
      'G0 B30. C45.' 'G43.4 H1' 'G0 X10. Y5. Z50. B30. C45.' 'G1 Z2. F500.' 'G1 X40. F800.' 'G0 Z50.' 'G49' 'G53 G0 Z0.' \
      'G53 G0 X-200. Y-100.' 'M30' '%' >cam.nc
    sed 's/G43\.4 H1/G234 H1/' cam.nc >cam-haas.nc
    printf '%s\n' '%' 'G21 G90 G17 G94' 'G53 G0 Z0' 'G53 G0 X0 Y0' 'G53 G0 B0 C0' 'T1 M6' 'G43 H1' 'S8000 M3' 'G0 B30 C45' \
      'M428' 'G0 X10 Y5 Z50 B30 C45' 'G1 Z2 F500' 'G1 X40 F800' 'G0 Z50' 'M429' 'G53 G0 Z0' 'G53 G0 X-200 Y-100' 'M2' '%' >cam.ngc
    printf '%s\n' 'G710 G90 G17 G94' 'SUPA G0 Z0' 'SUPA G0 X0 Y0' 'SUPA G0 B0 C0' 'T1 M6' 'D1' 'S8000 M3' 'G0 B30 C45' 'TRAORI' \
      'G0 X10 Y5 Z50 B30 C45' 'G1 Z2 F500' 'G1 X40 F800' 'G0 Z50' 'TRAFOOF' 'SUPA G0 Z0' 'SUPA G0 X-200 Y-100' 'M30' >cam.mpf
    printf '%s\n' '0 BEGIN PGM CAM MM' '1 TOOL CALL 1 Z S8000' '2 M140 MB MAX' '3 L X+0 Y+0 FMAX M91' '4 L B+30 C+45 FMAX' \
      '5 M128' '6 L X+10 Y+5 Z+50 B+30 C+45 FMAX M3' '7 L Z+2 F500' '8 L X+40 F800' '9 L Z+50 FMAX' '10 M129' \
      '11 L Z+0 FMAX M91' '12 L X-200 Y-100 FMAX M91' '13 END PGM CAM MM' >cam.h
    for source in iso:cam.nc haas:cam-haas.nc linuxcnc:cam.ngc siemens:cam.mpf heidenhain:cam.h; do
      from=${source%%:*} file=${source#*:}
      for to in iso siemens heidenhain linuxcnc haas; do
        out="out-$from.$to"
        run 0 translate --from-file bc.toml --from-dialect "$from" --to-file ac.toml --to-dialect "$to" -o "$out" "$file"
        [ -s "$out" ] || { report "$from -> $to: nothing written"; continue; }
        # machine-coordinate lines: G53 (ISO, Haas, LinuxCNC), SUPA (Siemens), M91 (Heidenhain)
        grep -E 'G53|SUPA|M91' "$out" >mc-lines
        words mc-lines >mc-words
        top=-10; [ "$from" = heidenhain ] && top=0
        first=$(sed -n 1p mc-words) park=$(sed -n 2p mc-words) last=$(tail -n 1 mc-words) retract=$(tail -n 2 mc-words | head -n 1)
        { near "$(value "$first" Z)" "$top" 1e-9 && [ -z "$(value "$first" X)" ]; } || report "$from -> $to: first retract $first, expected Z=$top"
        { near "$(value "$park" X)" 100 1e-9 && near "$(value "$park" Y)" -50 1e-9; } || report "$from -> $to: park at home $park, expected X=100 Y=-50"
        near "$(value "$retract" Z)" -10 1e-9 || report "$from -> $to: last retract $retract, expected Z=-10"
        { near "$(value "$last" X)" -100 1e-9 && near "$(value "$last" Y)" -150 1e-9; } || report "$from -> $to: last park $last, expected X=-100 Y=-150"
        # the positioning B30 C45 (tracking off): A and C alone, for the same tool axis
        pos=$(words "$out" | awk '/A=/ && /C=/ && !/X=/ && !/A=0( |$)/' | sed -n 1p)
        a=$(value "$pos" A) c=$(value "$pos" C)
        awk -v a="$a" -v c="$c" 'BEGIN { d = atan2(0, -1) / 180; s = sin(30 * d)
          e = (sin(a*d)*sin(c*d) - s*cos(45*d))^2 + (sin(a*d)*cos(c*d) - s*sin(45*d))^2 + (cos(a*d) - cos(30*d))^2
          exit !(a != "" && c != "" && e < 1e-10) }' || report "$from -> $to: positioning $pos is not the tool axis of B30 C45"
        # the approach and the cut: the source's tips
        for xyz in "10 5 50" "10 5 2" "40 5 2"; do
          set -- $xyz
          words "$out" | awk -v x="$1" -v y="$2" -v z="$3" '{ ok = 0; for (i = 1; i <= NF; ++i) { split($i, kv, "=")
              if (kv[1] == "X" && kv[2] == x) ok++; if (kv[1] == "Y" && kv[2] == y) ok++; if (kv[1] == "Z" && kv[2] == z) ok++ }
            if (ok == 3) found = 1 } END { exit !found }' || report "$from -> $to: no block at X$1 Y$2 Z$3"
        done
        # the written program reads back to the same moves, in machine coordinates and not
        run 0 translate --from-file ac.toml --from-dialect "$to" --to-file ac.toml --to-dialect "$to" -o "back-$out" "$out"
        words "$out" >w1; words "back-$out" >w2
        grep -E 'G53|SUPA|M91' "$out" | wc -l >m1; grep -E 'G53|SUPA|M91' "back-$out" | wc -l >m2
        { cmp -s w1 w2 && cmp -s m1 m2; } || { report "$from -> $to: the output does not read back to its moves"; show "$out" "back-$out"; }
      done
    done
    # A rotary move with tracking off before any retract: its tip matters, refused as before.
    printf '%s\n' '%' 'O1' 'G90 G21 G94' 'G0 B30. C45.' 'M30' '%' >early.nc
    run 2 translate --from-file bc.toml --from-dialect iso --to-file ac.toml -o early.h early.nc
    grep -q '^early\.nc:4:1: error: rotary motion without tool-tip tracking' err || { report "positioning before a retract not refused"; show err; }
    printf '%s\n' '%' 'O1' 'G90 G21 G94' 'G0 X0. Y0. Z5.' 'G53 B30. C45.' 'M30' '%' >early.nc
    run 2 translate --from-file bc.toml --from-dialect iso --to-file ac.toml -o early.h early.nc
    grep -q '^early\.nc:5:1: error: a move in machine coordinates (G53, SUPA, M91) that turns the rotary axes is translated only as a positioning of the retracted tool' err ||
      { report "G53 rotary move before a retract not refused"; show err; }
    # `G91 G28 X0 Y0 B0 C0` after the retract: X and Y home while B and C turn, Z stays.
    printf '%s\n' '%' 'O1' 'G90 G21 G94' 'G91 G28 Z0.' 'G91 G28 X0. Y0. B0. C0.' 'G90' 'M30' '%' >park.nc
    run 0 translate --from-file bc.toml --from-dialect iso --to-file ac.toml --to-dialect iso -o park.out park.nc
    grep -q '^G53 G0 X100\. Y-50\. A0\.' park.out || { report "G28 of X, Y and B not one park and positioning"; show park.out; }
    # The target's travel bounds a park: 500 mm from the home of X is past the A/C trunnion's.
    printf '%s\n' '%' 'O1' 'G90 G21 G94' 'G53 G0 X-500.' 'M30' '%' >far.nc
    run 2 translate --from-file bc.toml --from-dialect iso --to-file ac.toml -o far.h far.nc
    grep -q '^far\.nc:4:1: error: shop-ac cannot reach this move in machine coordinates: X=-400.000' err || { report "park past the travel not refused"; show err; }
    ;;
  setup)
    # A setup given three ways. T of (K10) written as a matrix and as the half turn about
    # (0,1,1) ((K10): T = R((0,1,1)/sqrt2, 180 deg)) must give Table 1 exactly as the default.
    run 0 translate --from sajo-12000p --to dmu-80p $g54 --setup-rotation=-1,0,0,0,0,1,0,1,0 -o m.h "$example"
    check_table1 m.h || { report "Table 1 with --setup-rotation"; show m.h; }
    run 0 translate --from sajo-12000p --to dmu-80p $g54 --setup-axis 0,1,1 --setup-angle 180 -o a.h "$example"
    check_table1 a.h || { report "Table 1 with --setup-axis/--setup-angle"; show a.h; }
    # An offset moves every tip by (10, 20, 30) mm and leaves B and C as in Table 1.
    run 0 translate --from sajo-12000p --to dmu-80p $g54 --setup-offset 10,20,-30 -o o.h "$example"
    while read -r xs ys zs as bs fs xd yd zd bd cd; do
      x=$(awk -v v="$xd" 'BEGIN { print v + 10 }')
      l=$(line_with o.h X "$x")
      [ -n "$l" ] || { report "no block with X=$x"; continue; }
      near "$(value "$l" Y)" "$(awk -v v="$yd" 'BEGIN { print v + 20 }')" 1e-6 || report "Y of X=$x: $l"
      near "$(value "$l" Z)" "$(awk -v v="$zd" 'BEGIN { print v - 30 }')" 1e-6 || report "Z of X=$x: $l"
      near "$(value "$l" B)" "$bd" 0.001 || report "B of X=$x: $l"
      near360 "$(value "$l" C)" "$cd" 0.001 || report "C of X=$x: $l"
    done <<EOF
$table1
EOF
    [ "$fail" = 0 ] || show o.h
    # Bad setups are usage errors (exit 1) and write nothing.
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --setup-rotation 1,0,0,0,1,0,0,0,2 -o bad.h "$example"
    grep -q "not a proper rotation" err || { report "improper rotation message"; show err; }
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --setup-rotation=1,0,0,0,1,0,0,0,1 --setup-axis 0,0,1 \
      --setup-angle 5 -o bad.h "$example"
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --setup-axis 0,0,1 -o bad.h "$example"
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --setup-offset 1,2 -o bad.h "$example"
    [ -e bad.h ] && report "bad.h written on a usage error"
    ;;
  machine-files)
    # A machine file runs the same pipeline as the bundled machine it describes: translate,
    # reverse and post with --from-file/--to-file/--machine-file write byte for byte what the
    # ids write (the bundled files: machines/<id>.toml).
    machines="$examples/../machines"
    run 0 translate --from sajo-12000p --to dmu-80p $g54 -o by-id.h "$example"
    run 0 translate --from-file "$machines/sajo-12000p.toml" --to-file "$machines/dmu-80p.toml" $g54 -o by-file.h "$example"
    cmp -s by-id.h by-file.h || { report "translate: file and id outputs differ"; show by-id.h by-file.h; }
    check_table1 by-file.h || { report "Table 1 values with machine files"; show by-file.h; }
    run 0 reverse --machine sajo-12000p $no_g54 -o by-id.apt "$example"
    run 0 reverse --machine-file "$machines/sajo-12000p.toml" $no_g54 -o by-file.apt "$example"
    cmp -s by-id.apt by-file.apt || { report "reverse: file and id outputs differ"; show by-id.apt by-file.apt; }
    run 0 post --machine dmu-80p -o post-id.h "$examples/cl-path.apt"
    run 0 post --machine-file "$machines/dmu-80p.toml" -o post-file.h "$examples/cl-path.apt"
    cmp -s post-id.h post-file.h || { report "post: file and id outputs differ"; show post-id.h post-file.h; }
    # A machine no catalog has: the DMU 80P's geometry under another id (so no default setup),
    # its C table programmed in physical angles (φ = ψ, where the DMU 80P writes −ψ). With the
    # paper's setup (K10) given, Table 1 comes out with C negated (mod 360°) and B unchanged.
    sed -e 's/^id = "dmu-80p"/id = "shop-dmu"/' -e '0,/^sense = "tool-relative"/s//sense = "physical"/' \
      "$machines/dmu-80p.toml" >shop.toml
    run 0 translate --from sajo-12000p --to-file shop.toml --setup-rotation=-1,0,0,0,0,1,0,1,0 -o shop.h "$example"
    printf '%s\n' "$table1" | while read -r sx sy sz sa sb sf dx dy dz db dc; do
      l=$(line_with shop.h X "$dx")
      { [ -n "$l" ] && near "$(value "$l" B)" "$db" 0.001 &&
        near360 "$(value "$l" C)" "$(awk -v c="$dc" 'BEGIN { print -c }')" 0.001; } ||
        { echo "expected B=$db C=-($dc) at X=$dx: $l" >&2; exit 1; }
    done || { report "Table 1 on a machine from a file"; show shop.toml shop.h; }
    # Both or neither of --to and --to-file: a usage error; a broken file: an input error at its line.
    run 1 translate --from sajo-12000p --to dmu-80p $g54 --to-file shop.toml -o x.h "$example"
    run 1 translate --from sajo-12000p -o x.h "$example"
    grep -q 'give exactly one of --to ID and --to-file FILE' err || { report "neither --to nor --to-file"; show err; }
    sed 's/^direction = \[0, 0.70710678118654757, 0.70710678118654757\]/direction = [0, 0, 1]/' shop.toml >bad.toml
    run 2 reverse --machine-file bad.toml -o x.apt "$example"
    grep -q '^bad\.toml:[0-9]*:[0-9]*: error: ' err || { report "bad machine file not named at a line"; show err; }
    [ -e x.h ] || [ -e x.apt ] && report "output written on an error"
    ;;
  linear-travel)
    # With --work-offset the slides of every output block are checked against the target's
    # linear travel (G7). DMU 80P, tool vertical (B = 0): the slides are the part point plus the
    # pivot and tool lengths along Z, Z_slide = Z_tip + offset_Z + 200 + tool length, whatever
    # C is (the C table turns about Z). Z travels over [-600, 0] mm.
    printf '%s\n' '0 BEGIN PGM T2 MM' '1 TOOL CALL 1 Z S4000' '2 M128' '3 L X+10 Y+20 Z+30 B+0 C+0 F1000' \
      '4 L X+10 Y+20 Z+60 B+0 C+0 F1000' '5 M129' '6 END PGM T2 MM' >t2.h
    # offset -400, tool 100: Z = -70 and -40: within.
    run 0 translate --from dmu-80p --to dmu-80p --tool-length 100 --work-offset 0,0,-400 -o ok.h t2.h
    # offset -300: Z = 30 and 60, past 0 by 30 and 60 mm; both blocks reported, as one run whose
    # worst is line 5; nothing written.
    run 3 translate --from dmu-80p --to dmu-80p --tool-length 100 --work-offset 0,0,-300 -o past.h t2.h
    grep -q '^t2\.h:4:[0-9]*: error: dmu-80p cannot reach the 2 blocks of lines 4-5; the worst, at line 5: slide Z=60\.000 mm, 60\.000 mm past its travel \[-600\.000, 0\.000\] mm' err ||
      { report "Z 30 and 60 mm past not reported as lines 4-5, worst line 5"; show err; }
    grep -q '2 unreachable' err || { report "not counted as unreachable"; show err; }
    [ -e past.h ] && report "past.h written"
    # offset -940: Z = -610 (10 mm below -600) and -580: only the first block.
    run 3 translate --from dmu-80p --to dmu-80p --tool-length 100 --work-offset 0,0,-940 -o low.h t2.h
    grep -q '^t2\.h:4:[0-9]*: error: .*slide Z=-610\.000 mm, 10\.000 mm past' err || { report "Z 10 mm below not reported"; show err; }
    grep -q '^t2\.h:5:' err && { report "block 5 reported within travel"; show err; }
    # Without --work-offset nothing is checked; --tool-length alone is a usage error.
    run 0 translate --from dmu-80p --to dmu-80p -o free.h t2.h
    run 1 translate --from dmu-80p --to dmu-80p --tool-length 100 -o free.h t2.h
    run 1 post --machine dmu-80p --work-offset 0,0 -o p.h "$examples/cl-path.apt"
    ;;
  untracked)
    # Motion without TCP read as machine coordinates (G9): an A/C trunnion program with a 3-axis
    # section, a rotary pre-positioning, a 3+2 section, a rotary feed move, a TCP section and a
    # park move, to the DMU 50V. Both tables of the ac-trunnion turn about lines through
    # (0, 0, -200); with the work offset there, the part point of program point p at physical
    # angles A, C is R_z(-C) R_x(-A) p (worked by hand below), whatever the tool length.
    printf '%s\n' '; PART U1' 'N10 G0 X0 Y0 Z50 A0 C0' 'N20 G1 Z-2 F200' 'N30 X40 F800' 'N40 G0 Z50' \
      'N50 A-60 C90' 'N60 G1 X10 Y20 Z30 F500' 'N70 X20' 'N80 A-30 F1000' 'N90 G0 Z100' 'N100 TRAORI' \
      'N110 G1 X0 Y0 Z10 A-20 C0 F1000' 'N120 X10' 'N130 TRAFOOF' 'N140 G0 Z150' 'N150 A0 C0' 'N160 M30' >u.mpf
    # Without the source's placement: refused at the first motion, nothing written.
    run 2 translate --from ac-trunnion --to dmu-50v -o no.h u.mpf
    grep -q '^u\.mpf:2:1: error: .*--source-work-offset and --source-tool-length' err || { report "no refusal at line 2"; show err; }
    [ -e no.h ] && report "no.h written"
    # With length compensation off (LinuxCNC G49), the point programmed is the gauge point, not
    # the tip: refused at the first motion after it, even with the placement given.
    printf '%s\n' 'T1 M6' 'G43 H1' 'G0 X0 Y0 Z50 A0 C0' 'G49' 'G1 Z40 F200' 'M2' >g49.ngc
    run 2 translate --from ac-trunnion --to dmu-50v --from-dialect linuxcnc --source-work-offset 0,0,-200 \
      --source-tool-length 100 -o no.h g49.ngc
    grep -q '^g49\.ngc:5:1: error: motion without tool-tip tracking while tool length compensation is off' err ||
      { report "G49 motion read as the tip"; show err; }
    [ -e no.h ] && report "no.h written after G49"
    # The placement options are checked as the target's are: both or neither, 3 numbers, a length.
    run 1 translate --from ac-trunnion --to dmu-50v --source-work-offset 0,0 --source-tool-length 100 -o no.h u.mpf
    grep -q 'source-work-offset needs 3 numbers' err || { report "2 numbers accepted"; show err; }
    run 1 translate --from ac-trunnion --to dmu-50v --source-work-offset 0,0,-200 --source-tool-length -1 -o no.h u.mpf
    grep -q 'source-tool-length: give a length in mm, 0 or more' err || { report "negative length accepted"; show err; }
    run 1 translate --from ac-trunnion --to dmu-50v --source-work-offset 0,0,-200 -o no.h u.mpf
    grep -q 'source-work-offset and --source-tool-length (or --tool-table) go together' err || { report "offset alone accepted"; show err; }
    [ -e no.h ] && report "no.h written"
    run 1 translate --from ac-trunnion --to dmu-50v --source-work-offset 0,0,-200 -o no.h u.mpf
    run 0 translate --from ac-trunnion --to dmu-50v --source-work-offset 0,0,-200 --source-tool-length 100 -o u.h u.mpf
    grep -q 'added: rotary moves without tool-tip tracking cut into pieces' err || { report "no count of added blocks"; show err; }
    sed -n 2,3p u.h | grep -q 'M128' || { report "TCP not switched on in the first motion"; show u.h; }
    words u.h >w
    # has X Y Z [B] [F]: a written motion with these values (positions to 0.001, B to 0.001).
    has() {
      awk -v x="$1" -v y="$2" -v z="$3" -v b="${4:-}" -v f="${5:-}" '
        function v(n,   i) { for (i = 1; i <= NF; ++i) if (index($i, n "=") == 1) return substr($i, length(n) + 2); return "" }
        function near(a, c) { return a != "" && (a - c < 0.0011 && c - a < 0.0011) }
        near(v("X"), x) && near(v("Y"), y) && near(v("Z"), z) && (b == "" || near(v("B"), b)) &&
          (f == "" || v("F") == f) { found = 1 } END { exit !found }' w || { report "no block X$1 Y$2 Z$3 B${4:-} F${5:-}"; show u.h; }
    }
    has 0 0 -2 0 200 && has 40 0 -2 0 800          # 3-axis: the program point is the tip
    has -43.301 -40 25 90                            # N50 end: R_z(-90) R_x(60) (40, 0, 50); B by (K23)
    has -15.981 -10 32.321 90 500                    # N60, one block, F kept: R_z(-90) R_x(60) (10, 20, 30)
    has -15.981 -20 32.321 90                        # N70
    has 2.321 -20 35.981                             # N80 end: R_z(-90) R_x(30) (20, 20, 30)
    has 10 -48.089 142.124                           # N140: X, Y stay where TCP left the slides (10, 3.420)
    has 10 3.42 150 0                                # N150: the zero pose
    # N50's pieces: the tip turns about the origin, so every piece lies 64.031 mm from it, and
    # there are more than 2 (a 60 deg and 90 deg swing of a 64 mm radius).
    n=$(awk '/FMAX/ { x = y = z = ""; for (i = 1; i <= NF; ++i) { w = substr($i, 1, 1); v = substr($i, 2) + 0
            if (w == "X") x = v; if (w == "Y") y = v; if (w == "Z") z = v }
          r = sqrt(x * x + y * y + z * z); if (r > 64.02 && r < 64.04) ++n } END { print n + 0 }' u.h)
    [ "$n" -gt 2 ] || { report "N50 not cut into pieces on its 64.031 mm sphere ($n)"; show u.h; }
    # N80: A turns 30 deg at F1000 (deg/min): 0.03 min over an arc of 36.056 * pi / 6 = 18.879 mm,
    # so the pieces run at 629.3 mm/min (their chords a hair shorter than the arc).
    grep -c 'F629\.[23]' u.h | awk '{ exit !($1 > 2) }' || { report "N80 pieces not at F629.3"; show u.h; }
    ;;
  machine-output)
    # Output in machine coordinates (G10) on the ac-trunnion: both tables turn about lines through
    # (0, 0, -200), so with the work offset there the part point of program point p at physical
    # angles A, C is R_z(-C) R_x(-A) p (worked by hand in 'untracked'), whatever the tool length:
    # a tip held at (10, 0, 0) at A-30 while C turns 0 -> 90 is written p = R_x(-30) R_z(C)
    # (10, 0, 0), on the sphere of radius 10 about the origin, ending at (0, 8.660, -5).
    printf '%s\n' 'N10 T1 M6' 'N20 TRAORI' 'N30 G0 X10 Y0 Z0 A-30 C0' 'N40 G1 C90 F1000' 'N50 X20' 'N60 TRAFOOF' \
      'N70 M30' >m.mpf
    run 1 translate --from ac-trunnion --to ac-trunnion --output-mode machine -o no.mpf m.mpf
    grep -q 'output-mode machine writes .*--work-offset' err || { report "no placement accepted"; show err; }
    run 1 reverse --machine ac-trunnion --output-mode machine -o no.apt m.mpf
    grep -q 'not machine coordinates' err || { report "reverse accepted machine"; show err; }
    run 1 translate --from ac-trunnion --to ac-trunnion --output-mode joints --work-offset 0,0,-200 -o no.mpf m.mpf
    [ -e no.mpf ] && report "no.mpf written"
    [ -e no.apt ] && report "no.apt written"
    run 0 translate --from ac-trunnion --to ac-trunnion --output-mode machine --work-offset 0,0,-200 \
      --tool-length 50 -o m.out m.mpf
    grep -q 'TRAORI\|TRAFOOF' m.out && { report "TCP words written"; show m.out; }
    grep -q 'added: ' err || { report "no count of added blocks"; show err; }
    words m.out >w
    # N40: the C pieces all on the sphere of radius 10, more than 2 of them, ending at (0, 8.660, -5);
    # 90 deg at F1000 is 0.09 min, and in inverse time the pieces' 1/F add up to it (F to 0.1).
    awk '{ delete v; for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
           r = sqrt(v["X"] ^ 2 + v["Y"] ^ 2 + v["Z"] ^ 2)
           if (v["C"] > 0 && r < 15) { if (r < 9.999 || r > 10.001) bad = 1; ++n; t += 1 / v["F"] } }
         END { exit !(n > 2 && !bad && t > 0.0899 && t < 0.0901) }' w ||
      { report "N40 pieces not on the sphere of radius 10 or not 0.09 min"; show m.out; }
    grep -q 'G93' m.out || { report "N40 not in inverse time"; show m.out; }
    line=$(line_with m.out C 90)
    near "$(value "$line" X)" 0 0.001 && near "$(value "$line" Y)" 8.66 0.001 && near "$(value "$line" Z)" -5 0.001 ||
      { report "N40 end not (0, 8.660, -5)"; show m.out; }
    # N50: the angles stand, so X20 is R_x(-30) R_z(90) (20, 0, 0) = (0, 17.321, -10) at F1000 again.
    grep -q 'G94' m.out || { report "no G94 after the pieces"; show m.out; }
    line=$(line_with m.out Z -10)
    near "$(value "$line" X)" 0 0.001 && near "$(value "$line" Y)" 17.321 0.001 && [ "$(value "$line" F)" = 1000 ] ||
      { report "N50 not X0 Y17.321 Z-10 F1000"; show m.out; }
    # ISO: the TCP switch becomes the tool's length compensation.
    run 0 translate --from ac-trunnion --to ac-trunnion --to-dialect iso --output-mode machine --work-offset 0,0,-200 \
      -o m.nc m.mpf
    grep -q 'N20 G43 H1$' m.nc || { report "no G43 H1 for TRAORI"; show m.nc; }
    grep -q 'G43\.4\|G49' m.nc && { report "TCP words in ISO"; show m.nc; }
    ;;
  tool-table)
    # Per-tool lengths (--tool-table): a program in machine coordinates on the ac-head (C about
    # +Z carrying A about +X, both through the pivot, pivot length 150) that changes tools. With
    # the part shifted by (0, 0, -400) on both sides, the tip of program point p at A90 C0, where the tool axis is
    # (0, -1, 0), is p + (150 + L)((0, 0, 1) - (0, -1, 0)) = p + (150 + L)(0, 1, 1) (theory.md,
    # (G8) and (G6), worked by hand): tool 1 (L 50) puts N40 at (0, 200, 200), tool 2 (L 100)
    # puts N70 at (0, 250, 250).
    printf '%s\n' 'N10 G90 G17' 'N20 T1 M6' 'N30 G0 X0 Y0 Z0 A0 C0' 'N40 G0 A90.' 'N50 G1 Z-5. F300' \
      'N60 T2 M6' 'N70 G0 X0 Y0 Z0 A90. C0' 'N80 G1 Z-5. F300' 'N90 M30' >t.nc
    printf '%s\n' '# two tools' 'kin5_tools = 1' '' '[[tool]]' 'number = 1' 'length_mm = 50' '' '[[tool]]' \
      'number = 2' 'length_mm = 100' 'radius_mm = 5' >tools.toml
    src="--from ac-head --to ac-head --from-dialect iso --to-dialect iso --source-work-offset 0,0,-400"
    run 0 translate $src --tool-table tools.toml -o t.out t.nc
    has_tip() {  # N X Y Z: the block numbered N (-N: the line before it, a cut block's end) is at X Y Z
      case $1 in -*) grep -B1 "^N${1#-} " t.out | head -n 1 ;; *) grep "^N$1 " t.out | head -n 1 ;; esac >l.nc
      l=$(words l.nc)
      near "$(value "$l" X)" "$2" 0.001 && near "$(value "$l" Y)" "$3" 0.001 && near "$(value "$l" Z)" "$4" 0.001 ||
        { report "N$1 not at ($2, $3, $4): $l"; show t.out; }
    }
    has_tip -50 0 200 200; has_tip 50 0 200 195; has_tip 70 0 250 250; has_tip 80 0 250 245
    # In machine coordinates on the same machine each tool's program points come back (the
    # target's tool 2 read with tool 1's length would write N70 at (0, 50, 50)).
    run 0 translate $src --tool-table tools.toml --output-mode machine --work-offset 0,0,-400 -o t.out t.nc
    has_tip 70 0 0 0; has_tip 80 0 0 -5
    # One length for the whole program: the second tool is refused at its first motion, nothing written.
    run 2 translate $src --source-tool-length 50 -o no.nc t.nc
    grep -q '^t\.nc:7:1: error: .*tool 2: its length is not known (--source-tool-length gives one tool.s, tool 1.s); give each tool.s length in --tool-table' err ||
      { report "second tool not refused at line 7"; show err; }
    # A tool the table lacks: refused at its first motion, naming the option.
    printf '%s\n' 'kin5_tools = 1' '[[tool]]' 'number = 1' 'length_mm = 50' >one.toml
    run 2 translate $src --tool-table one.toml -o no.nc t.nc
    grep -q '^t\.nc:7:1: error: .*tool 2 has no entry in the tool table.*--tool-table' err || { report "tool 2 not refused"; show err; }
    # Mistakes in the table: FILE:LINE:COL naming the key, exit 2, nothing written.
    printf '%s\n' 'kin5_tools = 1' '[[tool]]' 'number = 1' 'length_mm = 50' 'lenght_mm = 5' >bad.toml
    run 2 translate $src --tool-table bad.toml -o no.nc t.nc
    grep -q "^bad\.toml:5:1: error: unknown key 'lenght_mm' in \[\[tool\]\] #1" err || { report "unknown key"; show err; }
    printf '%s\n' 'kin5_tools = 1' '[[tool]]' 'number = 1' 'length_mm = 50' '[[tool]]' 'number = 1' 'length_mm = 60' >bad.toml
    run 2 translate $src --tool-table bad.toml -o no.nc t.nc
    grep -q '^bad\.toml:6:10: error: \[\[tool\]\] #2 number 1 is given twice' err || { report "number twice"; show err; }
    printf '%s\n' 'kin5_tools = 1' '[[tool]]' 'number = 1' 'length_mm = -50' >bad.toml
    run 2 translate $src --tool-table bad.toml -o no.nc t.nc
    grep -q '^bad\.toml:4:13: error: \[\[tool\]\] #1 length_mm must be 0 or more' err || { report "negative length"; show err; }
    printf '%s\n' 'kin5_tools = 1' '[[tool]]' 'length_mm = 50' >bad.toml
    run 2 translate $src --tool-table bad.toml -o no.nc t.nc
    grep -q "^bad\.toml:2:1: error: missing key 'number' in \[\[tool\]\] #1" err || { report "missing number"; show err; }
    run 2 translate $src --tool-table missing.toml -o no.nc t.nc
    grep -q '^missing\.toml:1:1: error: cannot read the tool-table file: No such file or directory' err || { report "missing file"; show err; }
    [ -e no.nc ] && report "no.nc written"
    # The table is for motion in machine coordinates: without a work offset it is a usage error.
    run 1 translate --from ac-head --to ac-head --tool-table tools.toml -o no.nc t.nc
    grep -q 'tool-table gives tool lengths .*--source-work-offset or --work-offset' err || { report "table alone accepted"; show err; }
    ;;
  tcp-word)
    # --tcp-word chooses Heidenhain's TCP switch (docs/dialects/heidenhain.md): FUNCTION TCPM on a
    # block of its own before the moves, FUNCTION RESET TCPM before the tool call and after it
    # again; M128/M129 by default. Another output dialect has no choice: a usage error.
    printf '%s\n' 'G90 G94 G21' 'T1 M6' 'S8000 M3' 'G43.4 H1' 'G1 X10. Y0 Z20. A-10. C20. F1000' 'T1 M6' \
      'G1 X12. Y0 Z20. A-12. C20.' 'G49' 'M30' >w.nc
    pair="--from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect heidenhain"
    run 0 translate $pair --tcp-word function-tcpm -o w.h w.nc
    grep -q 'M12[89]' w.h && { report "M128/M129 with function-tcpm"; show w.h; }
    awk '/FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS/ { on = 1 } /FUNCTION RESET TCPM/ { on = 0 }
         /TOOL CALL [0-9]/ && on { bad = 1 } / L X\+10 / && !on { bad = 1 } / L X\+12 / && !on { bad = 1 }
         END { exit bad }' w.h || { report "tracking not on around the moves, or on at a tool call"; show w.h; }
    [ "$(grep -c 'FUNCTION RESET TCPM' w.h)" = 2 ] || { report "FUNCTION RESET TCPM not twice"; show w.h; }
    run 0 translate $pair -o m.h w.nc
    grep -q 'TCPM' m.h && { report "FUNCTION TCPM by default"; show m.h; }
    grep -q 'M128' m.h || { report "M128 not written by default"; show m.h; }
    run 1 translate --from ac-trunnion --to ac-trunnion --from-dialect iso --to-dialect iso --tcp-word m128 -o no.nc w.nc
    grep -q -- '--tcp-word chooses Heidenhain' err || { report "--tcp-word into iso accepted"; show err; }
    [ -e no.nc ] && report "no.nc written"
    ;;
  include-dir)
    # A program that calls another file (M98 P1000, docs/user-guide.md "Programs that call other
    # files"): with --include-dir the called moves are executed into the output, the file found
    # whatever the case of its name; without, exit 2 naming the files it would need.
    mkdir sub empty
    printf '%%\nO0001\nT1 M6\nG43.4 H1\nG0 X0. Y0. Z10. A0. C0.\nM98 P1000\nG0 Z50.\nG49\nM30\n%%\n' >main.nc
    printf '%%\nO1000 (CORNER)\nG1 X11. Y12. Z1. F500.\nG1 X13.\nM99\n%%\n' >sub/o1000.nc
    pair="--from ac-trunnion --to ac-head --from-dialect iso --to-dialect iso"
    run 0 translate $pair --include-dir empty --include-dir sub -o out.nc main.nc
    words out.nc | awk '$1 == "X=11" && $2 == "Y=12" && $3 == "Z=1" { a = 1 } $1 == "X=13" { b = 1 } END { exit !(a && b) }' ||
      { report "the called moves are not in the output"; show out.nc; }
    grep -q 'M98\|M99\|O1000' out.nc && { report "the call was written, not executed"; show out.nc; }
    run 2 translate $pair -o no.nc main.nc
    grep -q '^main\.nc:6:1: error: call of O1000: .*O1000, O1000\.nc or 1000\.nc .*--include-dir' err ||
      { report "the missing file not named"; show err; }
    [ -e no.nc ] && report "no.nc written"
    # An error inside the called file names that file and its line.
    printf 'O1000\nG1 X#7\nM99\n' >sub/O1000.nc
    run 2 translate $pair --include-dir sub -o no.nc main.nc
    grep -q '^sub/O1000\.nc:2:' err || { report "the error is not at the called file's line"; show err; }
    # ... and the call it ran from, on the next line, as compilers note it.
    grep -A1 '^sub/O1000\.nc:2:5: error:' err | tail -n 1 | grep -q '^main\.nc:6:1: note: called from here$' ||
      { report "no note of the call"; show err; }
    # A subprogram of the same file called twice, 2 passes each: each error notes its call.
    printf '%%\nO0001\nT1 M6\nG43.4 H1\nG0 X0. Y0. Z10. A0. C0.\nM98 P2000\nM98 P2000\nM30\nO2000\nG1 X#7 F100.\nM99\n%%\n' >same.nc
    run 2 translate $pair --report r.json -o no.nc same.nc
    [ "$(grep -c '^same\.nc:10:5: error:' err)" = 2 ] || { report "not one error per call"; show err; }
    grep -q '^same\.nc:6:1: note: called from here$' err && grep -q '^same\.nc:7:1: note: called from here$' err ||
      { report "the calls are not noted"; show err; }
    grep -q '"called_from": \[{"file": "same.nc", "line": 7, "column": 1}\]' r.json ||
      { report "the report does not list the call"; show r.json; }
    ;;
  memory-bound)
    # A loop executes 210,000 lines into 140,000 blocks: with 64 KiB of memory for them (the
    # rest in a temporary file), the output is the same as with the default 256 MiB.
    printf '%%\nO0001\nT1 M6\nG43.4 H1\nG0 X0. Y0. Z10. A0. C0.\n#1=0\nWHILE [#1 LT 70000] DO1\nG1 X[#1/1000] F500.\n#1=#1+1\nEND1\nG49\nM30\n%%\n' >loop.nc
    pair="--from ac-trunnion --to ac-head --from-dialect iso --to-dialect iso"
    run 0 translate $pair -o default.nc loop.nc
    run 0 translate $pair --max-memory-bytes 64KiB -o bounded.nc loop.nc
    [ "$(grep -c '^N[0-9]* *G1\|^G1' default.nc)" -ge 70000 ] || { report "the loop's moves are not all written"; tail -n 3 default.nc; }
    cmp -s default.nc bounded.nc || { report "a bounded store writes another program"; cmp default.nc bounded.nc; }
    run 1 translate $pair --max-memory-bytes 0 -o no.nc loop.nc  # at least one byte
    ;;
  include-dir-heidenhain)
    # CALL PGM of a program in another file (docs/dialects/heidenhain.md, "Calls of other
    # files"): found in an include directory or beside the calling program, run to its END PGM.
    mkdir sub prog
    printf '0 BEGIN PGM MAIN MM\n1 TOOL CALL 1 Z S5000\n2 L X+0 Y+0 Z+10 A+0 C+0 R0 FMAX M128\n3 CALL PGM SUB\n4 L Z+50 FMAX\n5 M129\n6 END PGM MAIN MM\n' >prog/main.h
    printf '0 BEGIN PGM SUB MM\n1 L X+11 Y+12 Z+1 R0 F500\n2 L X+13\n3 END PGM SUB MM\n' >sub/sub.h
    pair="--from ac-trunnion --to ac-head --from-dialect heidenhain --to-dialect heidenhain"
    run 0 translate $pair --include-dir sub -o out.h prog/main.h
    words out.h | awk '$1 == "X=11" && $2 == "Y=12" && $3 == "Z=1" { a = 1 } $1 == "X=13" { b = 1 } END { exit !(a && b) }' ||
      { report "the called moves are not in the output"; show out.h; }
    grep -q 'CALL PGM\|PGM SUB' out.h && { report "the call was written, not executed"; show out.h; }
    run 2 translate $pair -o no.h prog/main.h
    grep -q "^prog/main\.h:4:3: error: call of PGM SUB: SUB\.h: not in the calling program's directory .*--include-dir" err ||
      { report "the missing file not named"; show err; }
    [ -e no.h ] && report "no.h written"
    # Beside the calling program it needs no option; an error inside it names its file and line.
    printf '0 BEGIN PGM SUB MM\n1 L X+Q7 R0 F500\n2 END PGM SUB MM\n' >prog/SUB.H
    run 2 translate $pair -o no.h prog/main.h
    grep -q '^prog/SUB\.H:2:' err || { report "the error is not at the called file's line"; show err; }
    ;;
  include-dir-siemens)
    # A subprogram named alone in its block (L100 P2) runs its file L100.SPF, to M17, twice.
    mkdir sub
    printf '%%_N_MAIN_MPF\nT1 M6\nTRAORI\nG0 X0 Y0 Z10 A0 C0\nN50 L100 P2\nG0 Z50\nTRAFOOF\nM30\n' >main.mpf
    printf '%%_N_L100_SPF\nG1 X11 Y12 Z1 F500\nG1 X13\nM17\n' >sub/l100.spf
    pair="--from ac-trunnion --to ac-head --from-dialect siemens --to-dialect siemens"
    run 0 translate $pair --include-dir sub -o out.mpf main.mpf
    [ "$(words out.mpf | awk '$1 == "X=11" && $3 == "Z=1"' | wc -l)" = 2 ] && [ "$(words out.mpf | awk '$1 == "X=13" && $3 == "Z=1"' | wc -l)" = 2 ] ||
      { report "the called moves are not in the output twice"; show out.mpf; }
    grep -q 'L100\|M17\|_SPF' out.mpf && { report "the call was written, not executed"; show out.mpf; }
    run 2 translate $pair -o no.mpf main.mpf
    grep -q "^main\.mpf:5:1: error: call of subprogram L100: L100\.SPF or _N_L100_SPF: .*--include-dir" err ||
      { report "the missing file not named"; show err; }
    [ -e no.mpf ] && report "no.mpf written"
    printf 'G1 X=R7\nM17\n' >sub/L100.SPF
    run 2 translate $pair --include-dir sub -o no.mpf main.mpf
    grep -q '^sub/L100\.SPF:1:' err || { report "the error is not at the called file's line"; show err; }
    ;;
  *)
    echo "run.sh: unknown test '$name'" >&2
    exit 2
    ;;
esac
exit "$fail"
