#!/bin/sh
# End-to-end tests of how the program commands write OUT (tools/kin5/output_file.hpp).
#
#   output_file.sh KIN5_EXE EXAMPLES_DIR TEST_NAME
#
# Each test runs the built tool in a fresh directory with OUT of one kind (regular file,
# symbolic link, hard link, read-only file, FIFO, character device, stdout) or under one kind
# of interruption (a signal, a file-size limit, a closed pipe), and checks the exit code, the
# message, what OUT holds afterwards, and that no temporary file is left. Signals are reset to
# their default action for the tool (`env --default-signal`), so that a tool which relies on
# inheriting them ignored is caught.
set -u

exe=$1 examples=$2 name=$3
dir=$(mktemp -d) || exit 2
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 2

fail=0
report() { echo "FAIL [$name]: $*" >&2; fail=1; }
show() { for f in "$@"; do echo "--- $f" >&2; cat "$f" >&2; done; }
example="$examples/table1-sajo.mpf"
translate="translate --from sajo-12000p --to dmu-80p"

# run EXPECTED_EXIT ARGS...: runs kin5 with every signal at its default action.
run() {
  want=$1; shift
  env --default-signal "$exe" "$@" >out 2>err
  got=$?
  [ "$got" = "$want" ] || { report "exit $got, expected $want: kin5 $*"; show err; }
}

# no_temporary: no temporary file of kin5's is left in the directory.
no_temporary() { [ "$(ls -A | grep -c 'kin5-')" = 0 ] || report "temporary files left: $(ls -A | grep 'kin5-')"; }

# big FILE LINES: a program of LINES motion blocks (about 50 bytes of output each).
big() {
  awk -v n="$2" 'BEGIN { print "N1 TRAORI"
    for (i = 0; i < n; ++i) printf "N%d G1 X%.3f Y%.3f Z50 A-%.3f B%.3f F1000\n", i + 2, i % 100, i % 77, 30 + i % 20, 10 + i % 15
    print "N9 TRAFOOF"; print "M30" }' >"$1"
}

# The 23-line example translates to a program whose first line is this.
first_line='0 BEGIN PGM TABLE1_SAJO MM'

case "$name" in
  symlink)
    # A symbolic link is written through: the link stays a link, the file it names is replaced.
    echo old >real.h
    ln -s real.h link.h
    run 0 $translate -o link.h "$example"
    [ -L link.h ] || report "link.h is no longer a symbolic link"
    [ "$(head -n 1 real.h)" = "$first_line" ] || report "real.h not written through the link"
    # A dangling link: the file it names is created.
    ln -s made.h dangling.h
    run 0 $translate -o dangling.h "$example"
    [ -L dangling.h ] || report "dangling.h is no longer a symbolic link"
    [ "$(head -n 1 made.h 2>/dev/null)" = "$first_line" ] || report "made.h not created through the link"
    no_temporary
    ;;
  hard-link)
    # A file with two names is refused: a rename would leave the other name on the old program.
    echo old >a.h
    ln a.h b.h
    run 2 $translate -o a.h "$example"
    grep -q "cannot write 'a.h': has 2 hard links" err || { report "no hard-link message"; show err; }
    [ "$(cat a.h)" = old ] && [ "$(cat b.h)" = old ] || report "a linked name changed"
    [ "$(stat -c %h a.h)" = 2 ] || report "the hard link was broken"
    no_temporary
    ;;
  read-only)
    # A file with no write bit is refused, even for root, and left as it was.
    echo old >ro.h
    chmod 444 ro.h
    run 2 $translate -o ro.h "$example"
    grep -q "cannot write 'ro.h': is read-only" err || { report "no read-only message"; show err; }
    [ "$(cat ro.h)" = old ] || report "ro.h changed"
    [ "$(stat -c %a ro.h)" = 444 ] || report "ro.h mode changed"
    no_temporary
    ;;
  directory)
    mkdir d
    run 2 $translate -o d "$example"
    grep -q "cannot write 'd': is a directory" err || { report "no directory message"; show err; }
    [ -d d ] || report "d replaced"
    ;;
  fifo)
    # A FIFO gets the program once the run has succeeded, and stays a FIFO.
    mkfifo pipe.h
    timeout 20 cat pipe.h >got &
    reader=$!
    run 0 $translate -o pipe.h "$example"
    wait $reader
    [ -p pipe.h ] || report "pipe.h is no longer a FIFO"
    [ "$(head -n 1 got)" = "$first_line" ] || report "the FIFO's reader did not get the program"
    # A failed run never opens it: its reader sees only the end we give it here.
    printf 'N10 TRAORI\nN20 G91 X1\n' >bad.mpf
    timeout 20 cat pipe.h >got2 &
    reader=$!
    run 2 $translate -o pipe.h bad.mpf
    [ -p pipe.h ] || report "pipe.h is no longer a FIFO after a failed run"
    : >pipe.h
    wait $reader
    [ -s got2 ] && report "a failed run wrote to the FIFO"
    no_temporary
    ;;
  device)
    # A character device is written, not replaced: a null and a full device, made here with
    # mknod where that is allowed (as root: never /dev's own, which a faulty tool run as root
    # would replace), else /dev/null, which this user cannot replace anyway.
    if mknod null c 1 3 2>/dev/null && mknod full c 1 7 2>/dev/null; then
      run 0 $translate -o null "$example"
      [ -c null ] || report "null was replaced"
      run 2 $translate -o full "$example"
      [ -c full ] || report "full was replaced"
      grep -q "cannot write 'full': No space left on device" err || { report "no ENOSPC message"; show err; }
    else
      run 0 $translate -o /dev/null "$example"
    fi
    no_temporary
    ;;
  stdout)
    # '-' and stdout: nothing from a failed run, the whole program from a good one.
    printf 'N10 TRAORI\nN20 G91 X1\n' >bad.mpf
    run 2 $translate -o - bad.mpf
    [ -s out ] && report "a failed run wrote to stdout"
    run 0 $translate "$example"
    [ "$(head -n 1 out)" = "$first_line" ] || report "stdout did not get the program"
    ;;
  closed-pipe)
    # The reader of stdout goes away early: exit 2 with a message, not death by SIGPIPE.
    big big.mpf 40000
    { env --default-signal "$exe" $translate big.mpf 2>err; echo $? >rc; } | head -c 10 >/dev/null
    [ "$(cat rc)" = 2 ] || { report "exit $(cat rc), expected 2"; show err; }
    grep -q "cannot write '-': Broken pipe" err || { report "no broken-pipe message"; show err; }
    ;;
  file-size-limit)
    # ulimit -f: exit 2 with a message, OUT unchanged, nothing left (was: SIGXFSZ, a partial
    # temporary file). The limit is on the tool only; the output is about 2 MB.
    big big.mpf 40000
    echo old >lim.h
    (ulimit -f 100 && exec env --default-signal "$exe" $translate -o lim.h big.mpf) >out 2>err
    rc=$?
    [ "$rc" = 2 ] || { report "exit $rc, expected 2"; show err; }
    grep -q "cannot write 'lim.h': File too large" err || { report "no file-size message"; show err; }
    [ "$(cat lim.h)" = old ] || report "lim.h changed"
    no_temporary
    ;;
  signals)
    # SIGTERM, SIGINT, SIGHUP during the write: the process dies of the signal, OUT keeps its
    # old contents and no temporary file is left; SIGKILL too where the temporary file has no
    # name. KIN5_OUTPUT_NAMED_TEMP=1 makes the tool use the named temporary file it falls back
    # to where the file system has no O_TMPFILE; SIGKILL cannot be caught, so it is not tried
    # there. The signal is sent once the write has begun: a kin5 temporary file in the
    # directory, or an open deleted file in the process.
    big big.mpf 100000
    for mode in unnamed named; do
      for sig in TERM INT HUP KILL; do
        [ "$mode.$sig" = named.KILL ] && continue
        echo old >o.h
        if [ "$mode" = named ]; then
          KIN5_OUTPUT_NAMED_TEMP=1 env --default-signal "$exe" $translate -o o.h big.mpf 2>/dev/null &
        else
          env --default-signal "$exe" $translate -o o.h big.mpf 2>/dev/null &
        fi
        pid=$!
        i=0
        while [ $i -lt 6000 ]; do
          ls -A | grep -q 'kin5-' && break
          ls -l /proc/$pid/fd 2>/dev/null | grep -q "$dir/.*(deleted)" && break
          kill -0 $pid 2>/dev/null || break
          sleep 0.01
          i=$((i + 1))
        done
        kill -s $sig $pid 2>/dev/null || report "$mode $sig: the run ended before the signal"
        wait $pid
        rc=$?
        case $sig in TERM) want=143 ;; INT) want=130 ;; HUP) want=129 ;; KILL) want=137 ;; esac
        [ "$rc" = "$want" ] || report "$mode $sig: exit $rc, expected $want"
        [ "$(cat o.h)" = old ] || report "$mode $sig: o.h changed"
        [ "$(ls -A | grep -c 'kin5-')" = 0 ] || report "$mode $sig: temporary files left: $(ls -A | grep 'kin5-')"
        rm -f .o.h.kin5-*
      done
    done
    ;;
  *)
    echo "output_file.sh: unknown test '$name'" >&2
    exit 2
    ;;
esac
exit "$fail"
