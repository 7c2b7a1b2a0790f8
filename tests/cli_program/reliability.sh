#!/bin/sh
# End-to-end regression tests of the program commands under hostile input and surroundings
# (docs/reliability.md).
#
#   reliability.sh KIN5_EXE EXAMPLES_DIR TEST_NAME
#
# How OUT is written (tools/kin5/output_file.hpp): each test runs the built tool in a fresh
# directory with OUT of one kind (regular file, symbolic link, hard link, read-only file, FIFO,
# character device, stdout) or under one kind of interruption (a signal, a file-size limit, a
# closed pipe), and checks the exit code, the message, what OUT holds afterwards, and that no
# temporary file is left. Signals are reset to their default action for the tool
# (`env --default-signal`), so that a tool which relies on inheriting them ignored is caught.
# Then inputs and options that once corrupted memory, wrote garbage or were accepted silently.
set -u

# Every signal at its default action for the tool (see above).
KIN5_RUN_ENV=--default-signal
. "$(cd "$(dirname "$0")" && pwd)/harness.sh"
example="$examples/table1-sajo.mpf"
translate="translate --from sajo-12000p --to dmu-80p --work-offset-map G54=1"  # the example's G54: preset 1

# limited run ...: `run` within 1 GB of address space (the memory bound of the input limits),
# except under AddressSanitizer, whose shadow memory alone takes more.
limited() {
  if ldd "$exe" 2>/dev/null | grep -q libasan; then "$@"; else (ulimit -v 1000000 && "$@"; exit "$fail") || fail=1; fi
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
  store-file-limit)
    # The blocks past --max-memory-bytes go to a temporary file; when it cannot be written (here
    # ulimit -f, during the first pass) the run is an input error naming it, OUT unchanged.
    big big.mpf 40000
    echo old >lim.h
    (ulimit -f 100 && exec env --default-signal "$exe" $translate --max-memory-bytes 1KiB -o lim.h big.mpf) >out 2>err
    rc=$?
    [ "$rc" = 2 ] || { report "exit $rc, expected 2"; show err; }
    grep -q "^big.mpf: error: cannot write the temporary file that holds the executed blocks beyond 1024 bytes (--max-memory-bytes): File too large" err ||
      { report "no message about the temporary file"; show err; }
    [ "$(cat lim.h)" = old ] || report "lim.h changed"
    no_temporary
    ;;
  signals)
    # SIGTERM, SIGINT, SIGHUP during the write: the process dies of the signal, OUT keeps its
    # old contents and no temporary file is left; SIGKILL too where the temporary file has no
    # name. KIN5_OUTPUT_NAMED_TEMP=1 makes the tool use the named temporary file it falls back
    # to where the file system has no O_TMPFILE; SIGKILL cannot be caught, so it is not tried
    # there. The signal is sent once the write has begun: a kin5 temporary file in the
    # directory, or an open deleted file in the process. The program is long enough for the
    # write to outlast that polling on a loaded machine (100,000 blocks were written in about
    # 0.1 s of CPU, less than one poll at a load of 14).
    big big.mpf 250000
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
  huge-record)
    # A 1.1 MB comment line, larger than a chunk of the block store, then ordinary blocks: the
    # record after it once went past the end of the chunk (a crash, or a corrupt heap and exit 0).
    {
      printf 'N10 TRAORI\nN20 G1 X1 Y2 Z3 A-10 B20 F100 ; '
      head -c 1100000 /dev/zero | tr '\0' c
      printf '\nN30 G1 X2 Y2 Z3\nN40 TRAFOOF\nN50 M30\n'
    } >y.mpf
    run 0 $translate -o y.h y.mpf
    grep -q '5 blocks read, 5 written' err || { report "summary"; show err; }
    [ "$(grep -c '^[0-9]* L ' y.h)" = 2 ] || report "the two moves not written"
    grep -q "$(head -c 1000 /dev/zero | tr '\0' c)" y.h || report "the long comment not kept"
    ;;
  number-range)
    # Numbers no NC program can hold are refused, never written as garbage: a setup offset
    # beyond 1e9 mm (exit 1), and an inverse-time F of 1/(1e-81 mm / 100 mm/min) (exit 2,
    # naming the block). --digits 4 lets the 81-decimal position past the precision check, so
    # the number check itself is what refuses the block.
    run 1 $translate --setup-offset=1e100,0,0 -o o.h "$example"
    grep -q -- '--setup-offset: each number must be within' err || { report "no offset message"; show err; }
    run 1 $translate --setup-offset=1e20,0,0 -o o.h "$example"
    zeros=$(awk 'BEGIN { while (n++ < 80) printf "0" }')
    printf 'N5 T1 M6\nN10 TRAORI\nN20 G1 X0 Y0 Z0 A-10 B20 F100\nN30 G1 X0.%s1\nN40 M30\n' "$zeros" >tiny.mpf
    run 2 $translate --to-dialect iso --feed inverse-time --digits 4 -o o.h tiny.mpf
    grep -q "^tiny.mpf:4:1: error: cannot write the program as iso: the number 1e+83 cannot be written" err || { report "no number message"; show err; }
    [ -e o.h ] && report "o.h written"
    ;;
  zero-feed)
    # A feed other than 0 is never written as F0: an inverse-time F of 1/(1000 mm / 20 mm/min)
    # is 0.02 (ISO and Siemens), a per-minute F0.04 stays F0.04 (Heidenhain); a rate the
    # controller's 3 decimals cannot write within 0.5 % is refused at its block. And F0 on a
    # feed move is refused at the F word, or at the move when an earlier F0 is in effect.
    printf 'N5 T1 M6\nN10 TRAORI\nN20 G1 X0 Y0 Z0 A-10 B20 F100\nN30 G1 X1000 F20\nN40 M30\n' >slow.mpf
    for to in iso siemens; do
      run 0 $translate --to-dialect $to --feed inverse-time -o o.nc slow.mpf
      grep -q 'X-1000\.\? .*F0\.02$' o.nc || { report "$to: inverse-time F not 0.02"; show o.nc; }
    done
    printf 'N5 T1 M6\nN10 TRAORI\nN20 G1 X0 Y0 Z0 A-10 B20 F100\nN30 G1 X10 F0.04\nN40 M30\n' >small.mpf
    run 0 $translate -o o.h small.mpf
    grep -q '^4 L X-10 .* F0\.04$' o.h || { report "F0.04 not kept"; show o.h; }
    printf 'N5 T1 M6\nN10 TRAORI\nN20 G1 X0 Y0 Z0 A-10 B20 F100\nN30 G1 X1000000 F0.4\nN40 M30\n' >tiny.mpf
    rm -f o.nc
    run 2 $translate --to-dialect iso --feed inverse-time -o o.nc tiny.mpf
    grep -q '^tiny.mpf:4:1: error: cannot write the program as iso: the feed 4[0-9.]*e-07 cannot be written with 3 decimals' err ||
      { report "no refusal of F4e-07"; show err; }
    [ -e o.nc ] && report "o.nc written"
    printf 'N5 T1 M6\nN10 TRAORI\nN20 G1 X0 Y0 Z0 A-10 B20 F100\nN30 G1 X10 F0 ; F1\nN40 G0 X20\nN50 G1 X30\nN60 M30\n' >zero.mpf
    rm -f o.h
    run 2 $translate -o o.h zero.mpf
    grep -q '^zero.mpf:4:12: error: feed move with F0' err || { report "F0 not refused at its word"; show err; }
    grep -q '^zero.mpf:6:1: error: feed move at a zero feed rate' err || { report "modal F0 not refused"; show err; }
    [ "$(grep -c ': error: ' err)" = 2 ] || { report "the rapid move G0 X20 refused too"; show err; }
    [ -e o.h ] && report "o.h written"
    ;;
  near-pole)
    # SAJO 12000P A alternating -90 +- eps (B = 30) is the DMU 80P's pole B = 0 give or take a
    # few 1e-6 rad: C keeps its angle on every block (it turned 180 deg per block), no warning.
    for eps in 0.0000001 0.00001 0.0001; do
      awk -v e=$eps 'BEGIN { print "N10 TRAORI"
        for (i = 0; i < 6; ++i) printf "N%d G1 X%d Y0 Z50 A%.7f B30 F1000\n", 20 + 10 * i, i, i % 2 ? -90 + e : -90 - e
        print "N99 M30" }' >jitter.mpf
      run 0 $translate --to-dialect siemens --digits 7 -o o.mpf jitter.mpf
      [ "$(grep -o ' C[-0-9.]*' o.mpf | sort -u | wc -l)" = 1 ] || { report "eps $eps: C moves"; show o.mpf; }
      grep -q 'warning' err && { report "eps $eps: a warning"; show err; }
    done
    # Crossing the pole in 1 deg steps: the DMU's B cannot go below 0, so C must turn 180 deg
    # inside one 0.1 mm block, and says so at that block with the angle.
    awk 'BEGIN { print "N10 TRAORI"
      for (i = 0; i < 7; ++i) printf "N%d G1 X%.1f Y0 Z50 A%d B30 F1000\n", 20 + 10 * i, i / 10, -93 + i
      print "N99 M30" }' >cross.mpf
    run 0 $translate -o o.h cross.mpf
    [ "$(grep -c 'warning' err)" = 1 ] || { report "not one warning"; show err; }
    grep -q '^cross.mpf:6:1: warning: sudden rotary move on dmu-80p: C turns by 180.000° while the tool axis turns by 1.000°' err ||
      { report "no warning of the C turn at line 6"; show err o.h; }
    ;;
  setup-angle)
    # A setup angle that is not a finite number is a bad argument, as a bad offset is.
    for angle in nan inf -inf; do
      run 1 $translate --setup-axis 0,0,1 --setup-angle "$angle" -o o.h "$example"
      grep -q -- '--setup-angle must be a finite number' err || { report "$angle: no message"; show err; }
    done
    [ -e o.h ] && report "o.h written"
    ;;
  error-cap)
    # A long line of bad words: the first 100 errors, then their count, not 20000 lines.
    { printf 'N10 TRAORI\nN20 G1'; awk 'BEGIN { while (n++ < 20000) printf " X1.2." }'; printf '\nN30 M30\n'; } >bad.mpf
    run 2 $translate -o o.h bad.mpf
    [ "$(grep -c ': error: ' err)" = 100 ] || report "$(grep -c ': error: ' err) errors printed, expected 100"
    grep -q '^kin5 translate: 19900 more errors not shown' err || { report "no count of the rest"; tail -n 3 err >&2; }
    grep -q '^kin5 translate: 20000 errors in bad.mpf' err || report "total not given"
    ;;
  same-file)
    # -o or --report naming the input file is refused before anything is read or written, exit 1:
    # directly, through a symbolic link, by another hard link, '-' read from it, stdout
    # redirected onto it; and -o and --report naming one file. Every program command.
    cp "$example" in.mpf
    ln -s in.mpf link.mpf
    ln in.mpf hard.mpf
    sum=$(cksum <in.mpf)
    same() {  # same EXPECTED_MESSAGE ARGS...: exit 1, that message, in.mpf untouched, nothing left
      want_msg=$1; shift
      run 1 "$@"
      grep -q -- "$want_msg" err || { report "no refusal ($want_msg): kin5 $*"; show err; }
      [ "$(cksum <in.mpf)" = "$sum" ] || { report "in.mpf changed by: kin5 $*"; cp "$example" in.mpf; }
      [ -s out ] && report "stdout written by: kin5 $*"
      no_temporary
    }
    same '-o in.mpf is the input file in.mpf' $translate -o in.mpf in.mpf
    same '-o link.mpf is the input file in.mpf' $translate -o link.mpf in.mpf
    same '-o hard.mpf is the input file in.mpf' $translate -o hard.mpf in.mpf
    same '--report in.mpf is the input file in.mpf' $translate --report in.mpf -o o.h in.mpf
    same '--report link.mpf is the input file' $translate --report link.mpf -o o.h in.mpf
    same '-o in.mpf is the file stdin reads' $translate -o in.mpf - <in.mpf
    same '-o hard.mpf is the file stdin reads' $translate -o hard.mpf - <in.mpf
    env --default-signal "$exe" $translate -o - in.mpf 1<>in.mpf 2>err
    rc=$?
    [ "$rc" = 1 ] || { report "stdout onto in.mpf: exit $rc, expected 1"; show err; }
    grep -q -- '-o - (stdout) is the input file in.mpf' err || { report "stdout onto in.mpf: no refusal"; show err; }
    [ "$(cksum <in.mpf)" = "$sum" ] || report "in.mpf changed through stdout"
    same '-o in.mpf is the input file' reverse --machine sajo-12000p -o in.mpf in.mpf
    same '--report in.mpf is the input file' reverse --machine sajo-12000p --report in.mpf -o o.apt in.mpf
    run 0 reverse --machine sajo-12000p --work-offset-map G54= -o in.apt in.mpf
    apt_sum=$(cksum <in.apt)
    run 1 post --machine dmu-80p -o in.apt in.apt
    grep -q -- '-o in.apt is the input file in.apt' err || { report "post: no refusal"; show err; }
    run 1 post --machine dmu-80p --report in.apt -o o.h in.apt
    [ "$(cksum <in.apt)" = "$apt_sum" ] || report "post replaced its input"
    echo old >o.h
    ln -s o.h o-link.h
    same '--report o-link.h and -o o.h are the same file' $translate --report o-link.h -o o.h in.mpf
    [ "$(cat o.h)" = old ] || report "o.h changed"
    [ -e o.json ] && report "o.json written"
    ;;
  unreadable-input)
    # A directory or an unreadable file given for a program, a machine file or a tool table: exit
    # 2 with a read error (was: match aborted with an uncaught std::__ios_failure, exit 134; a
    # directory as a machine file reported five missing keys).
    mkdir d
    run 2 translate --from-file d --to dmu-80p -o o.h "$example"
    grep -q '^d:1:1: error: cannot read the machine file: is a directory$' err || { report "machine file: directory"; show err; }
    grep -q 'missing key' err && { report "directory read as an empty machine file"; show err; }
    run 2 $translate --tool-table d --work-offset 0,0,0 -o o.h "$example"
    grep -q '^d:1:1: error: cannot read the tool-table file: is a directory$' err || { report "tool table: directory"; show err; }
    run 2 machines --machine-file /proc/self/mem
    grep -q '^/proc/self/mem:1:1: error: cannot read the machine file: Input/output error$' err || { report "machine file: EIO"; show err; }
    run 2 $translate -o o.h d
    grep -q "cannot read 'd': is a directory" err || { report "program: directory"; show err; }
    run 2 $translate -o o.h /proc/self/mem
    grep -q "cannot read '/proc/self/mem': Input/output error" err || { report "program: EIO"; show err; }
    if "$exe" match --from sajo-12000p --to dmu-80p 2>&1 | grep -q 'built without Ipopt'; then :; else
      run 2 match --from sajo-12000p --to dmu-80p --program d
      grep -q '^kin5 match: cannot read d: is a directory$' err || { report "match: directory"; show err; }
      run 2 match --from sajo-12000p --to dmu-80p --program /proc/self/mem
      grep -q '^kin5 match: cannot read /proc/self/mem: Input/output error$' err || { report "match: EIO"; show err; }
    fi
    [ -e o.h ] && report "o.h written"
    ;;
  deep-toml)
    # A 40,000-part dotted key, table name, or deeply nested inline tables or arrays in a machine
    # file or tool table: refused at its line and column before toml++ parses it (was: SIGSEGV,
    # the stack overflowed inside toml++); a key over 256 bytes and a file over 4 MiB too.
    awk 'BEGIN { print "kin5_machine = 1"; printf "a"; for (i = 1; i < 40000; ++i) printf ".a"; print " = 1" }' >key.toml
    awk 'BEGIN { print "kin5_tools = 1"; printf "["; printf "a"; for (i = 1; i < 40000; ++i) printf ".a"; print "]" }' >table.toml
    awk 'BEGIN { printf "x = "; for (i = 0; i < 40000; ++i) printf "{a = "; printf "1"; for (i = 0; i < 40000; ++i) printf "}"; print "" }' >inline.toml
    awk 'BEGIN { printf "x = "; for (i = 0; i < 40000; ++i) printf "["; printf "1"; for (i = 0; i < 40000; ++i) printf "]"; print "" }' >array.toml
    for f in key table inline array; do
      run 2 machines --machine-file $f.toml
      grep -q "^$f.toml:[12]:[0-9]*: error: nested more than 32 levels deep" err || { report "$f: machine file"; show err; }
      run 2 $translate --tool-table $f.toml --work-offset 0,0,0 -o o.h "$example"
      grep -q "^$f.toml:[12]:[0-9]*: error: nested more than 32 levels deep" err || { report "$f: tool table"; show err; }
    done
    run 2 machines --machine-file key.toml
    grep -q '^key.toml:2:1: error: nested' err || { report "not at the key"; show err; }
    awk 'BEGIN { print "kin5_tools = 1"; printf "  "; for (i = 0; i < 300; ++i) printf "k"; print " = 1" }' >long.toml
    run 2 $translate --tool-table long.toml --work-offset 0,0,0 -o o.h "$example"
    grep -q '^long.toml:2:3: error: a key longer than 256 bytes' err || { report "long key"; show err; }
    head -c 5000000 /dev/zero | tr '\0' '\n' >big.toml
    run 2 machines --machine-file big.toml
    grep -q '^big.toml:1:1: error: cannot read the machine file: larger than 4194304 bytes' err || { report "big file"; show err; }
    run 2 machines --machine-file /dev/zero
    grep -q 'larger than 4194304 bytes' err || { report "/dev/zero"; show err; }
    [ -e o.h ] && report "o.h written"
    ;;
  number-options)
    # nan, inf and 1e400 as a tool length or work offset are refused by every command with the
    # same check (format.hpp parse_length_mm): was accepted by match, which printed nan slides.
    for bad in nan inf 1e400; do
      run 1 $translate --work-offset "0,$bad,0" -o o.h "$example"
      run 1 $translate --work-offset 0,0,0 --tool-length "$bad" -o o.h "$example"
      run 1 solve --machine dmu-80p --vector 0,0,1 --tip 0,0,0 --tool-length "$bad"
      run 1 solve --machine dmu-80p --vector 0,0,1 --tip 0,0,0 --work-offset "0,0,$bad"
    done
    if "$exe" match --from sajo-12000p --to dmu-80p 2>&1 | grep -q 'built without Ipopt'; then :; else
      for bad in nan inf 1e400 -1; do
        run 1 match --from sajo-12000p --to dmu-80p --program "$example" --tool-length "$bad" --work-offset 0,0,-300
        grep -q -- '--tool-length: give a length in mm' err || { report "match --tool-length $bad"; show err; }
        [ -s out ] && report "match --tool-length $bad printed a report"
      done
      for bad in nan inf 1e400; do
        run 1 match --from sajo-12000p --to dmu-80p --program "$example" --work-offset "0,$bad,0"
        grep -q -- '--work-offset needs 3 numbers' err || { report "match --work-offset $bad"; show err; }
      done
      run 0 match --from sajo-12000p --to dmu-80p --program "$example" --tool-length 100 --work-offset 0,0,-500
      grep -qi nan out && { report "nan in the report"; show out; }
    fi
    [ -e o.h ] && report "o.h written"
    ;;
  all-signals)
    # With the named temporary file, every signal whose default action ends the process (and
    # can be caught) removes it before the process dies of that signal; INT, TERM, HUP: the
    # `signals` test. Was: QUIT, XCPU, USR1, ALRM … left .o.h.kin5-XXXXXX behind.
    big big.mpf 250000
    ulimit -c 0  # QUIT, XCPU, SYS, ABRT dump core by default
    for sig in QUIT XCPU USR1 USR2 ALRM VTALRM PROF IO PWR SYS ABRT RTMIN; do
      echo old >o.h
      KIN5_OUTPUT_NAMED_TEMP=1 env --default-signal "$exe" $translate -o o.h big.mpf 2>/dev/null &
      pid=$!
      i=0
      while [ $i -lt 6000 ]; do
        ls -A | grep -q 'kin5-' && break
        kill -0 $pid 2>/dev/null || break
        sleep 0.01
        i=$((i + 1))
      done
      kill -s $sig $pid 2>/dev/null || report "$sig: the run ended before the signal"
      wait $pid
      rc=$?
      [ "$rc" -gt 128 ] && [ "$(kill -l $rc)" = "$sig" ] || report "$sig: exit $rc, not death by $sig"
      [ "$(cat o.h)" = old ] || report "$sig: o.h changed"
      [ "$(ls -A | grep -c 'kin5-')" = 0 ] || report "$sig: temporary files left: $(ls -A | grep 'kin5-')"
      rm -f .o.h.kin5-*
    done
    ;;
  digits-rounding)
    # --digits below the source's decimals rounds knowingly but never silently: a warning that
    # says how far a position or an angle may move (--digits 0 moved 3-decimal positions by up
    # to 0.5 mm without a word); at or above them, nothing is said.
    run 0 $translate --digits 0 -o o.h "$example"
    grep -q "warning: --digits 0 rounds the source's positions written with 3 decimals to 0: each may move by up to 0.5 mm; angles written with 3 decimals to 0: each may move by up to 0.5 deg" err ||
      { report "no warning for --digits 0"; show err; }
    run 0 $translate --digits 2 -o o.h "$example"
    grep -q 'each may move by up to 0.005 mm' err || { report "no warning for --digits 2"; show err; }
    run 0 $translate --digits 3 -o o.h "$example"
    grep -q -- '--digits' err && { report "a warning for --digits 3"; show err; }
    ;;
  binary-input)
    # NUL bytes are refused at the first one, before the input is read to its end: 50 MB of
    # them (each a lexer word of about 100 bytes, and the tool read any number of bytes) once
    # ended in std::bad_alloc and SIGABRT under a few GB of address space.
    head -c 50000000 /dev/zero >zero.mpf
    limited run 2 $translate -o o.h - <zero.mpf
    grep -q '^<stdin>:1:1: error: a NUL byte (0x00): binary data, not an NC program' err || { report "stdin"; show err; }
    limited run 2 $translate -o o.h /dev/zero
    grep -q '^/dev/zero:1:1: error: a NUL byte' err || { report "/dev/zero"; show err; }
    limited run 2 $translate -o o.h /dev/urandom
    grep -q '^/dev/urandom:[0-9]*:[0-9]*: error: a NUL byte' err || { report "/dev/urandom"; show err; }
    # A NUL byte inside a program: at its line and column; nothing else of the file is read.
    printf 'N10 TRAORI\nN20 G1 X1\0 Y2\nN30 TRAFOOF\nN40 M30\n' >nul.mpf
    run 2 $translate -o o.h nul.mpf
    [ "$(grep -c ': error: ' err)" = 1 ] || { report "more than the one error"; show err; }
    grep -q '^nul.mpf:2:10: error: a NUL byte' err || { report "nul.mpf"; show err; }
    [ ! -e o.h ] || report "o.h written"
    ;;
  endless-input)
    # A FIFO that never ends stops at the file-size limit, at the line where the limit falls.
    mkfifo endless
    yes 'G1 X1 Y2' >endless &
    limited run 2 $translate --max-file-bytes 1MB -o o.h - <endless
    kill $! 2>/dev/null
    grep -q '^<stdin>:111112:2: error: the input goes on past the file-size limit of 1000000 bytes; --max-file-bytes raises it' err ||
      { report "no file-size refusal"; show err; }
    [ ! -e o.h ] || report "o.h written"
    # A file within the limit is read.
    run 0 $translate --max-file-bytes 4KiB -o o.h "$example"
    run 2 $translate --max-file-bytes 100 -o o.h "$example"
    grep -q "$(basename "$example"):3:62: error: the input goes on past the file-size limit of 100 bytes" err || { report "example"; show err; }
    ;;
  long-line)
    # A line longer than --max-line-bytes is refused at its line, at the first byte past the
    # limit; raised, the same line (a 2 MiB comment) is translated within a bounded address space.
    # long LENGTH: a program whose line 2 is LENGTH bytes.
    long() {
      printf 'N10 TRAORI\nN20 G1 X1 Y2 Z3 A-10 B20 F100 ; '
      head -c "$(($1 - 32))" /dev/zero | tr '\0' c
      printf '\nN30 G1 X2 Y2 Z3\nN40 TRAFOOF\nN50 M30\n'
    }
    long 2097152 >long.mpf
    run 2 $translate --max-line-bytes 1MiB -o o.h long.mpf
    grep -q '^long.mpf:2:1048577: error: a line longer than the line-length limit of 1048576 bytes; --max-line-bytes raises it' err ||
      { report "1MiB"; show err; }
    [ ! -e o.h ] || report "o.h written"
    limited run 0 $translate --max-line-bytes 2MiB -o o.h long.mpf
    grep -q '5 blocks read, 5 written' err || { report "summary"; show err; }
    run 1 $translate --max-line-bytes 0 -o o.h long.mpf
    # The default, 16 MiB (the dialect given: recognising it would scan the long line too).
    long 16777217 >long.mpf
    run 2 $translate --from-dialect siemens -o o.h long.mpf
    grep -q '^long.mpf:2:16777217: error: a line longer than the line-length limit of 16777216 bytes' err ||
      { report "default line limit"; show err; }
    ;;
  block-words)
    # More words in one line than --max-block-words: refused at the first word past the limit,
    # before any lexer keeps a word (a 60 MiB line of `X1 ` took 4.3 GB).
    { printf 'N10 TRAORI\nG1'; awk 'BEGIN { while (n++ < 2000) printf " X1" }'; printf '\nN30 M30\n'; } >words.mpf
    run 2 $translate --max-block-words 1000 -o o.h words.mpf
    grep -q '^words.mpf:2:3001: error: more words in one line than the words-per-block limit of 1000; --max-block-words raises it' err ||
      { report "1000 words"; show err; }
    run 2 $translate -o o.h words.mpf  # within the default: the reader's own errors (X repeated)
    grep -q 'words-per-block' err && report "refused by the default limit"
    # The default, 100,000: a line of 150,000 words (and 900 kB) is refused at the 100,001st,
    # within a bounded address space.
    { printf 'G1'; awk 'BEGIN { while (n++ < 150000) printf " X1.2." }'; printf '\nM30\n'; } >many.mpf
    limited run 2 $translate -o o.h many.mpf
    grep -q '^many.mpf:1:599998: error: more words in one line than the words-per-block limit of 100000' err ||
      { report "default"; show err; }
    [ ! -e o.h ] || report "o.h written"
    ;;
  executed-lines)
    # A program that loops for ever (a Heidenhain jump back, always taken) stops at
    # --max-executed-lines, at the statement that passes it, nothing written; one that repeats
    # a section within the bound is translated, each pass written.
    printf '0 BEGIN PGM LOOP MM\n1 TOOL CALL 1 Z S1000\n2 M128\n3 LBL 1\n4 L X+0 Y+0 Z+5 B+0 C+0 F500\n5 FN 9: IF +0 EQU +0 GOTO LBL 1\n6 END PGM LOOP MM\n' >loop.h
    run 2 translate --from dmu-80p --to dmu-80p --max-executed-lines 1000 -o o.h loop.h
    grep -q '^loop.h:5:3: error: more than 1000 lines executed: a jump may repeat for ever (--max-executed-lines raises the bound)' err ||
      { report "loop"; show err; }
    [ ! -e o.h ] || report "o.h written"
    printf '0 BEGIN PGM REP MM\n1 TOOL CALL 1 Z S1000\n2 M128\n3 LBL 1\n4 L X+0 Y+0 Z+5 B+0 C+0 F500\n5 CALL LBL 1 REP 2\n6 M30\n7 END PGM REP MM\n' >rep.h
    run 0 translate --from dmu-80p --to dmu-80p --max-executed-lines 1000 -o o.h rep.h
    [ "$(grep -c ' L X+0 Y+0 Z+5 B+0 C+0' o.h)" = 3 ] || { report "three passes"; show o.h; }
    run 1 translate --from dmu-80p --to dmu-80p --max-executed-lines 0 -o o.h rep.h
    ;;
  *)
    echo "reliability.sh: unknown test '$name'" >&2
    exit 2
    ;;
esac
exit "$fail"
