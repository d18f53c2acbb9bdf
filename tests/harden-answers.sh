#!/bin/sh
# tests/harden-answers.sh: what the terminal answers to the start-up queries, late or
# hostile (issue 33, items 3 and 4), in a pseudo-terminal of our own (tests/pixterm.c) and
# read back as a person sees it (tests/lib/screen.py, pyte's emulator).
# Answers that come 150 ms and 400 ms late (over SSH this is common), after the program
# stopped waiting for them, are never taken as keys (their [, ?, g and digits would slow
# the chain, open the help, show the ghost, enlarge a plot), and a key typed before they
# came (space) is kept: the chain runs at 1x, no ghost, no help.
# Run from the repository root as `sh tests/harden-answers.sh`, SPRINGSIM naming the
# binary. Ends with "harden-answers: N passed, M failed".
NAME=harden-answers
. "$(dirname "$0")/lib/check.sh"
trap 'exit 1' HUP INT TERM
plain_env
root=$(cd "$(dirname "$0")/.." && pwd)
PIXTERM=${PIXTERM:-$root/build/tests/pixterm}
screen="/usr/bin/python3 $root/tests/lib/screen.py"
LC_ALL=C.UTF-8
NCURSES_NO_UTF8_ACS=1
export LC_ALL NCURSES_NO_UTF8_ACS

# term KIND CW CH KEYS ARGS...: the program in a 100x30 terminal of KIND with cells of CW x
# CH pixels, KEYS typed; the screen at the end in $tmp/screen.
term() {
    kind=$1 cw=$2 ch=$3 keys=$4
    shift 4
    cmd="pixterm $kind $cw x $ch '$keys' springsim $*"
    "$PIXTERM" "$kind" 100 30 "$cw" "$ch" ffffff "$tmp/out" "$keys" "$SPRINGSIM" "$@"
    rc=$?
    $screen show "$tmp/out" 100 30 end >"$tmp/screen"
}
brief() { grep -E "$1" "$tmp/screen" | head -n 3 | tr '\n' '|'; }

# 1. Late answers, a key typed before them.
for late in 150 400; do
    term "sixel+$late" 10 20 '^ ~~q' -p resonance
    [ "$rc" -eq 0 ] && pass || fail "$cmd: exit $rc"
    grep -q 'Running' "$tmp/screen" && pass ||
        fail "$cmd: the space typed before the answers was lost: $(brief 'Paused|Running')"
    grep -qE 'Speed +1x' "$tmp/screen" && pass ||
        fail "$cmd: the answers changed the speed: $(brief 'Speed')"
    if grep -q 'ghost' "$tmp/screen" || grep -q '┌ Keys' "$tmp/screen"; then
        fail "$cmd: the answers showed the ghost or the help: $(brief 'ghost|[Kk]eys')"
    else
        pass
    fi
done

summary
