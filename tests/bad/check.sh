#!/bin/sh
# Runs one file of the must-reject corpus through its reader and checks the rejection.
#
#   check.sh KIN5_EXE FILE
#
# FILE lives in tests/bad/<dialect>/. Its first line is a comment of that dialect (`;` for
# Siemens, Heidenhain and ISO, `$$` for APT) saying what must be reported:
#
#   ; expect: LINE:COL: MESSAGE
#
# The file is read by the `kin5` command line in kin5.args beside it (one per dialect folder:
# the command that reads the dialect and the machine its programs were written for). The run
# must exit 2, print nothing on stdout, and report exactly one error,
# `FILE:LINE:COL: error: MESSAGE`; warnings may come with it.
set -u
exe=$1 file=$2
args=$(dirname "$file")/kin5.args
if [ ! -f "$args" ]; then
  echo "FAIL: $file: no $args naming the kin5 command that reads it" >&2
  exit 1
fi
# shellcheck disable=SC2046  # one line of words, split on purpose
set -- $(cat "$args")

expect=$(head -n 1 "$file" | tr -d '\r' | sed -n 's/^[;$ ]*expect: //p')
if [ -z "$expect" ]; then
  echo "FAIL: $file: the first line does not say '; expect: LINE:COL: MESSAGE'" >&2
  exit 1
fi
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
"$exe" "$@" "$file" >"$tmp/out" 2>"$tmp/err"
code=$?
fail=0
[ "$code" = 2 ] || { echo "FAIL: $file: exit $code, expected 2 (rejected)" >&2; fail=1; }
[ -s "$tmp/out" ] && { echo "FAIL: $file: something was written to stdout" >&2; fail=1; }
grep ': error: ' "$tmp/err" >"$tmp/errors"
printf '%s\n' "$file:$expect" | sed 's/^\([^:]*:[0-9]*:[0-9]*\): /\1: error: /' >"$tmp/want"
if ! cmp -s "$tmp/errors" "$tmp/want"; then
  echo "FAIL: $file: expected exactly this error:" >&2
  cat "$tmp/want" >&2
  fail=1
fi
if [ "$fail" != 0 ]; then
  echo "--- stderr of kin5 $*" >&2
  cat "$tmp/err" >&2
fi
exit "$fail"
