#!/bin/sh
# End-to-end checks of `kin5 match`: the pair's table in each format, a program's report, and
# the setup search — the printed `kin5 translate --setup-rotation … [--setup-offset …]` must
# translate the program that does not translate with the pair's default setup.
#   cli.sh KIN5 DIR     (DIR holds side.mpf and flank.mpf)
set -u
kin5=$1 dir=$2
out=$(mktemp -d) || exit 2
trap 'rm -rf "$out"' EXIT
fail=0
report() { echo "FAIL: $*" >&2; fail=1; }
run() {  # run EXPECTED_EXIT NAME ARGS...: stdout to $out/NAME
  want=$1 name=$2; shift 2
  "$kin5" "$@" >"$out/$name" 2>"$out/$name.err"
  got=$?
  [ "$got" = "$want" ] || { report "$name: exit $got, expected $want"; cat "$out/$name.err" >&2; }
}
has() {  # has NAME TEXT: stdout of NAME holds the line fragment TEXT
  grep -qF -- "$2" "$out/$1" || report "$1: no line with: $2"
}

# The pair's table (Tian et al. 2010 §1.1, worked in docs/matchability.md).
run 0 md match --from sajo-12000p --to dmu-80p
has md "| every | [-90.000, 0.000] | [-120.000, -90.000) | (0.000, 30.000] | 30.000 |"
run 0 csv match --from sajo-12000p --to dmu-80p --format csv
has csv "sajo-12000p,dmu-80p,every,0.000000,30.000000,no,yes,unreachable,30.000000"
run 0 json match --from sajo-12000p --to dmu-80p --format json
has json '"rows_independent": true'
run 0 svg match --from sajo-12000p --to dmu-80p --format svg
has svg '<svg xmlns="http://www.w3.org/2000/svg"'
# Machine files (machines/*.toml) give the same table as the bundled machines they describe.
run 0 csv_files match --from-file "$dir/../../machines/sajo-12000p.toml" --to-file "$dir/../../machines/dmu-80p.toml" --format csv
cmp -s "$out/csv" "$out/csv_files" || report "csv_files: differs from the table of the bundled machines"
run 1 unknown match --from sajo-12000p --to no-such-machine
grep -q "unknown machine 'no-such-machine'" "$out/unknown.err" || report "unknown: no message"

# --from-dialect takes the NC dialects of the list (an ISO program here), not CL data.
printf '%%\nO0001\nG90 G17\nG43.4 H1\nG1 X0 Y0 Z50. A-45. B30. F1000\nG1 X10. A5.\nG49\nM30\n%%\n' >"$out/wall.nc"
run 3 iso match --from sajo-12000p --to dmu-80p --program "$out/wall.nc" --from-dialect iso
has iso "| 6 | 1 | 5.000 |"
run 1 apt match --from sajo-12000p --to dmu-80p --program "$out/wall.nc" --from-dialect apt

# A program with blocks no setup can save: their tool axes fit in no hemisphere.
run 3 side match --from sajo-12000p --to dmu-80p --program "$dir/side.mpf"
has side "| direct | 2 |"
has side "| other branch | 1 |"
has side "| unreachable | 3 |"
has side "| 6 | 1 | 5.000 |"
has side "| 8 | 1 | 10.000 |"
has side "| 10 | 1 | 20.000 |"
has side "No rotation reaches every block"
run 3 side_csv match --from sajo-12000p --to dmu-80p --program "$dir/side.mpf" --format csv
has side_csv "$dir/side.mpf,8,8,1,10.000000"

# A program a re-fixturing saves: the printed command must translate it, the default must not.
run 3 flank match --from sajo-12000p --to dmu-80p --program "$dir/flank.mpf"
has flank "| 8–12 | 5 | 25.000 |"
rotation=$(sed -n 's/^kin5 translate .*--setup-rotation \([^ ]*\) .*/\1/p' "$out/flank")
[ -n "$rotation" ] || report "flank: no --setup-rotation printed"
run 3 default translate --from sajo-12000p --to dmu-80p -o "$out/default.h" "$dir/flank.mpf"
run 0 refixtured translate --from sajo-12000p --to dmu-80p --setup-rotation "$rotation" -o "$out/flank.h" "$dir/flank.mpf"
[ -s "$out/flank.h" ] || report "refixtured: nothing written"

# The same program selecting G54: into Heidenhain it needs --work-offset-map, in the setup
# search's trial translations too, and the printed command repeats the map.
sed 's/^N10 G90 G17$/N10 G90 G17 G54/' "$dir/flank.mpf" >"$out/flank54.mpf"
run 3 flank54 match --from sajo-12000p --to dmu-80p --work-offset-map G54=1 --program "$out/flank54.mpf"
grep -q '^kin5 translate .*--setup-rotation [^ ]* --work-offset-map G54=1 ' "$out/flank54" || report "flank54: map not in the printed command"
rotation54=$(sed -n 's/^kin5 translate .*--setup-rotation \([^ ]*\) .*/\1/p' "$out/flank54")
[ "$rotation54" = "$rotation" ] || report "flank54: another setup ($rotation54) than without G54 ($rotation)"
run 0 refixtured54 translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1 --setup-rotation "$rotation54" -o "$out/flank54.h" "$out/flank54.mpf"
run 1 badmap match --from sajo-12000p --to dmu-80p --work-offset-map G54 --program "$out/flank54.mpf"
grep -q "7 direct, 0 other-branch, 0 unreachable" "$out/refixtured.err" || report "refixtured: not every block direct"

# The same program calling its tool by name, into LinuxCNC (numbers only): refused without
# --tool-map; with it, the setup search's translations take the number, the printed command
# repeats the map and translates the program.
sed 's/^N10 G90 G17$/N10 G90 G17\nN11 T="MILL_D10" M6/' "$dir/flank.mpf" >"$out/flank_named.mpf"
run 3 named match --from sajo-12000p --to xyzac-trt --program "$out/flank_named.mpf"
has named "1 other errors stop a translation"
run 3 named_mapped match --from sajo-12000p --to xyzac-trt --tool-map MILL_D10=3 --program "$out/flank_named.mpf"
grep -q "other errors stop" "$out/named_mapped" && report "named_mapped: the mapped tool still stops it"
rotation_named=$(sed -n 's/^kin5 translate .*--setup-rotation \([^ ]*\) --tool-map MILL_D10=3 .*/\1/p' "$out/named_mapped")
[ -n "$rotation_named" ] || report "named_mapped: no command with --tool-map printed"
run 0 named_translated translate --from sajo-12000p --to xyzac-trt --setup-rotation "$rotation_named" --tool-map MILL_D10=3 \
  -o "$out/flank_named.ngc" "$out/flank_named.mpf"
grep -q '^N11 T3 M6$' "$out/flank_named.ngc" || report "named_translated: no T3 M6"
run 1 badtoolmap match --from sajo-12000p --to xyzac-trt --tool-map MILL_D10 --program "$out/flank_named.mpf"

# The slides (G7) against the DMU 80P's linear travel: a workpiece frame 2 m above the machine's
# origin puts Z beyond its [-600, 0] mm, and the setup search moves the part down.
run 3 flank_placed match --from sajo-12000p --to dmu-80p --program "$dir/flank.mpf" --tool-length 100 --work-offset 0,0,-300
has flank_placed "Linear travel on dmu-80p"
has flank_placed "tool length 100.000 mm, work offset (0.000, 0.000, -300.000) mm"
grep -q "exceeded" "$out/flank_placed" && report "flank_placed: a slide beyond its travel"
run 3 flank_high match --from sajo-12000p --to dmu-80p --program "$dir/flank.mpf" --work-offset 0,0,2000
has flank_high "[-600.000, 0.000] exceeded"
has flank_high "the part moved by (0.000, 0.000, -"

# With the part's place given, the setup search moves the part too: the printed command, setup
# offset included, must translate with the slides checked; the same rotation where the part sat
# leaves Z past its travel.
run 3 flank_moved match --from sajo-12000p --to dmu-80p --program "$dir/flank.mpf" --tool-length 100 --work-offset 0,0,2000
has flank_moved "the least move that keeps every slide 0.01 mm within its travel"
command=$(grep '^kin5 translate .* --setup-offset ' "$out/flank_moved")
[ -n "$command" ] || report "flank_moved: no --setup-offset printed"
set -- $command
shift 2  # kin5 translate
run 0 moved translate -o "$out/moved.h" "$@"
grep -q "7 direct, 0 other-branch, 0 unreachable" "$out/moved.err" || report "moved: not every block direct"
moved_rotation=$(echo "$command" | sed -n 's/.*--setup-rotation \([^ ]*\) .*/\1/p')
run 3 unmoved translate --from sajo-12000p --to dmu-80p --setup-rotation "$moved_rotation" --tool-length 100 --work-offset 0,0,2000 -o "$out/unmoved.h" "$dir/flank.mpf"
grep -q "past its travel" "$out/unmoved.err" || report "unmoved: no slide past its travel"

# A wall 3 m long: every block reachable, but no turn or place of the part fits it in the
# DMU 80P's 800 x 700 x 600 mm travel.
printf 'N10 G90 G17\nN20 TRAORI\nN30 G1 X0 Y0 Z50 A-45 B30 F1000\nN40 G1 X3000 A-30\nN50 TRAFOOF\nN60 M30\n' >"$out/long.mpf"
run 3 long match --from sajo-12000p --to dmu-80p --program "$out/long.mpf" --work-offset 0,0,-300
has long "| unreachable | 0 |"
has long "no place of the part on the table keeps every slide within its travel"

[ "$fail" = 0 ] && echo "kin5 match: all checks passed"
exit "$fail"
