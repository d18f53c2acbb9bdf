#!/bin/sh
# tests/tui-cursors.sh: the time cursors, their readout and the measurements in a real
# terminal (tmux), at 80x24 and 120x40: a free decay of one mass (k = 10 N/m each side,
# m = 1 kg, c = 0.1 N s/m, so zeta = c / (2 sqrt(2 k m)) = 0.01118) measured on screen;
# the readout's numbers are the exported CSV's at the cursor's time, to the digits shown;
# the cursor's keys come first only while it is shown; paused, the window scrolls back and
# running again shows the present; nothing in the readout is cut but with "…". Run from
# the repository root as `sh tests/tui-cursors.sh`, SPRINGSIM naming the binary. The
# measurements name the motion: a free decay with its zeta, driven beats transient with
# none, the default chain's steady state beside the theory's. Ends with
# "tui-cursors: N passed, M failed".
NAME=tui-cursors
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

DECAY="--masses 1 --boundary wall --x0 0.5 --amplitude 0 --no-collisions"
mkdir -p "$tmp/d80"
# shellcheck disable=SC2086
start_in "$tmp/d80" d80 80 24 -- $DECAY
start c120 120 40 -- -p 3-mass-chain
start n10 80 24 -- --masses 10 --amplitude 0.3
start fresh 80 24
start beat80 80 24 -- -p beating
start steady120 120 40
for s in d80 c120; do if up $s; then keys Space; fi; done
for s in beat80 steady120; do # at 10x (the Speed control)
    if up $s; then keys Up Up Up Right Right Right Right; wait_re '▸Speed +10x' 3 && keys Space; fi
done

# panel: the readout's rows (right of the plots, inside its frame), one per line
panel() { LC_ALL=$U8 sed "s/^.\{$(($1 - 1))\}//" "$scr" | sed -n '/┌ Cursor/,/└/p'; }
# value LABEL: the number after "LABEL " in the readout ("t 7.03 s" -> 7.03)
value() { panel "$1" | sed -n "s/.*│$2 \\([-0-9.e+]*\\) .*/\\1/p" | head -n 1; }
# agrees SCREEN CSV: the screen's number is the CSV's rounded to the digits it shows
agrees() {
    awk -v s="$1" -v c="$2" 'BEGIN {
        m = s; sub(/^-/, "", m); sub(/e.*/, "", m); gsub(/\./, "", m); sub(/^0+/, "", m)
        d = length(m); if (d < 1) d = 1
        exit !(sprintf("%." d "g", c) == s) }'
}

# ---- 80x24: a free decay measured ----
if up d80; then
    wait_t 12 20
    keys Space
    t0=$(settled_t)
    keys 1 '|'
    if settle_for '┌ Cursor ' 3 && has 'measured: mass 1' && has_re 'T 1\.4[0-9]* s  f 0\.71[0-9]* Hz' &&
        has 'free decay: peaks falling' && has 'theory ζ 0.01118 (mode 1)'; then pass; else
        fail "80x24: | should show the readout naming a free decay, with T, f and the theory's zeta; screen: $(brief "$scr" 'Cursor|measured|decay|T |ζ')"
    fi
    # zeta from the decrement within 2 % of c / (2 sqrt(k_eff m))
    z=$(sed -n 's/.*δ [-0-9.e]*  ζ \([-0-9.e]*\).*/\1/p' "$scr" | head -n 1)
    if awk -v z="$z" 'BEGIN { w = 0.1 / (2 * sqrt(20)); exit !(z != "" && (z - w) / w < 0.02 && (w - z) / w < 0.02) }'; then
        pass
    else
        fail "80x24: measured zeta '$z' should be within 2 % of 0.01118; screen: $(brief "$scr" 'ζ')"
    fi
    # nothing cut: every readout row inside its frame, no "…" for one mass
    if [ "$(panel 47 | grep -c '^│.*│$')" -eq "$(panel 47 | grep -c '^│')" ] &&
        ! panel 47 | grep -q '…' &&
        panel 47 | grep -qE '│1 +-?[0-9.e-]+ +-?[0-9.e-]+ +-?[0-9.e-]+│'; then pass; else
        fail "80x24: the readout should fit its frame whole; panel: $(panel 47 | tr '\n' '|')"
    fi
    # ← moves the cursor, not the control selected (Preset: it would load another)
    tc=$(value 47 t)
    keys Left Left Left Left Left
    if settle 3 eval '[ "$(value 47 t)" != "$tc" ]' &&
        awk -v a="$(value 47 t)" -v b="$tc" 'BEGIN { d = b - a; exit !(d > 0.0499 && d < 0.0501) }' &&
        [ "$(status_t)" = "$t0" ] && lacks 'Preset'; then pass; else
        fail "80x24: five ← should move the cursor 0.05 s back (from $tc), t staying $t0; screen: $(brief "$scr" 'Cursor|t ')"
    fi
    # the readout is the exported CSV at the cursor's time, to the digits shown
    keys x
    if settle_for 'exported ' 5; then
        csv=$(ls "$tmp/d80"/springsim-*.csv 2>/dev/null | head -n 1)
        t=$(value 47 t)
        row=$(awk -F, -v t="$t" 'NR > 1 && !/^#/ && $1 + 0 > t - 1e-9 && $1 + 0 < t + 1e-9' "$csv")
        set -- $(panel 47 | sed -n 's/^│1 *\([^ ]*\) *\([^ ]*\) *\([^│ ]*\)│$/\1 \2 \3/p')
        x=$1 v=$2 a=$3
        u=$(panel 47 | sed -n 's/^│u *\([^ │]*\).*/\1/p')
        cx=$(echo "$row" | cut -d, -f2) cv=$(echo "$row" | cut -d, -f3)
        ca=$(echo "$row" | cut -d, -f4) cu=$(echo "$row" | cut -d, -f5)
        if [ -n "$row" ] && agrees "$x" "$cx" && agrees "$v" "$cv" && agrees "$a" "$ca" &&
            agrees "$u" "$cu"; then pass; else
            fail "80x24: readout at t=$t (x $x, v $v, a $a, u $u) should be the CSV's row '$row'"
        fi
    else
        fail "80x24: x should export the samples; screen: $(brief)"
    fi
    # a second cursor a tenth of the window on: Δt 1 s, 1/Δt 1 Hz, Δx
    keys '|'
    if settle_for '┌ Cursors ' 3 && has_re 'Δt 1 s  1/Δt 1 Hz' && has 'Δx'; then pass; else
        fail "80x24: | again should add a second cursor (Δt 1 s, 1/Δt 1 Hz, Δx); screen: $(brief "$scr" 'Cursor|Δ')"
    fi
    # paused, PgUp scrolls back a window and says so; running again shows the present
    keys PgUp
    if settle_re 'shown 0\.0–10\.0 s, [0-9.]+ s back' 3; then pass; else
        fail "80x24: PgUp should show the window a window back; screen: $(brief "$scr" 'shown')"
    fi
    keys Space
    if wait_re 'shown [0-9.]+–[0-9.]+ s, live' 3; then pass; else
        fail "80x24: running again should show the present (live); screen: $(brief "$scr" 'shown')"
    fi
    keys Space Escape
    if settle_all 3 "has '┌ Controls' && lacks Cursor"; then pass; else
        fail "80x24: Esc should remove the cursors and give the controls back; screen: $(brief)"
    fi
    keys '|'
    wait_for '┌ Cursor ' 3
    keys '|' '|'
    if wait_for '┌ Controls' 3; then pass; else
        fail "80x24: | a third time should remove the cursors; screen: $(brief)"
    fi
    cp "$scr" "$tmp/d80.txt"
fi

# ---- 120x40: two cursors on all six plots, three masses ----
if up c120; then
    wait_t 8 20
    keys Space
    t0=$(settled_t)
    keys '|' '|'
    if settle_for '┌ Cursors ' 3; then
        rows=$(panel 83)
        if echo "$rows" | grep -qE '^│1 ' && echo "$rows" | grep -qE '^│2 ' &&
            echo "$rows" | grep -qE '^│3 ' && echo "$rows" | grep -qE '^│u ' &&
            echo "$rows" | grep -q 'measured: mass 1' && ! echo "$rows" | grep -q '…' &&
            [ "$(echo "$rows" | grep -c '^│.*│$')" -eq "$(echo "$rows" | grep -c '^│')" ]; then pass; else
            fail "120x40: the readout should show masses 1-3, u and the measurements whole; panel: $(echo "$rows" | tr '\n' '|')"
        fi
        # the phase portraits mark each mass's point at each cursor
        if has '6 v–a' && [ "$(grep -o '●' "$scr" | wc -l)" -ge 3 ] &&
            [ "$(grep -o '◆' "$scr" | wc -l)" -ge 3 ]; then pass; else
            fail "120x40: the phase portraits should mark the points at both cursors (● ◆); screen: $(brief "$scr" '●|◆')"
        fi
        keys Down
        if settle_for 'measured: mass 2' 3; then pass; else
            fail "120x40: ↓ should measure mass 2; screen: $(brief "$scr" 'measured')"
        fi
    else
        fail "120x40: | | should show two cursors; screen: $(brief)"
    fi
fi

# ---- 80x24, ten masses: the rows that do not fit say so ----
if up n10; then
    keys '|'
    if settle_for '┌ Cursor ' 3 && has_re '… [0-9]+ more masses' && has 'measured: mass 1' &&
        has 'not enough peaks (0)'; then pass; else
        fail "80x24, 10 masses: the readout should end its mass rows with '… N more masses' and keep the measurements; screen: $(brief "$scr" 'more|measured|peaks')"
    fi
fi

# ---- driven motion named, no zeta (issue 27): beats after 30 s, a steady state ----
S=beat80
if wait_t 30 15; then
    keys Space 1 '|'
    if settle_for '┌ Cursor ' 3 && has 'transient: peaks' && has 'not a free decay, not steady' &&
        lacks 'ζ'; then pass; else
        fail "80x24 -p beating after 30 s: the readout should name the motion transient and say no zeta (it said 'ζ -0.0545'); screen: $(brief "$scr" 'Cursor|measured|transient|steady|ζ')"
    fi
else
    fail "80x24 -p beating: expected it to run to t = 30 s at 10x; screen: $(brief)"
fi
# the default chain at 1 Hz, past 200 s (2m/c = 20 s): mass 1's steady swing and the
# theory's (--sweep's), agreeing to 0.1 %
S=steady120
if wait_t 200 40; then
    keys Space '|'
    amp=$("$SPRINGSIM" --sweep 1:2:2 | awk -F, 'NR == 2 { print $2 }')
    if settle_for 'driven steady state (±1 %)' 3 && has_re 'phase ° +-?[0-9.]+ +-?[0-9.]+' &&
        lacks 'ζ'; then
        row=$(sed -n 's/.*│amp m *\([0-9.e-]*\) *\([0-9.e-]*\) *│.*/\1 \2/p' "$scr" | head -n 1)
        if [ -n "$row" ] && awk -v r="$row" -v a="$amp" 'BEGIN { split(r, v, " ")
            exit !((v[1] - a) ^ 2 <= (1e-3 * a) ^ 2 && (v[2] - a) ^ 2 <= (1e-3 * a) ^ 2) }'; then
            pass
        else
            fail "120x40, default chain after 200 s: mass 1's amplitude and the theory's should both be $amp m (--sweep) within 0.1 %, read '$row'"
        fi
    else
        fail "120x40, default chain after 200 s: the readout should name a driven steady state with the phase beside the theory's and no zeta; screen: $(brief "$scr" 'Cursor|steady|amp|phase|ratio|ζ')"
    fi
else
    fail "120x40: expected the default chain to run to t = 200 s at 10x; screen: $(brief)"
fi

# ---- no cursor: the arrows are the controls' ----
if up fresh; then
    keys Down Down Down Down Down Down Down Down Down Down
    wait_re '▸Frequency' 3
    keys Right
    if settle_all 3 "has_re 'Frequency +1\.010? Hz' && lacks Cursor"; then pass; else
        fail "no cursor: → should adjust the selected control; screen: $(brief "$scr" 'Frequency')"
    fi
fi

summary
