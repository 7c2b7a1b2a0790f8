#!/bin/sh
# Runs the kin5 tool once and checks its exit code, stdout and stderr.
#
#   check.sh --exe PATH --exit N [--stdout LINES | --empty-stdout] [--tol T] [--stdout-regex ERE]
#            [--stderr-regex ERE] [--stdout-line-count N] -- ARGS...
#
# --stdout LINES   expected stdout, lines separated by '|' (--empty-stdout: none at all).
#                  Lines may come in any order. Within a line, tokens are separated by blanks
#                  and '='; numeric tokens are compared with absolute tolerance --tol (default
#                  1e-9), others exactly.
# --stdout-regex / --stderr-regex   an extended regular expression that must match some line.
set -u

exe="" want_exit="" want_stdout="" have_stdout=0 tol="1e-9" out_re="" err_re="" want_lines=""
while [ $# -gt 0 ]; do
  case "$1" in
    --exe) exe=$2; shift 2 ;;
    --exit) want_exit=$2; shift 2 ;;
    --stdout) want_stdout=$2; have_stdout=1; shift 2 ;;
    --empty-stdout) want_stdout=""; have_stdout=1; shift ;;
    --tol) tol=$2; shift 2 ;;
    --stdout-regex) out_re=$2; shift 2 ;;
    --stderr-regex) err_re=$2; shift 2 ;;
    --stdout-line-count) want_lines=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "check.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
[ -n "$exe" ] && [ -n "$want_exit" ] || { echo "check.sh: --exe and --exit are required" >&2; exit 2; }

dir=$(mktemp -d) || exit 2
trap 'rm -rf "$dir"' EXIT
"$exe" "$@" >"$dir/out" 2>"$dir/err"
got_exit=$?

fail=0
report() { echo "FAIL: $*" >&2; fail=1; }

[ "$got_exit" = "$want_exit" ] || report "exit code $got_exit, expected $want_exit"

if [ "$have_stdout" = 1 ]; then
  if ! awk -v want="$want_stdout" -v tol="$tol" '
    function isnum(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
    function same(a, b,   ta, tb, na, nb, k, d) {
      na = split(a, ta, /[ \t=]+/); nb = split(b, tb, /[ \t=]+/)
      if (na != nb) return 0
      for (k = 1; k <= na; ++k) {
        if (isnum(ta[k]) && isnum(tb[k])) { d = ta[k] - tb[k]; if (d < 0) d = -d; if (d > tol) return 0 }
        else if (ta[k] != tb[k]) return 0
      }
      return 1
    }
    { got[++n] = $0 }
    END {
      m = (want == "") ? 0 : split(want, exp_lines, "|")
      if (m != n) { printf "stdout has %d lines, expected %d\n", n, m > "/dev/stderr"; exit 1 }
      for (e = 1; e <= m; ++e) {
        found = 0
        for (g = 1; g <= n; ++g) if (!used[g] && same(got[g], exp_lines[e])) { used[g] = 1; found = 1; break }
        if (!found) { printf "no stdout line matches \"%s\"\n", exp_lines[e] > "/dev/stderr"; exit 1 }
      }
    }' "$dir/out"; then
    report "stdout differs (tolerance $tol)"
  fi
fi
if [ -n "$want_lines" ]; then
  got_lines=$(wc -l <"$dir/out" | tr -d ' ')
  [ "$got_lines" = "$want_lines" ] || report "stdout has $got_lines lines, expected $want_lines"
fi
if [ -n "$out_re" ] && ! grep -Eq -- "$out_re" "$dir/out"; then report "stdout does not match /$out_re/"; fi
if [ -n "$err_re" ] && ! grep -Eq -- "$err_re" "$dir/err"; then report "stderr does not match /$err_re/"; fi

if [ "$fail" != 0 ]; then
  echo "command: $exe $*" >&2
  echo "--- stdout" >&2; cat "$dir/out" >&2
  echo "--- stderr" >&2; cat "$dir/err" >&2
  exit 1
fi
exit 0
