# Sourced by run.sh, reliability.sh and silent.sh, which are called as `SCRIPT KIN5_EXE EXAMPLES_DIR
# TEST_NAME`: sets exe, examples and name from those, moves into a fresh directory removed on
# exit, and defines the helpers the tests share. Set KIN5_RUN_ENV before sourcing to run the tool
# under `env $KIN5_RUN_ENV` (reliability.sh: --default-signal).
exe=$1 examples=$2 name=$3
dir=$(mktemp -d) || exit 2
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 2

fail=0
# report MESSAGE...: marks the test failed, saying why.
report() { echo "FAIL [$name]: $*" >&2; fail=1; }
# show FILE...: prints each file to stderr under its name.
show() { for f in "$@"; do echo "--- $f" >&2; cat "$f" >&2; done; }

# run EXPECTED_EXIT ARGS...: runs kin5 with stdout to out, stderr to err; reports another exit.
run() {
  want=$1; shift
  # shellcheck disable=SC2086
  if [ -n "${KIN5_RUN_ENV:-}" ]; then env $KIN5_RUN_ENV "$exe" "$@" >out 2>err; else "$exe" "$@" >out 2>err; fi
  got=$?
  [ "$got" = "$want" ] || { report "exit $got, expected $want: kin5 $*"; show err; }
}
