#!/bin/sh
# tests/mouse.sh: the mouse in the interactive program, with the SGR mouse reports a
# terminal sends written into the pane as they would arrive: a click selects a control,
# the wheel adjusts it, and dragging a mass while paused sets its initial position (the
# mass follows the pointer; r restarts from there). At 120x40 and 80x24; where to click
# is read from the screen (the Frequency control, mass 1's label), and each event's
# effect is waited for before the next. Ends with "mouse: N passed, M failed".
NAME=mouse
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

# mouse B X Y M: an SGR report (1-based cell), M for press/motion, m for release.
mouse() { text "$(printf '\033[<%d;%d;%d%s' "$1" "$2" "$3" "$4")"; }
# mass1_at COLUMN: mass 1's label is in that column of the scene's row (the motor's)
mass1_at() { [ "$(cell_of 1 MOTOR | cut -d' ' -f2)" = "$1" ]; }

start big 120 40
start small 80 24

for s in big small; do
    up $s || continue
    case $s in big) size=120x40 ;; *) size=80x24 ;; esac

    # ---- click and wheel on the Frequency control ----
    # the whole first frame, not a part of it (a slow start, under the sanitizers)
    wait_for 'Frequency  1.000 Hz' 5
    set -- $(cell_of 'Frequency  1.000 Hz')
    if [ $# -eq 2 ]; then
        row=$1 col=$(($2 + 3))
        mouse 0 "$col" "$row" M
        mouse 0 "$col" "$row" m
        if wait_for '▸Frequency'; then pass; else
            fail "$size: a click on Frequency (row $row, column $col) did not select it; screen: $(brief "$scr" 'Frequency')"
        fi
        mouse 64 "$col" "$row" M # wheel up
        if wait_for 'Frequency  1.010 Hz'; then pass; else
            fail "$size: the wheel up over Frequency did not raise it to 1.010 Hz; screen: $(brief "$scr" 'Frequency')"
        fi
        mouse 65 "$col" "$row" M # wheel down
        if wait_for 'Frequency  1.000 Hz'; then pass; else
            fail "$size: the wheel down over Frequency did not lower it back to 1.000 Hz; screen: $(brief "$scr" 'Frequency')"
        fi
    else
        fail "$size: no 'Frequency  1.000 Hz' control on the screen; screen: $(brief "$scr" 'Frequency')"
    fi

    # ---- drag mass 1 (paused) ----
    wait_for MOTOR 5
    set -- $(cell_of 1 MOTOR)
    if [ $# -eq 2 ]; then
        row=$1 col=$2
        mouse 0 "$col" "$row" M
        if wait_for '─ mass 1: m 1 kg'; then pass; else
            fail "$size: pressing on mass 1 (row $row, column $col) should select it (border 'mass 1: m 1 kg'); screen: $(brief "$scr" 'mass 1')"
        fi
        mouse 32 $((col + 4)) "$row" M
        if poll 5 mass1_at $((col + 4)) && wait_for 'mass 1 starts at +'; then pass; else
            fail "$size: dragging mass 1 four columns right should move its label there (column $((col + 4))) and say 'mass 1 starts at +…'; label at $(cell_of 1 MOTOR); screen: $(brief)"
        fi
        mouse 32 $((col + 8)) "$row" M
        mouse 0 $((col + 8)) "$row" m
        if poll 5 mass1_at $((col + 8)); then pass; else
            fail "$size: dragging on to eight columns right and letting go should leave mass 1 there (column $((col + 8))); label at $(cell_of 1 MOTOR); screen: $(brief)"
        fi
        x=$(sed -n 's/.*mass 1 starts at +\([0-9.]*\) m.*/\1/p' "$scr")
        if awk -v x="$x" 'BEGIN { exit !(x != "" && x + 0 > 0) }'; then pass; else
            fail "$size: after the drag the message should say 'mass 1 starts at +X m' with X > 0; bottom line: $(last_line)"
        fi
        # r restarts from the new initial position: the label stays where it was left
        keys r
        if wait_all 5 "lacks 'mass 1 starts at' && has 't = 0.00 s' && mass1_at $((col + 8))"; then pass; else
            fail "$size: r should restart with mass 1 where it was dragged (column $((col + 8))); label at $(cell_of 1 MOTOR); screen: $(brief)"
        fi
    else
        fail "$size: no label 1 on the scene's row (the one with MOTOR); screen: $(brief "$scr" MOTOR)"
    fi
done

summary
