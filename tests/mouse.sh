#!/bin/sh
# tests/mouse.sh: the mouse in the interactive program, with the SGR mouse reports a
# terminal sends written into the pane as they would arrive: a click selects a control,
# the wheel adjusts it, and dragging a mass while paused sets its initial position.
# Ends with "mouse: N passed, M failed".
NAME=mouse
. "$(dirname "$0")/lib/check.sh"
sock=springsim-mouse-$$
T() { tmux -L "$sock" -f /dev/null "$@"; }
cleanup() { T kill-server 2>/dev/null; rm -rf "$tmp"; }
XDG_CONFIG_HOME=$tmp/xdg
export XDG_CONFIG_HOME

# screen_has TEXT: waits up to 2 s for TEXT on the screen.
screen_has() {
    for _ in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
        T capture-pane -p -t s | grep -q -- "$1" && return 0
        sleep 0.1
    done
    return 1
}
# mouse B X Y M: an SGR report (1-based cell), M for press/motion, m for release.
mouse() { T send-keys -t s -l "$(printf '\033[<%d;%d;%d%s' "$1" "$2" "$3" "$4")"; }

T new-session -d -x 120 -y 40 -s s "env LANG=C.UTF-8 TERM=xterm-256color $SPRINGSIM; sleep 30"
if ! screen_has Controls; then
    fail "the program did not start"
    summary
    exit
fi
# The Frequency control's row; the panel starts at column 90 at this width.
row=$(T capture-pane -p -t s | grep -n 'Frequency  1.000 Hz' | cut -d: -f1)
mouse 0 95 "$row" M
mouse 0 95 "$row" m
if screen_has '▸Frequency'; then pass; else fail "a click on Frequency did not select it"; fi
mouse 64 95 "$row" M # wheel up
if screen_has 'Frequency  1.010 Hz'; then pass; else fail "the wheel over Frequency did not raise it to 1.010 Hz"; fi
mouse 65 95 "$row" M # wheel down
if screen_has 'Frequency  1.000 Hz'; then pass; else fail "the wheel down did not lower it back"; fi

# Mass 1 sits at 10/3 m: column 3 + 10/3 * (118 - 11) / 13 = 30.4, on screen row 3.
mouse 0 31 3 M
mouse 32 36 3 M
mouse 32 40 3 M
mouse 0 40 3 m
if screen_has 'mass 1 starts at +1.'; then pass; else
    fail "dragging mass 1 did not set its initial position; bottom line: $(T capture-pane -p -t s | tail -1)"
fi
summary
