#!/bin/sh
# tests/tui-plots.sh: the plots and the scene as a person reads them (springsim(1), INTERACTIVE PROGRAM,
# issue 9), in a real terminal (tmux): 1..6 enlarge one plot (big enough to read, the
# resonance's oscillations distinct), the same digit or 0 give the grid back, < and >
# change the time window (the beating preset and --window choose the one at start), the
# time axis reads absolute t, the latest at the right, also scrolled back; at 60x20 every
# plot shown carries data; tick labels are whole
# numbers falling evenly and gridlines evenly spaced in every plot at every size, also
# with accelerations of 1e4; mass labels 1..10 in full, on the springs' row whatever the
# masses. Run from the repository root as `sh tests/tui-plots.sh`, SPRINGSIM naming the
# binary. Ends with "tui-plots: N passed, M failed".
NAME=tui-plots
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

TITLES='1 Displacement (m)|2 Velocity (m/s)|3 Acceleration (m/s²)|4 x–v (m, m/s)|5 x–a (m, m/s²)|6 v–a (m/s, m/s²)'
title() { echo "$TITLES" | cut -d'|' -f"$1"; } # title DIGIT
# the plot titles on the screen, one per line ("1 Displacement (m)")
titles() { sed -n 's/.*┌─* \([1-6] [^─]*[^ ─]\) ─.*/\1/p' "$scr"; sed -n 's/.*┐┌─* \([1-6] [^─]*[^ ─]\) ─.*/\1/p' "$scr"; }
shown() { grep -oE '┌─* [1-6] ' "$scr" | sed 's/[^1-6]//g' | tr -d '\n'; } # digits shown, "14"
shown_is() { [ "$(shown)" = "$1" ]; }
# area_at_least TITLE COLS ROWS: the plot's drawing area (plot_area) is at least that
area_at_least() { aa=$(plot_area "$1"); [ -n "$aa" ] && [ "${aa% *}" -ge "$2" ] && [ "${aa#* }" -ge "$3" ]; }
# x_window W [TITLE]: the time axis of the plot TITLE (default $t1) is a window of W s in
# absolute time: its labels evenly spaced, spread over W s give or take a tick (the axis
# rounds W out to its ticks), none below 0; the steps even to within the rounding of
# the labels (44.8 - 44.6 and 45.0 - 44.8 differ in binary)
x_window() {
    xlabels "${2:-$t1}" | awk -v w="$1" '{ v[n++] = $1 + 0 }
        END { if (n < 2) exit 1; step = v[1] - v[0]; spread = v[n - 1] - v[0]
              for (k = 1; k < n; k++) { d = v[k] - v[k - 1] - step; if (d > 1e-9 || d < -1e-9) exit 1 }
              exit !(v[0] >= 0 && spread <= w + step - 1e-9 && spread > w - 2 * step) }'
}
# x_ends T [TITLE]: the time axis's last label is within a tick below T (s) (or half a
# cell above it): the latest time at the right
x_ends() {
    xlabels "${2:-$t1}" | awk -v t="$1" '{ v[n++] = $1 + 0 }
        END { if (n < 2) exit 1; step = v[1] - v[0]; exit !(v[n - 1] < t + step / 4 && v[n - 1] > t - step) }'
}
# axis_says: what the time axis of $t1 reads, for a failure message
axis_says() { xlabels "${1:-$t1}" | tr '\n' ' '; }
# xlabels TITLE: the numbers under the x axis of the plot titled TITLE
xlabels() {
    plot_awk 'END { if (plot(title)) { s = ""; for (k = left + 1; k < right; k++) s = s cell(axr + 1, k); print s } }' \
        -v "title=$1" | tr -s ' ' '\n' | grep -E '^-?[0-9]'
}
# ticks_good: the y axes of every plot on the screen are right (plot_ticks); what is
# wrong in $to_bad
ticks_good() {
    to_bad=
    for d in $(shown | sed 's/./& /g'); do
        b=$(plot_ticks "$(title "$d")")
        [ -n "$b" ] && to_bad="$to_bad $b"
    done
    [ -n "$(shown)" ] && [ -z "$to_bad" ]
}
# ticks_ok WHAT: ticks_good, on a screen captured whole (a frame being drawn may be
# captured half-way, so a running screen is looked at again for up to a second)
ticks_ok() {
    if poll 1 ticks_good; then pass; else
        fail "$1: tick labels or gridlines wrong:${to_bad:- no plot on screen}"
    fi
}

# labels WHAT N: the scene (rows between "┌ Chain" and its bottom) shows the labels 1..N
# once each, all on the row of the springs and the motor's rod (the one with MOTOR).
labels() {
    rows=$(awk '/^┌ Chain/ { on = 1; next } on && /^└/ { exit } on { print NR ": " $0 }' "$scr")
    motor=$(printf '%s\n' "$rows" | grep 'MOTOR' | cut -d: -f1)
    # a label: a run of digits (nothing else in the scene has any)
    found=$(printf '%s\n' "$rows" | while IFS= read -r l; do
        r=${l%%:*}
        printf '%s\n' "${l#*: }" | grep -oE '[0-9]+' | sed "s/^/$r /"
    done)
    want=$(seq "$2" | tr '\n' ' ')
    got=$(printf '%s\n' "$found" | awk '{ print $2 }' | sort -n | tr '\n' ' ')
    off=$(printf '%s\n' "$found" | awk -v m="$motor" '$1 != m { printf " %s (row %s)", $2, $1 }')
    if [ -n "$motor" ] && [ "$got" = "$want" ] && [ -z "$off" ]; then pass; else
        fail "$1: expected the mass labels $want once each on the scene's row $motor (the springs' and motor's); found: $got; off that row:$off; scene: $(printf '%s\n' "$rows" | cut -c 1-100 | tr '\n' '|')"
    fi
}

# ---- the checks themselves: on screens known to be wrong, they fail ----
# (made by hand from what issue 9 saw: labels cut to -1000 where -10000 was meant,
# gridlines two rows then three apart, a trace that is a solid block, a light mass's
# label below the springs)
cat >"$tmp/wrong" <<'WRONG'
┌─── 3 Acceleration (m/s²) ───┐┌── 1 Displacement (m) ──┐
│  20000┤· · · · · · · · · · ·││    1.0┤⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿│
│       │                     ││       │⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿│
│  10000┤· · · · · · · · · · ·││    0.0┤⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿│
│       │                     ││       │⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿│
│      0┤─────────────────────││   -1.0┤⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿⣿│
│       │                     ││       └┬──────┬──────┬─│
│       │                     ││ s     -10    -5      0 │
│  -1000┤· · · · · · · · · · ·│└────────────────────────┘
│       │                     │
│  -2000┤· · · · · · · · · · ·│
│       └┬─────────┬─────────┬│
│ s     -10       -5         0│
└─━1──────────────────────────┘
WRONG
cat >"$tmp/right" <<'RIGHT'
┌─── 3 Acceleration (m/s²) ───┐┌──────── 1 Displacement (m) ─────────┐
│    2e4┤· · · · · · · · · · ·││    1.0┤  ⢀⡀    ⢀⡀    ⢀⡀    ⢀⡀    ⢀⡀ │
│       │                     ││       │ ⡜ ⢣   ⡜ ⢣   ⡜ ⢣   ⡜ ⢣   ⡜ ⢣ │
│    1e4┤· · · · · · · · · · ·││    0.0┤⡜   ⢣ ⡜   ⢣ ⡜   ⢣ ⡜   ⢣ ⡜   ⢣│
│       │                     ││       │     ⠙     ⠙     ⠙     ⠙     │
│      0┤─────────────────────││   -1.0┤                             │
│       │                     ││       └┬──────┬──────┬─────────────│
│ -10000┤· · · · · · · · · · ·││ s     -10    -5      0             │
│       │                     │└─────────────────────────────────────┘
│ -20000┤· · · · · · · · · · ·│
│       └┬─────────┬─────────┬│
│ s     -10       -5         0│
└─━1──────────────────────────┘
RIGHT
cat >"$tmp/scene" <<'SCENE'
┌ Chain ───────────────────────────────────────────────────────────────────────┐
│▓▓⢠ ⡄⡄⢠ ⡄⡄⢠⢠ ⡄⢠  ⢠ ⡄⡄⡄⢠⢠⢠ ⡄▁▁▁⢠ ⡄⡄⡄⢠⢠⢠ ⡄▋█▋⡄⢠ ⡄⡄⢠ ⡄⡄⢠ ▌▏              ┌───────┐│
│▓▓⠃⢧⢳⠏⡞⢧⢳⠏⡞⢧⢳    ⠋⡾⢱⢳⢳⠏⡞⡞⡾⢱▊2▊⠋⡾⢱⢳⢳⠏⡞⡞⡾⢱▋3▋⠸⡜⡾⢱⠻⡜⡾⢱⠻⡜⡾▌▏══════════════┤MOTOR ●││
│▓▓ ⠈⠈ ⠁⠈⠈ ⠁⠈⠈▉1▉ ⠁⠈⠈⠈ ⠁⠁⠁⠈▇▇▇ ⠁⠈⠈⠈ ⠁⠁⠁⠈▋█▋ ⠁⠁⠈ ⠁⠁⠈ ⠁⠁▌▏              └───────┘│
└──────────────────────────────────────────────────────────────────────────────┘
SCENE
PLOT_SCR=$tmp/wrong
b=$(plot_ticks '3 Acceleration (m/s²)')
case $b in *"not evenly spaced"*"do not fall evenly"*) pass ;;
*) fail "self-check: plot_ticks should find the cut labels and the uneven gridlines of a wrong screen, found: '$b'" ;;
esac
b=$(plot_peaks '1 Displacement (m)')
if [ "$b" -eq 0 ]; then pass; else fail "self-check: plot_peaks should count no peak in a solid block, counted $b"; fi
PLOT_SCR=$tmp/right
b=$(plot_peaks '1 Displacement (m)')
if [ "$b" -eq 5 ]; then pass; else fail "self-check: plot_peaks should count the 5 peaks of a drawn sine, counted $b"; fi
set -- $(plot_area '1 Displacement (m)')
if [ "$*" = "29 5" ]; then pass; else fail "self-check: plot_area should measure 29x5 cells, measured '$*'"; fi
b=$(plot_ticks '3 Acceleration (m/s²)')$(plot_ticks '1 Displacement (m)')
if [ -z "$b" ]; then pass; else fail "self-check: plot_ticks should accept a right screen, says '$b'"; fi
# the time axis counting back from now (-10 .. 0) is not a window in absolute time
if ! x_window 10 '1 Displacement (m)'; then pass; else
    fail "self-check: x_window should refuse the axis -10 -5 0, read '$(axis_says '1 Displacement (m)')'"
fi
PLOT_SCR=
cp "$tmp/scene" "$scr"
labels_out=$(labels "a light mass drawn below its springs" 3)
case $labels_out in *"FAIL: "*"1 (row 4)"*) pass ;;
*) fail "self-check: labels should find mass 1's label below the springs' row, says '$labels_out'" ;;
esac

start res80 80 24 -- -p resonance
start big 120 40
start huge 160 48
start small 60 20
start acc 120 40 -- -n 1 --spring 50 --mass 0.1 --amplitude 3
start acc80 80 24 -- -n 1 --mass 0.1 --spring 500 --dt 0.002 --frequency 16 --amplitude 1
start acc120 120 40 -- -n 1 --mass 0.1 --spring 500 --dt 0.002 --frequency 16 --amplitude 1
start acc60 60 20 -- -n 1 --mass 0.1 --spring 500 --dt 0.002 --frequency 16 --amplitude 1
start ten 120 40 -- -n 10
start ten80 80 24 -- -n 10
start light 120 40 -- -n 3 --mass 0.2,1,5
start light80 80 24 -- -n 3 --mass 0.2,1,5
start beat80 80 24 -- -p beating
start win80 80 24 -- --window 2
start abs80 80 24
start abs120 120 40
start fit80 80 24
sessions="res80 big huge small acc acc80 acc120 acc60 ten ten80 light light80"
for s in res80 big huge small acc acc80 acc120 acc60; do
    if up $s; then keys Space; fi
done

# ---- mass labels: 1..10 in full, all on the springs' row ----
if up ten; then labels "-n 10 at 120x40" 10; fi
if up ten80; then labels "-n 10 at 80x24" 10; fi
if up light; then labels "-n 3 --mass 0.2,1,5 at 120x40" 3; fi
if up light80; then labels "-n 3 --mass 0.2,1,5 at 80x24" 3; fi

# ---- the grid and each plot enlarged at 120x40: sizes, titles, back ----
if up big; then
    if [ "$(shown)" = 123456 ]; then pass; else
        fail "120x40: expected the six plots 1..6 in the grid, shown: '$(shown)'; screen: $(brief "$scr" '┌─* [1-6] ')"
    fi
    for d in 1 2 3 4 5 6; do
        t=$(title "$d")
        keys "$d"
        if ! poll 3 shown_is "$d" || lacks " $t "; then
            fail "120x40: $d should enlarge the plot '$t' alone; shown: '$(shown)'; screen: $(brief "$scr" '┌─* [1-6] ')"
            keys 0
            wait_re '┌─* 6 ' 3
            continue
        fi
        if wait_all 1 "area_at_least '$t' 70 24 && has Controls"; then pass; else
            fail "120x40: plot $d enlarged should draw on at least 70x24 cells beside the controls, has '$(plot_area "$t")'; screen: $(brief "$scr" '┌─* [1-6] ')"
        fi
        case $d in 1 | 2 | 3)
            if poll 1 x_window 10 "$t"; then pass; else
                fail "120x40: plot $d's time axis should be a window of 10 s in absolute time, reads '$(axis_says "$t")'"
            fi
            ;;
        esac
        ticks_ok "120x40, plot $d enlarged"
        keys "$d" # the same digit: the grid again
        if poll 3 shown_is 123456; then pass; else
            fail "120x40: $d again should give the grid of six back; shown: '$(shown)'; screen: $(brief "$scr" '┌─* [1-6] ')"
        fi
    done
    ticks_ok "120x40 grid (running)"
fi
if up huge; then
    if [ "$(shown)" = 123456 ]; then pass; else
        fail "160x48: expected the six plots 1..6 in the grid, shown: '$(shown)'"
    fi
    wait_t 1
    ticks_ok "160x48 grid"
fi

# ---- 60x20: every plot shown carries data ----
S=small
if wait_t 3; then
    # dots WHAT: each plot shown has braille dots (10 cells or more)
    dots_good() {
        empty=
        for d in $(shown | sed 's/./& /g'); do
            n=$(plot_dots "$(title "$d")")
            [ "$n" -ge 10 ] || empty="$empty '$(title "$d")' ($n cells with dots)"
        done
        [ -n "$(shown)" ] && [ -z "$empty" ]
    }
    dots() {
        if poll 1 dots_good; then pass; else
            fail "60x20 ($1): every plot shown should carry data after 3 s; empty:${empty:- no plot shown}; screen: $(brief "$scr" '┌─* [1-6] ')"
        fi
    }
    dots grid
    ticks_ok "60x20 grid"
    for d in 2 3 4 5 6; do
        keys "$d"
        if poll 3 shown_is "$d"; then
            dots "plot $d enlarged"
            ticks_ok "60x20, plot $d enlarged"
        else
            fail "60x20: $d should enlarge plot $d; screen: $(brief "$scr" '┌─* [1-6] ')"
        fi
    done
    keys 0
    if wait_all 3 "shown_is 1 && lacks '0 all plots'"; then pass; else
        fail "60x20: 0 should give the grid back; screen: $(brief)"
    fi
else
    fail "60x20: expected it to run to t = 3 s; screen: $(brief)"
fi

# ---- tick labels whole and falling evenly, with large accelerations ----
S=acc
if wait_t 3; then
    ticks_ok "-n 1 --spring 50 --mass 0.1 --amplitude 3 at 120x40"
fi
for s in acc120 acc80 acc60; do
    S=$s
    case $s in acc120) size=120x40 ;; acc80) size=80x24 ;; acc60) size=60x20 ;; esac
    what="a 16 Hz drive of a 0.1 kg mass on 500 N/m springs at $size"
    if ! wait_t 2; then
        fail "$what: expected it to run to t = 2 s; screen: $(brief)"
        continue
    fi
    keys Space
    wait_for Paused
    ticks_ok "$what, the grid"
    for d in 3 6; do
        keys "$d"
        if poll 3 shown_is "$d"; then
            ticks_ok "$what, plot $d enlarged"
            # the labels reach 1e4 (the check above had long labels to look at)
            big=$(plot_awk 'END { if (plot(title)) for (r = axtop; r < axr; r++) { v = label(r) + 0; if (v < 0) v = -v; if (v > m) m = v } print m + 0 }' \
                -v "title=$(title "$d")")
            if [ "$big" -ge 10000 ]; then pass; else
                fail "$what: plot $d's labels should reach 1e4 m/s², the largest is $big"
            fi
        else
            fail "$what: $d should enlarge plot $d; screen: $(brief "$scr" '┌─* [1-6] ')"
        fi
    done
    keys 0
    wait_gone '0 all plots' 3
done

# ---- 80x24, -p resonance after 10 s: 1 enlarges x(t), readable; < >; 0 ----
S=res80
if wait_t 10 14; then
    t1=$(title 1)
    if [ "$(shown)" = 14 ]; then pass; else
        fail "80x24: the grid should show x(t) and x–v (1 and 4), shows '$(shown)'; screen: $(brief "$scr" '┌─* [1-6] ')"
    fi
    ticks_ok "80x24 grid, -p resonance"
    keys 1
    if wait_all 3 "has '0 all plots' && shown_is 1 && has ' $t1 '"; then
        pass
        if poll 1 area_at_least "$t1" 40 12; then pass; else
            fail "80x24: plot 1 enlarged should draw on at least 40x12 cells, has '$(plot_area "$t1")'; screen: $(brief "$scr" '┌─* [1-6] ')"
        fi
        if poll 1 eval '[ "$(plot_peaks "$t1")" -ge 4 ]'; then pass; else
            fail "80x24: -p resonance after 10 s, plot 1 enlarged should show distinct oscillations (4 or more peaks), counted $(plot_peaks "$t1")"
            sed 's/^/    /' "$scr"
        fi
        ticks_ok "80x24, plot 1 enlarged"
        if x_window 10; then pass; else fail "80x24: the time axis should be a window of 10 s, reads '$(axis_says)'"; fi
        keys '>'
        if poll 3 x_window 20; then pass; else
            fail "80x24: > should make the time window 20 s, reads '$(axis_says)'"
        fi
        keys '<' '<'
        if poll 3 x_window 5; then pass; else
            fail "80x24: < twice from 20 s should make the window 5 s, reads '$(axis_says)'"
        fi
        keys '<' '<' '<'
        if poll 3 x_window 1; then pass; else
            fail "80x24: < from 5 s should go down to 1 s and stop there, reads '$(axis_says)'"
        fi
        keys '>' '>' '>' '>' '>' '>' '>'
        if poll 3 x_window 60; then pass; else
            fail "80x24: > from 1 s should go up to 60 s and stop there, reads '$(axis_says)'"
        fi
        keys 0
        if poll 3 shown_is 14; then pass; else
            fail "80x24: 0 should give the grid back (1 and 4); shown: '$(shown)'; screen: $(brief "$scr" '┌─* [1-6] ')"
        fi
        for d in 2 3 4 5 6; do
            keys "$d"
            t=$(title "$d")
            if wait_all 3 "shown_is '$d' && has ' $t '"; then
                if poll 1 area_at_least "$t" 40 12; then pass; else
                    fail "80x24: plot $d enlarged should draw on at least 40x12 cells, has '$(plot_area "$t")'"
                fi
                ticks_ok "80x24, plot $d enlarged, 60 s window"
            else
                fail "80x24: $d should enlarge the plot '$t' alone; shown: '$(shown)'; screen: $(brief "$scr" '┌─* [1-6] ')"
            fi
        done
        keys 6
        if poll 3 shown_is 14; then pass; else
            fail "80x24: 6 again should give the grid back; shown: '$(shown)'"
        fi
    else
        fail "80x24: 1 should enlarge '$t1' alone (and the footer offer '0 all plots'); shown: '$(shown)'; screen: $(brief "$scr" '┌─* [1-6] ')"
    fi
else
    fail "80x24 -p resonance: expected it to run to t = 10 s; screen: $(brief)"
fi

# ---- one time axis: absolute t (issue 27), the latest at the right, also scrolled back
# (after 25 s with a 10 s window the labels run from about 15 to 25) ----
for S in abs80 abs120; do
    keys Up Up Up Right Right Right Right # the Speed control: 10x
    if wait_re '▸Speed +10x' 3; then keys Space; else fail "$S: the Speed control should reach 10x; screen: $(brief "$scr" Speed)"; fi
done
for S in abs80 abs120; do
    if ! wait_t 25 10; then
        fail "$S: expected it to run to t = 25 s at 10x; screen: $(brief)"
        continue
    fi
    keys Space 1
    if ! poll 3 eval 'has Paused && has "0 all plots" && steady'; then
        fail "$S: space and 1 should pause with x(t) enlarged; screen: $(brief)"
        continue
    fi
    t=$(status_t)
    if x_window 10 && x_ends "$t"; then pass; else
        fail "$S: paused at t = $t s, the time axis should run over the last 10 s (about $(awk -v t="$t" 'BEGIN { print int(t - 10) }') to $t), reads '$(axis_says)'"
    fi
    keys '|' PgUp
    if poll 3 eval 'has_re "shown [0-9.]+–[0-9.]+ s, 10.0 s back"'; then
        back=$(sed -n 's/.*shown [0-9.]*–\([0-9.]*\) s, 10.0 s back.*/\1/p' "$scr" | head -n 1)
        if poll 2 eval 'x_window 10 && x_ends "$back"'; then pass; else
            fail "$S: scrolled back to end at $back s, the time axis should run over the 10 s before it, reads '$(axis_says)'"
        fi
    else
        fail "$S: | and PgUp should show the window a window back; screen: $(brief "$scr" shown)"
    fi
done

all_alive $sessions

# ---- the window at start: the beating preset's three beats, --window ----
# beating.ini: f1 = sqrt(20) / 2 pi = 0.7118 Hz driven at 0.62 Hz beats every
# 1 / 0.0918 = 10.9 s; its window of 33 s holds three beats, on an axis from -40 s.
S=beat80
t1=$(title 1)
keys 1
if wait_for '0 all plots' 3 && poll 3 x_window 33; then pass; else
    fail "80x24 -p beating: the time axis should be a window of 33 s (three beats of 10.9 s), reads '$(axis_says)'"
fi
keys '<'
if poll 3 x_window 30; then pass; else
    fail "80x24 -p beating: < from 33 s should make the window 30 s, reads '$(axis_says)'"
fi
keys '>'
if poll 3 x_window 60; then pass; else
    fail "80x24 -p beating: > from 30 s should make the window 60 s, reads '$(axis_says)'"
fi
S=win80
keys 1
if wait_for '0 all plots' 3 && poll 3 x_window 2; then pass; else
    fail "80x24 --window 2: the time axis should be a window of 2 s, reads '$(axis_says)'"
fi

# ---- the first motion fits the axis at once ----
# The default chain starts paused at rest (x = 0 on a -1..1 placeholder axis); in its
# first second under the 0.1 m drive the masses move less than 0.2 m, so the displacement
# axis reads at most 0.5 then. It used to wait 30 refreshes (3 s or more) to shrink.
ylabels() { plot_awk 'END { if (plot(title)) for (r = axtop; r < axr; r++) { s = label(r); if (s != "") print s } }' -v "title=$1"; }
ytop_below() { top=$(ylabels "$t1" | head -n 1); [ -n "$top" ] && awk -v t="$top" 'BEGIN { exit !(t + 0 < 0.5) }'; }
S=fit80
t1=$(title 1)
keys ' '
if wait_t 0.3 && poll 0.5 ytop_below; then pass; else
    fail "80x24 default, running: the displacement axis should fit the first motion (top label below 0.5) by t = 1 s, reads '$(ylabels "$t1" | tr '\n' ' ')'"
fi

summary
