#!/bin/sh
# tests/harden-paste.sh: text pasted into the interactive program's terminal. A paste of
# arbitrary text (q, ?, [, ], digits, g, a new line) is no flood of commands: with
# bracketed paste (the program turns xterm's mode 2004 on; tmux's paste-buffer -p then
# brackets the text) and as a burst of text from a terminal without it, the status line
# stays as it was (paused, 1x, no ghost), no help, and the program says the paste was
# ignored; pasted while a value is typed, the text goes into the value. The mode is turned
# off again at the end: on q, and on SIGTERM; and while the program is suspended (Ctrl+Z),
# on again after fg. Run from the repository root as `sh tests/harden-paste.sh`, SPRINGSIM
# naming the binary. Ends with "harden-paste: N passed, M failed".
NAME=harden-paste
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start bracketed 80 24 -- -p resonance
start burst 80 24 -- -p resonance
start value 80 24
start term 80 24
# Every byte the program of session term writes, to see the mode set and reset.
tm pipe-pane -t term -o "cat >>'$tmp/term.out'"
for s in bracketed burst value term; do S=$s; wait_for Paused 5; done

# paste SESSION [-p]: the text below pasted into SESSION (-p: bracketed, as the program
# asked)
paste() {
    tm set-buffer -b t "q?mgf]]]]]12345 GG[[ q
q"
    tm paste-buffer -b t -t "$1" $2
}
for how in "bracketed -p" "burst"; do
    set -- $how
    S=$1
    cap
    status=$(head -n 1 "$scr")
    paste "$1" "$2"
    sleep 1
    cap
    if alive "$1" && [ "$(head -n 1 "$scr")" = "$status" ] && lacks '┌ Keys' &&
        has 'pasted text ignored'; then pass; else
        fail "$1 paste: the pasted text acted as keys (q, ?, ], g, digits): $(brief)"
    fi
done
# into a value being typed: Tab to the first mass, Enter, then the paste
S=value
keys Tab Enter
wait_for 'Enter sets it' 3
tm set-buffer -b v "0.25"
tm paste-buffer -b v -t value -p
sleep 0.5
cap
has 'm (kg) = 0.25' && pass || fail "a value pasted while typing should go into it: $(brief)"
keys Enter
wait_for 'm 0.25 kg' 3 && pass || fail "the pasted value should be set by Enter: $(brief)"

# last_mode SESSION: h or l, the last of xterm's mode 2004 set or reset in its output
last_mode() {
    LC_ALL=C awk 'BEGIN { RS = "\033\\[\\?2004" } NR > 1 { last = substr($0, 1, 1) } END { print last }' "$tmp/$1.out"
}
# the mode off once the program ends: by q, then by SIGTERM (that it is on while the
# program runs is seen below, where the output is watched from before the program starts:
# here the pipe is attached once the session runs, and may come after the mode is set)
S=term
keys q
wait_for EXITED 5
off=$(last_mode term)
[ "$off" = l ] && pass || fail "q: bracketed paste should be off at the end (last: '$off')"
start term2 80 24
S=term2
tm pipe-pane -t term2 -o "cat >>'$tmp/term2.out'"
wait_for Paused 5
kill -TERM "$(cat "$tmp/term2.pid")"
wait_for EXITED 5
off=$(last_mode term2)
[ "$off" = l ] && pass || fail "SIGTERM: bracketed paste should be off at the end (last: '$off')"

# and Ctrl+Z: off while the shell has the terminal, on again after fg
start_shell sus 80 24
tm pipe-pane -t sus -o "cat >>'$tmp/sus.out'"
S=sus
wait_for 'PROMPT$' 5
text "$SPRINGSIM"
keys Enter
wait_for Paused 5
modes=$(last_mode sus)
keys C-z
wait_for Stopped 5
modes="$modes $(last_mode sus)"
text fg
keys Enter
wait_for Paused 5
modes="$modes $(last_mode sus)"
keys q
wait_for 'PROMPT$' 5
[ "$modes" = "h l h" ] && pass ||
    fail "Ctrl+Z: bracketed paste should be on, off while suspended, on after fg: got '$modes'"

summary
