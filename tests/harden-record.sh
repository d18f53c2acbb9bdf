#!/bin/sh
# tests/harden-record.sh: --record and --replay (issue 33, items 1, 2 and 11; issue 27). A
# recording made with keys in the program replays to the same state bit for bit, for the
# default chain with no preset (it wrote "element m 1 nan" lines), more masses and a
# preset, keys that change elements and views; its run lines are the shortest decimals
# (run 1.34, not 1.3400000000000003); a preset file whose name has two blanks in a row
# replays, from any directory (the recording holds its settings). --record writes as -o
# does (core/output.c): a FIFO is written in place and stays a FIFO, a character device
# stays one (as root), a symbolic link stays and its target is written, a new file gets
# the umask's mode and an old one keeps its own, names of 249 to 255 bytes are written,
# kill -9 leaves no file behind. --plain --replay that ends in another state says so and
# exits 1. A session past a lesson's 1800 s of runs ends its recording there, said, and
# the file replays. Run from the repository root as `sh tests/harden-record.sh`, SPRINGSIM
# naming the binary. Ends with "harden-record: N passed, M failed".
NAME=harden-record
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$tmp" || exit 1

# replays FILE WHAT: --plain --replay FILE exits 0 saying "bit for bit".
replays() {
    timeout 60 "$SPRINGSIM" --plain --replay "$1" </dev/null >"$tmp/replay.out" 2>"$tmp/replay.err"
    r=$?
    if [ "$r" -eq 0 ] && grep -q 'bit for bit' "$tmp/replay.out" && ! grep -qE '(^| )nan( |$)' "$1"; then
        pass
    else
        fail "$2: replay of $1 exit $r: $(tail -c 300 "$tmp/replay.err" "$tmp/replay.out" | tr '\n' '|')"
    fi
}

# 1. Recordings made with keys in the program, in tmux: set-up x keys.
# record_keys NAME ARGS -- KEYS...: the program with --record NAME.lesson and ARGS, each
# key sent 0.4 s apart (a key "wait" waits 1 s), then q.
record_keys() {
    name=$1
    shift
    rk_args=
    while [ "$1" != -- ]; do rk_args="$rk_args $1"; shift; done
    shift
    rm -f "$name.lesson"
    # shellcheck disable=SC2086
    start_in "$tmp" "$name" 80 24 -- --record "$name.lesson" $rk_args
    S=$name
    wait_for 'Paused' 5
    for k in "$@"; do
        if [ "$k" = wait ]; then sleep 1; else keys "$k"; sleep 0.4; fi
    done
    keys q
    wait_for 'EXITED' 5
}
record_keys default -- Space wait Space
replays default.lesson "the default chain, space, space"
record_keys three -n 3 -- Space wait Down Right Right Space m
replays three.lesson "-n 3, a control adjusted, the modes view"
record_keys res -p resonance -- Space wait Up Left wait Space
replays res.lesson "-p resonance, controls adjusted while running"

# A chain whose first step blows up at t = 0 pauses itself with no time run: the
# recording must still leave the replay paused there, so that the mass placed next is
# placed (it answered "ok pause first" and the replay ended elsewhere).
record_keys blowup -- Tab Enter 1e-9 Enter R Space Tab Tab l
replays blowup.lesson "a mass of 1e-9 kg, random, space (blows up at t = 0), a mass moved"
# and Space twice before a frame ran: started and paused with no time between.
record_keys quick -- Tab '  ' l
replays quick.lesson "space twice at once, then a mass moved"
printf 'set mass 1e-9\nrandom 7\nstart\nrun 1\nplace 1 0.3\nquit\n' |
    "$SPRINGSIM" --plain --record plainblow.lesson >/dev/null 2>&1
replays plainblow.lesson "plain: start, a run that blows up at once, place"
# and place refused (the chain running) is an error, not "ok"
printf 'start\nplace 1 0.3\nquit\n' | "$SPRINGSIM" --plain >"$out" 2>&1
grep -q '^error pause first to move a mass' "$out" && pass ||
    fail "place while running should be refused as an error: $(grep '^[oe]' "$out" | tr '\n' '|')"

# 2. Run lines in their shortest form, and what they replay.
printf 'run 2.34\nset frequency 0.5\nrun 1.34\nset frequency 0.6\nrun 0.07\nstart\nquit\n' |
    "$SPRINGSIM" --plain --record short.lesson >/dev/null 2>&1
runs=$(grep '^run ' short.lesson | tr '\n' ' ')
[ "$runs" = "run 2.34 run 1.34 run 0.07 " ] && pass ||
    fail "run lines: expected 'run 2.34 run 1.34 run 0.07', got '$runs'"
replays short.lesson "runs of 2.34, 1.34 and 0.07 s"

# 3. A preset file with two blanks in its name, named by a relative path: the recording
# holds its settings, so that it replays from another directory (it replayed only from
# the one it was made in), in plain mode and in the program (the Preset control typed).
cp "$root/presets/beating.ini" "$tmp/a  b.ini"
printf 'preset ./a  b.ini\nrun 1\nstart\nquit\n' | "$SPRINGSIM" --plain --record blanks.lesson >/dev/null 2>&1
grep -c '^setup$' blanks.lesson | grep -qx 2 && ! grep -q '^preset' blanks.lesson && pass ||
    fail "a preset loaded should be recorded as its settings: $(grep -E '^(preset|setup)' blanks.lesson)"
replays blanks.lesson "a preset path with two blanks"
mkdir elsewhere
cd elsewhere && replays ../blanks.lesson "a relative preset path, replayed from another directory"; cd "$tmp" || exit 1
# and in the program, a preset chosen from the menu whose directory is relative
mkdir mine
cp "$root/presets/beating.ini" mine/aaa.ini
start_in "$tmp" menu 80 24 SPRINGSIM_PRESETS=./mine -- --record menu.lesson
S=menu
wait_for 'Paused' 5
for k in Enter Down Enter Space; do keys "$k"; sleep 0.4; done
sleep 0.6
keys q
wait_for 'EXITED' 5
cd elsewhere && replays ../menu.lesson "a preset from SPRINGSIM_PRESETS=./mine, replayed from elsewhere"; cd "$tmp" || exit 1

# 4. A replay that ends elsewhere: said, exit 1.
sed 's/^expect t=[^ ]* x1=[^ ]*/expect t=0x1p+0 x1=0x1p-1/' short.lesson >other.lesson
"$SPRINGSIM" --plain --replay other.lesson </dev/null >"$out" 2>"$err"
rc=$?
if [ "$rc" -eq 1 ] && grep -q 'differs' "$out" && grep -q 'another state' "$err"; then pass; else
    fail "a replay ending in another state: exit $rc, $(cat "$err")"
fi

# 5. Where --record writes: as -o does.
record_to() { printf 'run 0.5\nstart\nquit\n' | "$SPRINGSIM" --plain --record "$1" >/dev/null 2>"$err"; }
mkfifo fifo
timeout 10 cat fifo >from-fifo &
reader=$!
record_to fifo
wait $reader
if [ -p fifo ] && grep -q '^expect ' from-fifo; then pass; else
    fail "--record FIFO: it is no longer a FIFO or the reader got nothing"
fi
ln -s target.lesson link.lesson
record_to link.lesson
if [ -L link.lesson ] && grep -q '^expect ' target.lesson; then pass; else
    fail "--record through a symbolic link: the link replaced or its target not written"
fi
(umask 077 && record_to private.lesson)
(umask 022 && record_to public.lesson)
: >old.lesson
chmod 600 old.lesson
(umask 022 && record_to old.lesson)
modes="$(stat -c %a private.lesson) $(stat -c %a public.lesson) $(stat -c %a old.lesson)"
[ "$modes" = "600 644 600" ] && pass ||
    fail "--record's modes: umask 077, 022 and an old 0600 file gave $modes (expected 600 644 600)"
if [ "$(id -u)" = 0 ]; then
    mknod -m 666 dev c 1 3
    record_to dev
    [ -c dev ] && pass || fail "--record onto a character device (1,3) replaced it"
fi
for len in 249 250 253 255; do
    name=$(printf "%${len}s" "" | tr ' ' n)
    record_to "$name"
    if grep -q "^expect " "$name" 2>/dev/null && [ ! -s "$err" ]; then pass; else
        fail "--record, a name of $len bytes: $(cat "$err")"
    fi
    rm -f "$name"
done
# kill -9 while recording: nothing left in the directory.
mkdir killed
mkfifo hold
"$SPRINGSIM" --plain --record killed/k.lesson <hold >/dev/null 2>&1 &
pid=$!
exec 3>hold
sleep 1
kill -9 "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
exec 3>&-
left=$(ls -A killed)
[ -z "$left" ] && pass || fail "--record killed with SIGKILL left: $left"

# A session longer than a lesson may run (1800 s of runs, reset or not): the recording
# ends at that bound, says so and where it went, and replays; the session goes on.
printf 'run 500\nrun 500\nreset\nrun 500\nrun 500\nstatus\nquit\n' |
    "$SPRINGSIM" --plain --record long.lesson >long.out 2>long.err
r=$?
if [ "$r" -eq 0 ] && grep -q 'recording ended at 1800 s of runs.*written to long.lesson' long.out &&
    grep -q 'status t=1000.00' long.out; then pass; else
    fail "a 2000 s session recorded: exit $r, $(grep -i 'record\|^status' long.out | tail -n 3 | tr '\n' '|') $(head -c 200 long.err)"
fi
replays long.lesson "a recording ended at 1800 s"
[ "$(awk '$1 == "run" { s += $2 } END { print s }' long.lesson)" = 1800 ] && pass ||
    fail "the ended recording's runs should add up to 1800 s: $(grep '^run' long.lesson | tr '\n' ' ')"

# and a session whose steps cost much (ten masses under a square drive of 1 MHz: 2000
# sub-steps a step) ends its recording at a lesson's bound in mass-steps, and replays.
printf 'set masses 10\nset dt 0.001\nset wave square\nset frequency 1000000\nrun 30\nquit\n' |
    "$SPRINGSIM" --plain --record heavy.lesson >heavy.out 2>&1
grep -q 'recording ended at .* mass-steps.*written to heavy.lesson' heavy.out && pass ||
    fail "a recording of costly steps should end at a lesson's mass-steps: $(grep -i record heavy.out | head -c 300)"
replays heavy.lesson "a recording ended at the bound in mass-steps"

# and a session of many commands and no runs (a lesson file holds 256 KiB at most: a
# recording of 15000 frequency changes was 304 KiB, refused by its own --replay) ends its
# recording below that size, says so, and replays: masses placed (changes of the chain
# or the drive cost mass-steps, which end a recording first; below).
awk 'BEGIN { for (i = 0; i < 20000; i++) printf "place 1 %.7f\n", i % 9973 / 100000 + 1e-7; print "quit" }' |
    "$SPRINGSIM" --plain --record bytes.lesson >bytes.out 2>&1
grep -q 'recording ended at .* KiB.*written to bytes.lesson' bytes.out && pass ||
    fail "a recording of 15000 commands should end below a lesson's size: $(grep -i record bytes.out | head -c 300)"
replays bytes.lesson "a recording ended at a lesson file's size"
# 15000 changes of the frequency at ten masses: each works out the limits of dt anew, as
# long as 4000 steps a mass, so the recording ends at a lesson's mass-steps (its replay
# took 25 s to check), and replays.
awk 'BEGIN { print "set masses 10"; for (i = 0; i < 15000; i++) printf "set frequency %.3f\n", 0.5 + i % 97 / 1000; print "quit" }' |
    "$SPRINGSIM" --plain --record changes.lesson >changes.out 2>&1
grep -q 'recording ended at .* mass-steps.*written to changes.lesson' changes.out && pass ||
    fail "a recording of 15000 changes at ten masses should end at a lesson's mass-steps: $(grep -i record changes.out | head -c 300)"
replays changes.lesson "a recording of changes ended at the bound in mass-steps"

summary
