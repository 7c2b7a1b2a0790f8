#!/bin/sh
# The JSON account of a run (`--report FILE`, translate/run_report.hpp), on translate, reverse
# and post, when the run succeeds and when it fails.
#
#   report.sh KIN5_EXE EXAMPLES_DIR TEST_NAME
#
# Each report is parsed back with Python's json module (strict: no invalid string, no bare NaN),
# then its fields are checked against what the program is known to hold: counts worked out by
# hand from the program the test writes, never taken from kin5's own output.
set -u

. "$(cd "$(dirname "$0")" && pwd)/harness.sh"

example="$examples/table1-sajo.mpf"
translate="translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1"  # the example's G54: preset 1

# check FILE PYTHON: parses FILE as JSON into d, then runs PYTHON (asserts); reports what failed.
check() {
  python3 - "$1" "$2" 2>check.err <<'EOF' || { report "report $1: $(tail -n 1 check.err)"; show err; }
import json, sys
def no_constant(c):
    raise ValueError("not JSON: " + c)
with open(sys.argv[1], encoding="utf-8") as f:
    d = json.load(f, parse_constant=no_constant)
b = d["blocks"]
assert b["read"] == b["translated"] + b["comment_only"] + b["refused"], "read != translated + comment only + refused"
exec(sys.argv[2])
EOF
}

case "$name" in
  success)
    # The example: 23 blocks, 6 moves, 5 blocks of comments only (kin5 writes them all).
    run 0 $translate -o t.h --report r.json "$example"
    check r.json '
assert d["kin5_report"] == 1 and d["command"] == "translate"
assert d["exit_code"] == 0 and d["written"] is True
assert d["input"]["file"].endswith("table1-sajo.mpf") and d["input"]["dialect"] == "siemens"
assert d["input"]["machine"] == "sajo-12000p"
assert d["output"] == {"file": "t.h", "dialect": "heidenhain", "machine": "dmu-80p"}
assert b == {"read": 23, "translated": 18, "comment_only": 5, "refused": 0, "written": 23, "added": 0}, b
assert d["motion_blocks"] == {"direct": 6, "other_branch": 0, "unreachable": 0}
assert d["error_count"] == 0 and d["errors"] == [] and d["unreachable"] == []'
    [ -s t.h ] || report "t.h not written"
    ;;
  unreachable)
    # A > 0 cannot be reached on the DMU 80P, by a gap of A (docs/matchability.md): three runs,
    # 20,000 blocks with a comment inside (worst A24 at line 23), 2 blocks, 1 block.
    {
      printf '%s\n' 'N10 G17 G90 G94' 'N20 TRAORI' 'G1 X0 Y0 Z50 A-45 B30 F1000'
      awk 'BEGIN { for (i = 0; i < 20000; ++i) { if (i == 10000) print "; midway"; printf "G1 X%d Y0 Z50 A%d B30\n", i % 100, 5 + i % 20 } }'
      printf '%s\n' 'G1 X1 Y0 Z50 A-30 B30' 'G1 X2 Y0 Z50 A7 B30' 'G1 X3 Y0 Z50 A8 B30' 'G1 X4 Y0 Z50 A-30 B30' \
        'G1 X5 Y0 Z50 A9 B30' 'N90 TRAFOOF' 'N100 M30'
    } >runs.mpf
    run 3 translate --from sajo-12000p --to dmu-80p -o runs.h --report r.json runs.mpf
    check r.json '
assert d["exit_code"] == 3 and d["written"] is False
assert b == {"read": 20011, "translated": 7, "comment_only": 1, "refused": 20003, "written": 0, "added": 0}, b
assert d["motion_blocks"] == {"direct": 3, "other_branch": 0, "unreachable": 20003}
assert d["error_count"] == 20003 and d["errors"] == [], d["error_count"]
got = [(u["first_line"], u["last_line"], u["blocks"], u["worst_line"], u["worst_gap_deg"]) for u in d["unreachable"]]
assert got == [(4, 20004, 20000, 23, 24), (20006, 20007, 2, 20007, 8), (20009, 20009, 1, 20009, 9)], got
assert d["unreachable"][0]["worst_reason"] == "tool axis 24.000\u00b0 outside the reach of dmu-80p"'
    [ -e runs.h ] && report "runs.h created on failure"
    ;;
  reader-errors)
    # 1,500 lines with an unknown word (a reader keeps 1,000 errors and counts the rest), the last
    # with two (Q, and a quote, a backslash and a byte that is not UTF-8 in the word quoted).
    {
      printf 'N10 TRAORI\n'
      awk 'BEGIN { for (i = 0; i < 1499; ++i) print "N20 G1 X1 YY2" }'
      printf 'N25 G1 X1 Q"\\\3772\n; a comment\nN30 M30\n'
    } >bad.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o bad.h --report r.json bad.mpf
    check r.json '
assert d["exit_code"] == 2 and d["written"] is False
assert b == {"read": 1503, "translated": 2, "comment_only": 1, "refused": 1500, "written": 0, "added": 0}, b
assert d["error_count"] == 1501 and d["errors_not_listed"] == 501 and len(d["errors"]) == 1000, d["error_count"]
e = d["errors"][0]
assert e == {"file": "bad.mpf", "line": 2, "column": 11, "construct": None, "reason": "unknown word '"'"'YY2'"'"'", "option": None,
             "called_from": []}, e'
    # The last line is beyond the 1,000 kept: read it alone for the quoting.
    tail -n 3 bad.mpf >q.mpf
    run 2 translate --from sajo-12000p --to dmu-80p -o q.h --report q.json q.mpf
    check q.json '
r = [e["reason"] for e in d["errors"]]
assert any("\"\\\ufffd2" in x for x in r), r'
    ;;
  source-errors)
    # A program for a B/C machine given as the DMU 80P: two A words the source lacks (refused at
    # the word, with the option that resolves them), a rotary move without TCP, a comment.
    printf '%s\n' 'BEGIN PGM T MM' 'L X+1 Y+2 Z+3 A+10 B+0 C+0 F100' 'L X+1 Y+2 Z+4 B+0 C+0' '; c' \
      'L X+1 Y+2 Z+5 A+3 B+0 C+0' 'END PGM T MM' >t.h
    run 2 translate --from dmu-80p --to sajo-12000p -o t.mpf --report r.json t.h
    check r.json '
assert b == {"read": 6, "translated": 2, "comment_only": 1, "refused": 3, "written": 0, "added": 0}, b
got = [(e["line"], e["column"], e["construct"], e["option"]) for e in d["errors"]]
assert got == [(2, 15, "A+10", "--from"), (3, 1, None, None), (5, 15, "A+3", "--from")], got
assert "dmu-80p has no A axis" in d["errors"][0]["reason"]'
    ;;
  many-errors)
    # 2,500 blocks refused by a source check (an A word on a B/C machine): the first 1,000 errors
    # in source order are listed, the rest counted, beyond the 2,000 the translation holds too;
    # every block is counted as refused.
    { printf 'BEGIN PGM T MM\nM128\n'; awk 'BEGIN { for (i = 0; i < 2500; ++i) print "L X+1 Y+2 Z+3 A+10 B+0 C+0 F100" }'
      printf 'END PGM T MM\n'; } >t.h
    run 2 translate --from dmu-80p --to sajo-12000p -o t.mpf --report r.json t.h
    check r.json '
assert b["read"] == 2503 and b["refused"] == 2500, b
assert d["error_count"] == 2500 and d["errors_not_listed"] == 1500 and len(d["errors"]) == 1000, d["error_count"]
assert [e["line"] for e in d["errors"]] == list(range(3, 1003))'
    ;;
  output-refused)
    # OUT is a directory: nothing read, the report says why (an error about the file OUT).
    mkdir d
    run 2 $translate -o d --report r.json "$example"
    check r.json '
assert d["exit_code"] == 2 and b["read"] == 0 and d["error_count"] == 1
e = d["errors"][0]
assert e["file"] == "d" and e["line"] == 0 and "is a directory" in e["reason"], e'
    ;;
  report-refused)
    # The report may not be OUT, nor stdout beside OUT on stdout (bad arguments); a directory is
    # refused. Nothing is written then, OUT included.
    run 1 $translate -o t.h --report t.h "$example"
    [ -e t.h ] && report "t.h written when --report names it"
    run 1 $translate --report - "$example"
    [ -s out ] && report "stdout written with --report - and OUT -"
    mkdir d
    run 2 $translate -o t.h --report d "$example"
    grep -q "cannot write 'd': is a directory" err || { report "no directory message"; show err; }
    [ -e t.h ] && report "t.h written when the report cannot be"
    ;;
  stdout)
    # --report - writes the JSON to stdout.
    run 0 $translate -o t.h --report - "$example"
    check out 'assert d["written"] is True and b["written"] == 23'
    ;;
  reverse-post)
    # reverse names no target machine, post no source machine; both count every block.
    run 0 reverse --machine sajo-12000p --work-offset-map G54= -o r.apt --report r.json "$example"
    check r.json '
assert d["command"] == "reverse" and d["output"] == {"file": "r.apt", "dialect": "apt", "machine": None}
assert d["input"]["machine"] == "sajo-12000p" and b["read"] == 23 and b["refused"] == 0'
    run 0 post --machine dmu-80p -o p.h --report p.json r.apt
    check p.json '
assert d["command"] == "post" and d["input"] == {"file": "r.apt", "dialect": "apt", "machine": None}
assert d["output"]["machine"] == "dmu-80p" and d["exit_code"] == 0 and b["refused"] == 0'
    ;;
  *)
    echo "report.sh: unknown test '$name'" >&2
    exit 2
    ;;
esac
exit "$fail"
