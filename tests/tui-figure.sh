#!/bin/sh
# tests/tui-figure.sh: X in the program, in a real terminal (tmux): a report figure of the
# view on the screen, its file name asked for (Enter keeps the default), said where it
# went. The displacement plot's figure, after 25 s shown in a 10 s window with a cursor,
# read back from its PDF: a title with no key digit, axis titles with units on both axes,
# the time axis absolute (about 15..25 s, as the screen's), the cursor's values written
# (its time the readout's), the settings under the title; with a second cursor close by,
# both cursors' values, no text on another and all inside the plot; its SVG: the mass's
# curve, the motor's only where it moves. The response and modes views saved too, and six instances
# pressing X in the same second leave six pairs. A sweep's measured points: markers of one
# small size in the figure, its state on the response view's border never cut.
# Ends with "tui-figure: N passed, M failed".
NAME=tui-figure
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"
fc="python3 $(cd "$(dirname "$0")" && pwd)/lib/figcheck.py"
M1=0,95,255
MOTOR=0,0,0

mkdir -p "$tmp/fig" "$tmp/drv" "$tmp/still" "$tmp/six" "$tmp/sweep"
start_in "$tmp/sweep" sweeping 80 24 -- -n 3 --amplitude 0.05
start_in "$tmp/fig" cosine 100 30 -- -n 1 --boundary wall --x0 0.5 --damping 0
start_in "$tmp/drv" driven 100 30 -- -n 1
start_in "$tmp/still" still 100 30 -- -n 1 --amplitude 0 --x0 0.3
# Six instances in one directory, for X pressed in all of them at once.
for i in 1 2 3 4 5 6; do start_in "$tmp/six" six$i 80 24 -- -n 1; done

# saved DIR: waits for X's message naming files other than the last ones; sets $base to
# their name without extension, true when both are in DIR.
base=
saved() {
    prev=$base
    poll 5 new_name || return 1
    [ -f "$1/$base.svg" ] && [ -f "$1/$base.png" ]
}
# save_as NAME: X, the name typed, Enter; true when X says it saved NAME.
save_as() {
    keys X
    wait_for 'figure name'
    text "$1"
    keys Enter
    wait_for "saved the figure as ./$1"
}
new_name() {
    base=$(sed -n 's/.*saved the figure as \.\/\(springsim-[0-9]\{8\}-[0-9]\{6\}\(-[0-9]*\)\{0,1\}\)\.svg and \.png.*/\1/p' "$scr" | head -n 1)
    [ -n "$base" ] && [ "$base" != "$prev" ]
}

# expect WHAT GOT WANT
expect() {
    if [ "$2" = "$3" ]; then pass; else fail "$1: got '$2', expected '$3'"; fi
}

# within LO HI WORDS...: every word a number in [LO, HI], and at least three.
within() {
    lo=$1 hi=$2
    shift 2
    echo "$@" | awk -v lo="$lo" -v hi="$hi" '
        { for (i = 1; i <= NF; i++) { n++; if ($i + 0 < lo || $i + 0 > hi) bad = 1 } }
        END { exit !(n >= 3 && !bad) }'
}

S=cosine
if up cosine; then
    # 25 s and more in the 10 s window, the displacement plot enlarged, paused, a cursor.
    keys 1 ] ] ] Space
    wait_t 25 30
    keys Space
    settled_t >/dev/null
    keys '|'
    wait_for 'Cursor'
    keys H H
    sleep 0.3
    cap
    cp "$scr" "$tmp/x-screen"
    cursor_t=$(sed -n 's/.*│t \([0-9][0-9.]*\) s .*/\1/p' "$tmp/x-screen" | head -n 1)
    # The screen's time labels, under the plot.
    screen_ticks=$(sed -n 's/^│ s *\([0-9 ]*\)│.*/\1/p' "$tmp/x-screen" | head -n 1)
    keys X
    if wait_for 'figure name [springsim-'; then pass; else
        fail "X: expected it to ask for the figure's name with the default; screen: $(brief)"
    fi
    text x.pdf
    keys Enter
    if wait_for 'saved the figure as ./x.pdf' && [ -s "$tmp/fig/x.pdf" ]; then pass; else
        fail "X, x.pdf: expected 'saved the figure as ./x.pdf' and the file; screen: $(brief); files: $(ls "$tmp/fig" | tr '\n' ' ')"
    fi
    pdf=$tmp/fig/x.pdf
    $fc text "$pdf" >"$tmp/x-text" 2>&1
    expect "X: the title (no key digit, no unit)" "$(sed -n 1p "$tmp/x-text")" "Displacement"
    grep -q 'wall' "$tmp/x-text" && grep -q 'rk4, dt 0.01 s' "$tmp/x-text" && pass ||
        fail "X: the settings should be under the title: $(sed -n 2p "$tmp/x-text")"
    grep -q '^time t (s)$' "$tmp/x-text" && pass ||
        fail "X: no x axis title 'time t (s)': $(tr '\n' '|' <"$tmp/x-text")"
    # The y axis title is turned upright: pdftotext gives its words a line each.
    grep -qx 'displacement' "$tmp/x-text" && grep -qx '(m)' "$tmp/x-text" && pass ||
        fail "X: no y axis title 'displacement x (m)': $(tr '\n' '|' <"$tmp/x-text")"
    ticks=$($fc xticks "$pdf" time)
    # Absolute time: the window's 10 s ending past 25 s, labelled as the screen is.
    if within 14 47 $ticks && within 14 47 $screen_ticks &&
        [ "$(echo $ticks | awk '{ print $NF - $1 }')" -le 10 ]; then pass; else
        fail "X: the time axis should be absolute, 10 s past 15 s: labels '$ticks' (the screen's '$screen_ticks')"
    fi
    first=$(echo $screen_ticks | awk '{ print $1 }') last=$(echo $screen_ticks | awk '{ print $NF }')
    if echo $ticks | awk -v a="$first" -v b="$last" '{ exit !($1 + 0 >= a - 2 && $NF + 0 <= b + 2) }'
    then pass; else fail "X: time labels '$ticks' should span the screen's $first..$last"; fi
    # The cursor: its time and mass 1's value written beside it.
    if [ -n "$cursor_t" ] && grep -q "t = $cursor_t" "$tmp/x-text" && grep -q 'x1 = -\{0,1\}0\.[0-9]* m' "$tmp/x-text"
    then pass; else
        fail "X: the cursor's values (t = $cursor_t s, x1 = ... m) should be written: $(tr '\n' '|' <"$tmp/x-text")"
    fi
    if grep -q '^1 Displacement\|Displacement (m)' "$tmp/x-text"; then
        fail "X: the screen's words are in the figure: $(tr '\n' '|' <"$tmp/x-text")"
    else pass; fi
    # Enter keeps the default: the SVG and PNG pair.
    keys X
    wait_for 'figure name [springsim-'
    keys Enter
    if saved "$tmp/fig"; then pass; else
        fail "X, Enter: expected 'saved the figure as ./springsim-...svg and .png' and both files; screen: $(brief); files: $(ls "$tmp/fig" | tr '\n' ' ')"
    fi
    svg=$tmp/fig/$base.svg
    expect "X: the mass's curve in the SVG" "$($fc curves "$svg" $M1)" 1
    expect "X: no motor (a wall at the right end)" "$($fc curves "$svg" $MOTOR)" 0
    # The curve is the cosine, 0.5 m each side: its extent is most of the plot's height.
    got=$($fc png "$tmp/fig/$base.png" 2>&1)
    [ "$got" = "1890 1181" ] && pass || fail "X: PNG $got, expected 1890 x 1181 (160 x 100 mm at 300 dpi)"
    # Esc cancels: nothing written.
    n=$(ls "$tmp/fig" | wc -l)
    keys X
    wait_for 'figure name'
    keys Escape
    wait_gone 'figure name'
    [ "$(ls "$tmp/fig" | wc -l)" -eq "$n" ] && pass || fail "X, Esc: files were written: $(ls "$tmp/fig" | tr '\n' ' ')"
    # A directory's name (sub/, or sub that is one): the default pair inside it, not the
    # hidden sub/.svg and sub/.png.
    mkdir -p "$tmp/fig/sub"
    for d in sub/ sub; do
        keys X
        wait_for 'figure name'
        text "$d"
        keys Enter
        if wait_re "saved the figure as sub/springsim-[0-9-]*\\.svg and \\.png" &&
            ! [ -e "$tmp/fig/sub/.svg" ] && ! [ -e "$tmp/fig/sub/.png" ]; then pass; else
            fail "X, $d: expected the default pair inside sub; screen: $(brief); files: $(ls -A "$tmp/fig/sub" | tr '\n' ' ')"
        fi
        rm -f "$tmp/fig/sub/.svg" "$tmp/fig/sub/.png"
    done
    # A second cursor a tenth of the window from the first: both cursors' values written,
    # no text on another, each inside the plot (right of the y labels, left of the page's
    # right margin: 160 mm less 12 pt).
    keys '|'
    sleep 0.3
    if save_as x2.pdf; then
        $fc overlaps "$tmp/fig/x2.pdf" >"$tmp/x2-overlaps" 2>&1
        [ -s "$tmp/x2-overlaps" ] && fail "X, two cursors: texts on each other: $(tr '\n' '|' <"$tmp/x2-overlaps")" ||
            pass
        $fc cursors "$tmp/fig/x2.pdf" >"$tmp/x2-cursors" 2>&1
        left=$(sed -n 's/^plot //p' "$tmp/x2-cursors")
        if [ "$(grep -c ' t = ' "$tmp/x2-cursors")" -eq 2 ] && [ "$(grep -c ' x1 = ' "$tmp/x2-cursors")" -eq 2 ] &&
            awk -v l="$left" '$1 != "plot" && ($1 < l || $2 > 441.5) { bad = 1 } END { exit bad }' "$tmp/x2-cursors"
        then pass; else
            fail "X, two cursors: expected two cursors' t and x1 inside the plot: $(tr '\n' '|' <"$tmp/x2-cursors")"
        fi
    else
        fail "X, two cursors: x2.pdf not saved; screen: $(brief)"
    fi
fi

S=still
if up still; then
    # A motor end whose amplitude is 0: the motor does not move, so no motor line.
    keys Space
    wait_t 2
    keys X
    wait_for 'figure name'
    keys Enter
    if saved "$tmp/still" && [ "$($fc curves "$tmp/still/$base.svg" $MOTOR)" = 0 ] &&
        [ "$($fc curves "$tmp/still/$base.svg" $M1)" -ge 2 ]; then pass; else
        fail "X, amplitude 0: expected the mass's curves and no motor line; screen: $(brief)"
    fi
fi

S=driven
if up driven; then
    keys Space
    wait_t 2
    keys X
    wait_for 'figure name'
    keys Enter
    # The plots' grid: the motor moves, dashed, in the displacement panel only.
    if saved "$tmp/drv" && [ "$($fc curves "$tmp/drv/$base.svg" $MOTOR)" = 1 ] &&
        [ "$($fc dashed "$tmp/drv/$base.svg" $MOTOR)" = 1 ]; then pass; else
        fail "X, driven: expected one dashed motor line; screen: $(brief)"
    fi
    # The response view: its amplitude and phase curves.
    keys f
    wait_for 'Frequency response'
    keys X
    wait_for 'figure name'
    keys Enter
    if saved "$tmp/drv" && [ "$($fc curves "$tmp/drv/$base.svg" $M1)" -ge 2 ]; then pass; else
        fail "X in the response view: expected a figure with the amplitude and phase curves; screen: $(brief)"
    fi
    # The drive's line has an upright mark in the legend, not the theory's level stroke.
    expect "X in the response view: the drive's upright legend mark" \
        "$($fc uprights "$tmp/drv/$base.svg" $MOTOR)" 1
    # The energy view in --energy --figure's words.
    keys e
    wait_for 'kinetic'
    if save_as e.pdf; then
        $fc text "$tmp/drv/e.pdf" >"$tmp/e-text" 2>&1
        grep -q 'dissipated' "$tmp/e-text" && ! grep -q 'damped' "$tmp/e-text" &&
            grep -q '^time t (s)$' "$tmp/e-text" && pass ||
            fail "X in the energy view: expected 'dissipated' and 'time t (s)': $(tr '\n' '|' <"$tmp/e-text")"
    else
        fail "X in the energy view: e.pdf not saved; screen: $(brief)"
    fi
    # The modes view: the shape of the one mode, as --modes --figure draws it.
    keys m
    wait_for 'Modes'
    keys X
    wait_for 'figure name'
    keys Enter
    if saved "$tmp/drv" && [ "$($fc curves "$tmp/drv/$base.svg" $M1)" = 1 ]; then pass; else
        fail "X in the modes view: expected the mode's shape; screen: $(brief)"
    fi
    [ "$(ls "$tmp/drv" | grep -vc '^e\.pdf$')" -eq 6 ] && pass ||
        fail "X: expected three SVG and PNG pairs and e.pdf; found $(ls "$tmp/drv" | tr '\n' ' ')"
fi

S=sweeping
if up sweeping; then
    keys f w ] ] ] ] ] ]
    # Four points measured (the fifth being measured), each a marker on both panels.
    if wait_re 'sweep [5-9]/40|sweep [1-9][0-9]/40' 60; then pass; else
        fail "sweep: expected the fifth point within a minute; screen: $(brief)"
    fi
    border=$(grep '^└.*sweep [0-9]*/40' "$scr" | head -n 1)
    case $border in
    *'(w stops)'*) pass ;;
    *) fail "sweep: the state should be whole on the border at 80 columns: '$border'" ;;
    esac
    if save_as sweep.svg; then pass; else
        fail "X, sweep.svg: not saved; screen: $(brief)"
    fi
    set -- $($fc markers "$tmp/sweep/sweep.svg" $M1)
    # Mass 1's points on the amplitude and the phase panels, each 3.2 points across.
    if [ "${1:-0}" -ge 8 ] && awk -v a="$2" -v b="$3" 'BEGIN { exit !(a > 3.0 && b < 3.4) }'
    then pass; else
        fail "sweep's X: expected 8 or more markers of mass 1, each 3.2 pt across; got ${1:-0}, ${2:-?}..${3:-?} pt"
    fi
    [ "$($fc curves "$tmp/sweep/sweep.svg" $M1)" -ge 2 ] && pass ||
        fail "sweep's X: the theory's lines (amplitude and phase) are missing"
fi

# Six instances pressing X in the same second (issue 33 item 6): six pairs, none replaced.
ok=1
for i in 1 2 3 4 5 6; do up six$i || ok=; done
if [ -n "$ok" ]; then
    for i in 1 2 3 4 5 6; do S=six$i; keys X; done
    for i in 1 2 3 4 5 6; do S=six$i; wait_for 'figure name' || ok=; done
    # The default names were given in the same second or two: Enter in all at once.
    for i in 1 2 3 4 5 6; do S=six$i; keys Enter; done
    for i in 1 2 3 4 5 6; do S=six$i; wait_for 'saved the figure as' || ok=; done
    svgs=$(ls "$tmp/six" | grep -c '\.svg$') pngs=$(ls "$tmp/six" | grep -c '\.png$')
    seconds=$(ls "$tmp/six" | sed -n 's/^springsim-\([0-9]*-[0-9]*\).*\.svg$/\1/p' | sort -u | wc -l)
    if [ -n "$ok" ] && [ "$svgs" -eq 6 ] && [ "$pngs" -eq 6 ]; then pass; else
        fail "X in six instances: expected six SVG and PNG pairs, found $(ls "$tmp/six" | tr '\n' ' ')"
    fi
    # Each pair whole: an SVG that ends, a PNG with its end chunk.
    bad=0
    for f in "$tmp/six"/*.svg; do tail -c 8 "$f" | grep -q '</svg>' || bad=$((bad + 1)); done
    for f in "$tmp/six"/*.png; do tail -c 8 "$f" | grep -q 'IEND' || bad=$((bad + 1)); done
    [ "$bad" -eq 0 ] && pass || fail "X in six instances: $bad files not whole"
    echo "tui-figure: six X presses fell in $seconds distinct second(s)" >&2
fi

all_alive cosine still driven sweeping six1 six2 six3 six4 six5 six6

summary
