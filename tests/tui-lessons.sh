#!/bin/sh
# tests/tui-lessons.sh: lessons in the interactive program, in a real terminal (tmux) at
# 80x24 and 120x40: the caption panel below the plots and the controls (never over them),
# the question and its choices readable, a digit answers, space goes on (a step's run
# plays, and space while it plays ends it at once), ',' goes back a step (to the state
# that step left), Esc leaves with the chain as it is; L opens the
# lesson menu, which reads (every lesson's name and title), and starts the one chosen; a
# bad lesson chosen there is refused with its line. Screens are kept in
# $SHOTS (if set) for a person to look at. Run from the repository root as
# `sh tests/tui-lessons.sh`, SPRINGSIM naming the binary. Ends with
# "tui-lessons: N passed, M failed".
NAME=tui-lessons
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"
root=$(cd "$(dirname "$0")/.." && pwd)

start l80 80 24 -- --lesson resonance
start l120 120 40 -- --lesson resonance
start m80 80 24
start m120 120 40
mkdir -p "$tmp/xdg-bad/springsim/lessons"
printf 'title Broken\npreset resonance\nset frequency 0.5\nwobble 3\n' \
    >"$tmp/xdg-bad/springsim/lessons/broken.lesson"
start bad 80 24 "XDG_CONFIG_HOME=$tmp/xdg-bad"
for f in "$root"/lessons/*.lesson; do
    n=$(basename "$f" .lesson)
    start "ask-$n" 80 24 -- --lesson "$n"
done
shot() { [ -n "$SHOTS" ] && mkdir -p "$SHOTS" && cp "$scr" "$SHOTS/$1.txt"; }

# row N: the first screen row (1-based) holding TEXT; 0 if none
row() { grep -nF -- "$1" "$scr" | head -n 1 | cut -d: -f1; }
# the last row of the plots' frames (their bottom edge) and of the controls' frame
plots_bottom() { grep -n '^└' "$scr" | sed -n '2p' | cut -d: -f1; }

for size in 80 120; do
    S=l$size
    cols=$size
    top=
    if ! up "$S"; then continue; fi
    wait_for 'Lesson 1/8' 5
    shot "lesson-$size-ask"
    top=$(row 'Lesson 1/8')
    # the panel: below every plot and the controls' frame, across the screen, its
    # question and the three choices in it, and its keys
    # (the whole step, its caption too, fits in the panel even at 80x24)
    if [ -n "$top" ] && [ "$(plots_bottom)" -lt "$top" ] && has 'At what frequency will the mass swing the most?' &&
        has 'One mass of 1 kg between two springs of 10 N/m; the motor shakes one end.' &&
        has '1) 0.50 Hz: √(k/m)/2π, as if one spring held it' && has '2) 0.71 Hz' && has '3) 1.00 Hz' && has '1-3 answers' &&
        has 'Esc leaves' && has Controls && has 'Displacement'; then pass; else
        fail "$S: the caption panel should sit below the plots and controls with the question, its three choices and its keys; screen: $(brief)"
    fi
    # the panel's frame is whole: both its corners on its top row, the right one in the
    # last column
    if sed -n "${top}p" "$scr" | grep -qE '^┌.*┐$' && [ "$(sed -n "${top}p" "$scr" | wc -m)" -eq $((cols + 1)) ]; then pass; else
        fail "$S: the caption panel's top edge should span the screen: $(sed -n "${top}p" "$scr")"
    fi
    keys 2
    if wait_all 3 "has 'You chose 2: right.' && has 'Lesson 2/8' && has 'modes: 1: 0.7118 Hz'"; then pass; else
        fail "$S: 2 should answer the question (right), go on to step 2 and show modes' answer; screen: $(brief)"
    fi
    keys Space
    # the step's run plays: the chain runs, the panel and the hints say space ends it
    if wait_all 3 "has 'Lesson 3/8' && has Running && has 'space ends the run' &&
        has 'space end the run' && t_at_least 0.3 && ! t_at_least 5"; then pass; else
        fail "$S: space should go on to step 3, its 0.5 Hz run playing at the lesson's speed; screen: $(brief)"
    fi
    keys Space
    if wait_all 3 "has 'Lesson 3/8' && has_re 'Paused +t = 30\.00 s' && has 'space goes on'"; then pass; else
        fail "$S: space while the run plays should end it at once (t = 30.00 s); screen: $(brief)"
    fi
    shot "lesson-$size-step3"
    keys ,
    if wait_all 3 "has 'back to step 2 of 8' && has 'Lesson 2/8' && has_re 't = 0\.00 s'"; then pass; else
        fail "$S: , should go back to step 2 (t = 0.00 s again); screen: $(brief)"
    fi
    keys Space Space Space Space
    if wait_all 3 "has 'Lesson 4/8' && has 'Now 0.60 Hz' && has_re 'Paused +t = 30\.00 s'"; then pass; else
        fail "$S: space four times should reach step 4 (0.60 Hz, its run ended at t = 30); screen: $(brief)"
    fi
    keys Escape
    if wait_all 3 "has 'left the lesson resonance: the chain is as it is' && lacks 'Lesson 4/8' &&
        has_re 't = 30\.00 s' && has '0.600 Hz'"; then pass; else
        fail "$S: Esc should leave the lesson, the chain as it is (t = 30.00, 0.600 Hz); screen: $(brief)"
    fi
    # the keys are the program's own again: space starts it
    keys Space
    if wait_re 'Running|t = 3[0-9]\.[0-9]*[1-9][0-9]* s' 3; then pass; else
        fail "$S: after the lesson, space should start the chain; screen: $(brief)"
    fi
done

# ---- every built-in lesson's first question reads whole at 80x24: its step's caption,
# the question and each choice, a line of the lesson wrapped where it is long ----
# step_of: the step the caption shows ("Lesson 3/8": 3)
step_of() { sed -n 's/.*Lesson \([0-9]*\)\/.*/\1/p' "$scr" | head -n 1; }
for f in "$root"/lessons/*.lesson; do
    n=$(basename "$f" .lesson)
    S=ask-$n
    up "$S" || continue
    # the step's caption lines, the question and the choices ("K) TEXT"), one a line
    awk '$1 == "pause" { n = 0 } $1 == "say" { sub(/^[ \t]*say[ \t]+/, ""); say[n++] = $0 }
         $1 == "ask" { for (i = 0; i < n; i++) print say[i]; sub(/^[ \t]*ask[ \t]+/, ""); print; q = 1; next }
         q && $1 == "choice" { sub(/^[ \t]*choice[ \t]+/, ""); print ++k ") " $0; next }
         q && $1 != "choice" { exit }' "$f" >"$tmp/ask-$n"
    i=0
    # space until the question's step is shown, each step waited for (a second space
    # before the step it goes on to is shown would pass the question by)
    while ! has ' answers ' && [ $i -lt 6 ]; do
        st=$(step_of)
        keys Space
        wait_all 3 "[ \"\$(step_of)\" != '$st' ]"
        i=$((i + 1))
    done
    has ' answers ' && settle 2 has ' answers '
    # the caption's rows joined (a line of the lesson may wrap onto the next row)
    awk '/Lesson [0-9]+\// { on = 1; next } on && /^└/ { exit }
         on { sub(/^│ ?/, ""); sub(/ *│ *$/, ""); printf "%s ", $0 }' "$scr" |
        tr -s ' ' >"$tmp/caption-$n"
    missing=
    while IFS= read -r line; do
        grep -qF -- "$(printf '%s' "$line" | tr -s ' ')" "$tmp/caption-$n" || missing="$missing|$line"
    done <"$tmp/ask-$n"
    if [ -s "$tmp/ask-$n" ] && has ' answers ' && [ -z "$missing" ]; then pass; else
        fail "$n at 80x24: the first question's step should show whole; missing: $missing; screen: $(brief)"
    fi
done

# ---- L: the lesson menu reads, and starts the lesson chosen ----
for size in 80 120; do
    S=m$size
    if ! up "$S"; then continue; fi
    keys L
    wait_for 'Lessons' 3
    shot "menu-$size"
    missing=
    for f in "$root"/lessons/*.lesson; do
        n=$(basename "$f" .lesson)
        title=$(sed -n 's/^title //p' "$f")
        # the name and its title (the whole title at 120 columns, its first 40 at 80)
        grep -qE "│ *$n +$(printf '%s' "$title" | cut -c 1-40 | sed 's/[][\.*^$()+?{}|/]/\\&/g')" "$scr" || missing="$missing $n"
        if [ "$size" = 120 ] && ! has "$title"; then missing="$missing $n(title)"; fi
    done
    if [ -z "$missing" ] && has 'Enter start'; then pass; else
        fail "$S: the lesson menu should list every lesson with its title; missing:$missing; screen: $(brief)"
    fi
    keys Down Down Enter
    if wait_all 3 "has 'Lesson 1/4: Damping' && has 'Each swing is smaller than the one before'"; then pass; else
        fail "$S: Down, Down, Enter should start the third lesson (damping); screen: $(brief)"
    fi
done

# ---- a bad lesson from the menu: refused with its line, nothing started ----
S=bad
if up bad; then
    keys L
    wait_for 'broken' 3
    keys Down Down Enter # absorber, beating, broken
    if settle_all 3 "has 'broken.lesson:4:' && has \"'wobble' is not\" && lacks 'Lesson 1/' &&
        has_re 't = 0\.00 s' && lacks Broken"; then pass; else
        fail "bad: a lesson with an unknown command should be refused with FILE:4 and nothing run; screen: $(brief)"
    fi
fi

# ---- --record in the program: keys become commands; --replay ends in that state ----
# (started here, not with the others: a recording keeps its idle time as waits, which the
# replay below sits through)
start rec 80 24 -- -p 3-mass-chain --record "$tmp/rec.lesson"
S=rec
if up rec; then
    keys Space ]
    wait_t 1
    keys g '<'
    wait_for 'ghost made' 3
    keys m
    wait_for 'Modes' 3
    keys Down Enter
    wait_for 'started in mode 2' 3
    keys Space
    wait_for Paused 3
    keys . . , R
    wait_for 'random initial positions' 3
    keys m
    wait_gone 'Modes' 3
    keys Tab Right Right
    keys c
    wait_for 'c (N' 3
    text 0.7
    keys Enter
    wait_for 'c = 0.7' 3
    keys L
    if wait_for 'no lessons while recording' 3; then pass; else
        fail "rec: L while recording should say no lessons; screen: $(brief)"
    fi
    keys Space
    wait_t 1.5
    keys Escape Up Left # the Graphics control (the last), auto -> braille
    wait_re '▸Graphics +braille' 3
    keys q
    poll 5 ended
    f=$tmp/rec.lesson
    missing=
    for want in '^start$' '^faster$' '^ghost$' '^set window 5$' '^view modes$' '^mode 2$' \
        '^step$' '^back$' '^random [0-9]+$' '^place 1 -?[0-9.e-]+$' '^element c 1 0.7$' '^set graphics braille$' \
        '^expect t=0x'; do
        grep -qE "$want" "$f" 2>/dev/null || missing="$missing $want"
    done
    if [ -z "$missing" ] && ! grep -q '^pause$' "$f"; then pass; else
        fail "rec: the recording should hold the keys as commands; missing:$missing; file: $(sed -n '/^end/,$p' "$f" 2>/dev/null | tr '\n' '|')"
    fi
    "$SPRINGSIM" --plain --replay "$f" </dev/null >"$tmp/replay.out" 2>&1
    if grep -q '^ok replayed: the state at t = [0-9.]* s is the one recorded, bit for bit$' "$tmp/replay.out"; then pass; else
        fail "rec: --plain --replay should end in the recorded state bit for bit: $(grep -E '^(error|ok replayed)' "$tmp/replay.out" | head -c 400)"
    fi
    start replay 80 24 -- --replay "$f"
    S=replay
    if up replay && wait_all 30 "has 'is the one recorded, bit for bit' && has 'the end'"; then pass; else
        fail "replay: --replay in the program should end in the recorded state bit for bit; screen: $(brief)"
    fi
    shot "replay-80"
fi

# A lesson cannot keep the program computing for long: 300 s of stiff cubic springs
# under a 1 MHz drive at dt 0.001 (about 10 s of computing at once, and as long for its
# check) passes the mass-steps a lesson may compute, refused at its run's line before
# anything runs. A run finished at once (space) on the heaviest chain a lesson may have
# stops on Esc: the lesson is left at once, before the run's end.
cat >"$tmp/heavy.lesson" <<'EOF2'
title heavy
setup
[system]
masses = 10
spring_cubic = 1000
damping = 0
dt = 0.001
[motor]
amplitude = 5
frequency = 1000000
end
say part one
run 300
pause
say part two
EOF2
sed 's/^frequency = 1000000$/frequency = 1/; s/^run 300$/run 1000/' "$tmp/heavy.lesson" >"$tmp/heaviest.lesson"
start heavy 80 24 -- --lesson "$tmp/heavy.lesson" --graphics braille
start heaviest 80 24 -- --lesson "$tmp/heaviest.lesson" --graphics braille
S=heavy
if wait_for 'EXITED 2' 20 && has "heavy.lesson:13: run 300: the lesson's runs pass"; then pass; else
    fail "heavy: the lesson should be refused at its run's line (mass-steps); screen: $(brief)"
fi
S=heaviest
if wait_for 'part one' 30; then
    t0=$(date +%s.%N)
    keys Space Escape
    if wait_for 'left the lesson heaviest' 5; then
        secs=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
        t=$(sed -n 's/.*Paused t = \([0-9.]*\) s.*/\1/p' "$scr" | head -n 1)
        if awk -v s="$secs" -v t="$t" 'BEGIN { exit !(s < 1.5 && t != "" && t + 0 < 1000) }'; then
            pass
        else
            fail "heaviest: Esc during a run finished at once should leave within a second, before t = 1000: took $secs s, t = $t"
        fi
    else
        fail "heaviest: Esc during a run finished at once should leave the lesson; screen: $(brief)"
    fi
else
    fail "heaviest: the lesson should start; screen: $(brief)"
fi

summary
