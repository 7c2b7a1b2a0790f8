# shellcheck shell=sh
# Sourced by the benchmark scripts (POSIX sh): `quietly LOG WHAT COMMAND...` runs COMMAND with
# its output in the file LOG; if it fails, prints the last 40 lines of LOG and says what failed
# and where the whole log is, then exits 1.
quietly() {
  quietly_log=$1 quietly_what=$2
  shift 2
  mkdir -p "$(dirname "$quietly_log")"
  if ! "$@" >"$quietly_log" 2>&1; then
    tail -n 40 "$quietly_log" >&2
    echo "$0: $quietly_what failed; the last 40 lines of its output are above, all of it is in $quietly_log" >&2
    exit 1
  fi
}
