#!/bin/sh
# tests/tui-play.sh: lessons and demos that play in the interactive program (tmux).
# In --lesson damping at 80x24 and 120x40, 2 s of wall time after the step with run 15
# starts, the status line's t has advanced between 1 and 4 s and the displacement plot's
# y axis covers the 0.5 m decay within a factor of 2. A run ended at once by space, a run
# played to its end and a step gone back to with ',' all end bit for bit where the plain
# mode (at full speed) ends: the lesson's own expect line says so. Every caption of every
# built-in lesson is on the screen or behind its ↓ more at 80x24 and 60x20 (each word of
# each say line is seen, scrolling with ↓). A recording made with keys replays in the
# program in about the time it was recorded (±20 %), bit for bit, and in --plain in under
# a second; space pauses the replay, '.' skips on. A lesson of more than 30 simulated
# minutes is refused with FILE:LINE, exit 2; the dry run of the longest one is left by
# Esc within 0.2 s. Run from the repository root as `sh tests/tui-play.sh`, SPRINGSIM
# naming the binary. Ends with "tui-play: N passed, M failed".
NAME=tui-play
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }

# The lessons of the bit-for-bit cases: two runs (3 s and 2.5 s, not whole periods),
# ending in the state the plain mode reaches, as an expect line.
state_of() { # state_of FILE: the state the plain mode ends the lesson FILE in
    printf '\n\n\n\n' | "$SPRINGSIM" --plain --lesson "$1" 2>&1 |
        sed -n 's/.*have \(t=[^)]*\)).*/\1/p' | head -n 1
}
mklesson() { # mklesson NAME STATE
    printf 'title Play %s\npreset resonance\nset amplitude 0\nset damping 0.3\nmode 1\n' "$1"
    printf 'say The first run.\nrun 3\npause\nsay The second run.\nrun 2.5\npause\n'
    printf 'say The end.\nexpect %s\n' "$2"
}
mklesson probe 't=0x0p+0' >"$tmp/probe.lesson"
want=$(state_of "$tmp/probe.lesson")
for n in space played back; do mklesson "$n" "$want" >"$tmp/$n.lesson"; done
# a lesson of 1801 simulated seconds, and the longest there may be (ten masses at dt
# 0.001 for 1800 s: 1.8 million steps, about 0.45 s to check)
printf 'title Long\npreset resonance\nrun 1000\nsay more\nrun 801\n' >"$tmp/long.lesson"
printf 'title Longest\npreset resonance\nset masses 10\nset dt 0.001\nrun 900\nrun 900\n' \
    >"$tmp/longest.lesson"

start d80 80 24 -- --lesson damping
start d120 120 40 -- --lesson damping

# ---- the damping lesson plays in real time, its plot fitted to the decay ----
# y_span TITLE: "BOTTOM TOP", the values the plot's y axis reaches at the middle of its
# lowest and highest rows, from the first and last labelled rows (the axis is linear)
y_span() {
    plot_awk 'END { if (!plot(title)) exit; r1 = ""
        for (r = axtop; r < axr; r++) { s = label(r); if (s == "") continue
            if (r1 == "") { r1 = r; v1 = s + 0 } else { r2 = r; v2 = s + 0 } }
        if (r1 == "" || r2 == "") exit
        per = (v1 - v2) / (r2 - r1)
        print v2 - (axr - 1 - r2) * per, v1 + (r1 - axtop) * per }' -v "title=$1"
}
for size in 80 120; do
    S=d$size
    up "$S" || continue
    wait_for 'Each swing is smaller' 5
    keys 2
    t0=$(now)
    wait_for 'You chose 2' 3
    # 2 s after the step began (its answer), as near as the capture allows
    while [ "$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print (b - a < 2.0) }')" = 1 ]; do sleep 0.02; done
    cap
    t=$(status_t) span=$(y_span 'Displacement')
    if awk -v t="$t" 'BEGIN { exit !(t != "" && t >= 1 && t <= 4) }' && has Running; then pass; else
        fail "$S: 2 s after the run 15 step began, t should have advanced 1 to 4 s; t = $t; screen: $(brief)"
    fi
    # the decay runs from 0.5 m to about -0.42 m: the axis covers it (to half a row)
    # and spans no more than twice its 0.92 m
    if echo "$span" | awk '{ exit !(NF == 2 && $2 >= 0.45 && $1 <= -0.37 && $2 - $1 <= 1.84) }'; then
        pass
    else
        fail "$S: the displacement axis should cover the 0.5 m decay within a factor of 2; it spans '$span'; screen: $(brief "$scr" '┤')"
    fi
    # space ends the run at once: t = 15 exactly, the step waiting
    keys Space
    if wait_all 5 "has_re 'Paused +t = 15\\.00 s' && has 'space goes on'"; then pass; else
        fail "$S: space should end the playing run at once (t = 15.00); screen: $(brief)"
    fi
done

# ---- bit for bit: a run ended by space, runs played out, a step gone back to ----
# each session started as its case comes, each key sent when the panel says what it does
start space 80 24 -- --lesson "$tmp/space.lesson"
S=space
if up space && wait_for 'space ends the run' 3; then
    keys Space   # the first run ends at once
    wait_for 'space goes on' 3
    keys Space   # the second plays out
    wait_for 'space ends the run' 3
    if wait_all 8 "has 'Lesson 2/3' && has 'space goes on'" && keys Space &&
        wait_for 'is the one recorded, bit for bit' 3; then pass; else
        fail "space: a run ended by space should end where the plain mode ends, bit for bit; screen: $(brief)"
    fi
fi
start played 80 24 -- --lesson "$tmp/played.lesson"
S=played
if up played && wait_for 'space ends the run' 3; then
    wait_for 'space goes on' 6
    keys Space
    wait_for 'space ends the run' 3
    if wait_all 6 "has 'Lesson 2/3' && has 'space goes on'" && keys Space &&
        wait_for 'is the one recorded, bit for bit' 3; then pass; else
        fail "played: runs played in real time should end where the plain mode ends, bit for bit; screen: $(brief)"
    fi
fi
start back 80 24 -- --lesson "$tmp/back.lesson"
S=back
if up back && wait_for 'space ends the run' 3; then
    keys Space   # both runs ended at once
    wait_for 'space goes on' 3
    keys Space
    wait_for 'space ends the run' 3
    keys Space
    wait_all 3 "has 'Lesson 2/3' && has 'space goes on'"
    keys ,       # back to the first step's end
    wait_for 'back to step 1 of 3' 3
    keys Space   # the second run again, ended at once
    wait_for 'space ends the run' 3
    keys Space
    wait_all 3 "has 'Lesson 2/3' && has 'space goes on'"
    keys Space
    if wait_for 'is the one recorded, bit for bit' 3; then pass; else
        fail "back: ',' should go back to the state the step left, bit for bit; screen: $(brief)"
    fi
fi

# ---- every caption line of every built-in lesson, on screen or behind ↓ more ----
# panel: the caption panel's text rows (between its frame's top, "Lesson" or "Replay",
# and its bottom edge), their borders taken off
panel() {
    awk '/^┌ +Lesson / { on = 1; next } on && /^└/ { exit } on { sub(/^│ ?/, ""); sub(/ *│$/, ""); print }' "$scr"
}
step_of() { sed -n 's/.*Lesson \([0-9]*\)\/.*/\1/p' "$scr" | head -n 1; }
# captions NAME COLS: plays the lesson in session cap-NAME-COLS, every step's panel (and
# what ↓ shows of it) into $tmp/seen-NAME-COLS; run in the background, one per session
captions() {
    S=${3:-cap}-$1-$2
    scr=$tmp/screen-$S
    seen=$tmp/seen-$1-$2
    [ -n "$3" ] || : >"$seen" # a second walk adds to what the first saw
    wait_for Controls 5 || return 1
    # playback at 0.1x: no run ends on its own between a look at the panel and the key
    # that ends it (the lesson's own speed lines aside)
    keys [ [ [ [ [
    i=0
    while [ $i -lt 80 ]; do
        i=$((i + 1))
        cap
        panel >>"$seen"
        if has 'space ends the run'; then keys Space; wait_gone 'space ends the run' 3; fi
        settle 2 has 'Lesson'
        panel >>"$seen"
        j=0
        while has '↓ more' && [ $j -lt 40 ]; do
            keys Down
            j=$((j + 1))
            settle 2 has Lesson
            panel >>"$seen"
        done
        has 'space or Esc closes' && break
        has 'Lesson' || break # closed: a run that ended as space came
        # the key that goes on is chosen on a fresh look: the panel and its ↓ took
        # seconds, and a run (at the lesson's own 10x or 50x) may have ended meanwhile,
        # making space close the lesson before its last caption was read; a run still
        # playing, or a lesson at its end, goes back to the top (space ends the run there
        # on a look just taken; the end's panel is read there)
        cap
        if has 'space ends the run' || has 'space or Esc closes'; then continue; fi
        st=$(step_of)
        if has ' answers '; then keys 1; else keys Space; fi
        wait_all 3 "[ \"\$(step_of)\" != '$st' ] || has 'space or Esc closes' || has 'space ends the run'"
    done
}
# six sessions at a time, one size after the other
for size in 80x24 60x20; do
    for f in "$root"/lessons/*.lesson; do
        n=$(basename "$f" .lesson)
        start "cap-$n-${size%x*}" "${size%x*}" "${size#*x}" -- --lesson "$n"
    done
    for f in "$root"/lessons/*.lesson; do
        captions "$(basename "$f" .lesson)" "${size%x*}" &
    done
    wait
done
# missing FILE SEEN: the words of FILE's say lines not in SEEN
missing() {
    sed -n 's/^[[:space:]]*say[[:space:]]\{1,\}//p' "$1" | tr ' ' '\n' | grep . |
        while IFS= read -r w; do grep -qF -- "$w" "$2" || printf '%s ' "$w"; done
}
# A walk can lose a caption to its own timing, not the program's: a lesson's own pace
# (jump at 10x, a sweep at 50x) may end a run between the walk's look and its key, and
# on an idle machine sometimes does. A lesson and size whose walk missed words is walked
# once more, in a new session; a word must still be seen in one of the two walks.
for size in 80x24 60x20; do
    for f in "$root"/lessons/*.lesson; do
        n=$(basename "$f" .lesson)
        [ -n "$(missing "$f" "$tmp/seen-$n-${size%x*}")" ] || continue
        start "again-$n-${size%x*}" "${size%x*}" "${size#*x}" -- --lesson "$n"
        captions "$n" "${size%x*}" again &
    done
    wait
done
for f in "$root"/lessons/*.lesson; do
    n=$(basename "$f" .lesson)
    for size in 80x24 60x20; do
        seen=$tmp/seen-$n-${size%x*}
        # every word of every say line was seen in the panel
        missing=$(missing "$f" "$seen")
        if [ -s "$seen" ] && [ -z "$missing" ]; then pass; else
            fail "$n at $size: every caption word should be on screen or behind ↓ more; missing: $missing"
        fi
    done
done
scr=$tmp/screen

# ---- a recording made with keys replays in about the time it took, bit for bit ----
start rec 80 24 -- -p resonance --record "$tmp/rec.lesson"
S=rec
if up rec; then
    r0=$(now)
    sleep 1
    keys Space
    sleep 2.5
    keys m
    sleep 1.5
    keys Space
    sleep 2
    keys ]
    keys Space
    sleep 2
    keys q
    poll 5 ended
    took=$(since "$r0")
    f=$tmp/rec.lesson
    if grep -q '^wait [0-9.]*$' "$f" && grep -q '^faster$' "$f" && grep -q '^expect t=' "$f"; then pass; else
        fail "rec: the recording should hold the waits, the keys and the state: $(sed -n '/^end/,$p' "$f" | tr '\n' '|')"
    fi
    p0=$(now)
    "$SPRINGSIM" --plain --replay "$f" </dev/null >"$tmp/replay.out" 2>&1
    pt=$(since "$p0")
    if grep -q 'is the one recorded, bit for bit' "$tmp/replay.out" &&
        awk -v t="$pt" -v s="${SANITIZED:-no}" 'BEGIN { exit !(t < (s == "yes" ? 5 : 1)) }'; then pass; else
        fail "rec: --plain --replay should end bit for bit in under a second; took $pt s: $(tail -n 2 "$tmp/replay.out" | tr '\n' '|')"
    fi
    start replay 80 24 -- --replay "$f"
    S=replay
    up replay
    p0=$(now)
    wait_all 30 "has 'is the one recorded, bit for bit'"
    pt=$(since "$p0")
    if has 'is the one recorded, bit for bit' &&
        awk -v t="$pt" -v r="$took" 'BEGIN { exit !(t >= 0.8 * r && t <= 1.2 * r) }'; then pass; else
        fail "replay: in the program it should take about the recorded $took s (±20 %) and end bit for bit; took $pt s; screen: $(brief)"
    fi
    # space pauses a replay (t stands), space plays on, '.' skips to the next command
    start replay2 80 24 -- --replay "$f"
    S=replay2
    up replay2
    wait_for Running 5
    keys Space
    if wait_for 'replay paused' 3 && t1=$(settled_t) && sleep 1 && cap && [ "$(status_t)" = "$t1" ] &&
        has 'Replay (paused)'; then pass; else
        fail "replay2: space should pause the replay (t stands); screen: $(brief)"
    fi
    # more dots than the recording has commands: those past its end change nothing
    keys Space . . . . . . . . . . . .
    if wait_for 'is the one recorded, bit for bit' 5 && sleep 0.5 && cap &&
        has 'is the one recorded, bit for bit'; then pass; else
        fail "replay2: '.' should skip to the end, and a '.' past it change nothing; screen: $(brief)"
    fi
fi

# ---- a lesson's runs are bounded; the dry run of the longest is left by Esc ----
"$SPRINGSIM" --plain --lesson "$tmp/long.lesson" </dev/null >"$tmp/long.out" 2>"$tmp/long.err"
rc=$?
if [ $rc -eq 2 ] && grep -q "^springsim: $tmp/long.lesson:5: run 801: .*1800 s (30 minutes)" "$tmp/long.err" &&
    [ "$(wc -l <"$tmp/long.err")" -eq 1 ] && [ ! -s "$tmp/long.out" ]; then pass; else
    fail "a lesson of 1801 simulated seconds should be refused with FILE:5, exit 2; exit $rc: $(cat "$tmp/long.err")"
fi
# how long a key takes to end the program here and now (tmux's delivery, the machine's
# load): the same program idle, quit with q; the dry run's Esc may take 0.2 s more
gone_after() { # gone_after SESSION KEY: seconds from the key to the program's end
    S=$1
    ga0=$(now)
    keys "$2"
    n=0
    while alive "$1" && [ $n -lt 500 ]; do sleep 0.01; n=$((n + 1)); done
    since "$ga0"
}
start idle 80 24 -- -p resonance
up idle
base=$(gone_after idle q)
start longest 80 24 -- --lesson "$tmp/longest.lesson"
# the check takes about 0.45 s on a quiet machine: the key goes 0.1 s after the program
# starts, inside it (a key typed before the terminal turns raw is kept for it too)
n=0
while ! alive longest && [ $n -lt 500 ]; do sleep 0.01; n=$((n + 1)); done
sleep 0.1
el=$(gone_after longest Escape)
S=longest # gone_after ran in a subshell
poll 3 ended
if ended && has 'EXITED 1' && has 'the check was left' && has 'TERMINAL SAME' &&
    awk -v t="$el" -v b="$base" -v s="${SANITIZED:-no}" 'BEGIN { exit !(t < b + (s == "yes" ? 0.6 : 0.2)) }'; then pass; else
    fail "longest: Esc should leave the dry run (exit 1, said) within 0.2 s of an idle q; took $el s, idle q $base s; screen: $(brief)"
fi

summary
