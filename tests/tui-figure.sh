#!/bin/sh
# tests/tui-figure.sh: X in the program (issue 18), in a real terminal (tmux): the view on
# the screen saved as SVG and PNG in the working directory, said in the status line. The
# picture is checked against what tmux shows: its gridlines on the rows of the screen's y
# tick labels, a known cosine's peaks (x0 = 0.5 m, undamped, between walls) on the rows
# those labels give for +-0.5 m, the PNG the frame's size at 16 x 32 pixels a cell and in
# the mass's colour; the response and modes views saved too.
# Ends with "tui-figure: N passed, M failed".
NAME=tui-figure
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"
fc="python3 $(cd "$(dirname "$0")" && pwd)/lib/figcheck.py"
M1=0,95,255
GRID=214,214,214

mkdir -p "$tmp/fig"
mkdir -p "$tmp/drv"
start_in "$tmp/fig" cosine 100 30 -- -n 1 --boundary wall --x0 0.5 --damping 0
start_in "$tmp/drv" driven 100 30 -- -n 1
# Six instances in one directory, for X pressed in all of them at once.
mkdir -p "$tmp/six"
for i in 1 2 3 4 5 6; do start_in "$tmp/six" six$i 80 24 -- -n 1; done

# saved DIR: waits for X's message naming files other than the last ones; sets $base to
# their name without extension, true when both are in DIR.
base=
saved() {
    prev=$base
    poll 5 new_name || return 1
    [ -f "$1/$base.svg" ] && [ -f "$1/$base.png" ]
}
new_name() {
    base=$(sed -n 's/.*saved the view as \.\/\(springsim-[0-9]\{8\}-[0-9]\{6\}\(-[0-9]*\)\{0,1\}\)\.svg and \.png.*/\1/p' "$scr" | head -n 1)
    [ -n "$base" ] && [ "$base" != "$prev" ]
}

S=cosine
if up cosine; then
    keys 1 Space
    wait_t 3 && keys Space
    settled_t >/dev/null
    keys X
    if saved "$tmp/fig"; then pass; else fail "X: expected 'saved the view as ./springsim-...svg and .png' and both files; screen: $(brief); files: $(ls "$tmp/fig" | tr '\n' ' ')"; fi
    cp "$scr" "$tmp/x-screen"
    svg=$tmp/fig/$base.svg
    png=$tmp/fig/$base.png
    # The frame on the screen: its top row, width and height in cells.
    geo=$(python3 -c '
import sys
lines = open(sys.argv[1], encoding="utf-8").read().split("\n")
top = next(i for i, l in enumerate(lines) if "1 Displacement" in l)
bot = next(i for i in range(top, len(lines)) if lines[i].startswith("\u2514"))
print(top, lines[top].index("\u2510") + 1, bot - top + 1)' "$tmp/x-screen")
    set -- $geo
    top=$1 w=$2 h=$3
    # Each y label's row, as a page y in the picture (cells of 16 points, from the frame).
    sed -n 's/^│ *\(-\{0,1\}[0-9.][0-9.]*\)┤.*/\1/p' "$tmp/x-screen" >"$tmp/labels"
    grep -n '^│ *-\{0,1\}[0-9.][0-9.]*┤' "$tmp/x-screen" | cut -d: -f1 |
        awk -v top="$top" '{ print ($1 - 1 - top + 0.5) * 16 }' >"$tmp/label-y"
    $fc gridrows "$svg" $GRID >"$tmp/grid-y"
    if [ -s "$tmp/label-y" ] && [ "$(sort -n "$tmp/label-y")" = "$(sort -n "$tmp/grid-y" | awk '{ print $1 + 0 }')" ]
    then pass; else
        fail "X: the picture's gridlines ($(tr '\n' ' ' <"$tmp/grid-y")) should be on the label rows ($(tr '\n' ' ' <"$tmp/label-y"))"
    fi
    # The cosine's peaks: +-0.5 m on the page y the labels' rows give (within a dot, 4 pt).
    ext=$($fc extent "$svg" $M1 0)
    if paste -d' ' "$tmp/labels" "$tmp/label-y" | awk -v ext="$ext" '
        { v[NR] = $1; y[NR] = $2; n = NR }
        END { a = (y[n] - y[1]) / (v[n] - v[1]); b = y[1] - a * v[1]
              split(ext, e, " ")
              exit !(n >= 3 && (e[1] - (a * 0.5 + b)) ^ 2 < 16 && (e[2] - (a * -0.5 + b)) ^ 2 < 16) }'
    then pass; else
        fail "X: the cosine's curve spans page y $ext, expected the rows of +-0.5 m from the labels $(paste -d= "$tmp/labels" "$tmp/label-y" | tr '\n' ' ')"
    fi
    expect_png=$((w * 16))" "$((h * 32))
    got=$($fc png "$png" 2>&1)
    [ "$got" = "$expect_png" ] && pass || fail "X: PNG size $got, expected $expect_png (the frame, $w x $h cells)"
    blue=$(convert "$png" -format %c histogram:info:- 2>/dev/null | grep -ci '#005FFF')
    [ "${blue:-0}" -ge 1 ] && pass || fail "X: the PNG has no pixel of mass 1's colour #005FFF"

fi

S=driven
if up driven; then
    keys Space
    wait_t 2
    # The response view: its amplitude and phase curves.
    keys f
    wait_for 'Frequency response'
    keys X
    if saved "$tmp/drv" && [ "$($fc curves "$tmp/drv/$base.svg" $M1)" -ge 2 ]; then pass; else
        fail "X in the response view: expected a picture with the amplitude and phase curves; screen: $(brief)"
    fi
    # The modes view: the shape of the one mode, as --modes --figure draws it.
    keys m
    wait_for 'Modes'
    keys X
    if saved "$tmp/drv" && [ "$($fc curves "$tmp/drv/$base.svg" $M1)" = 1 ]; then pass; else
        fail "X in the modes view: expected the mode's shape; screen: $(brief)"
    fi
    [ "$(ls "$tmp/drv" | wc -l)" -eq 4 ] && pass ||
        fail "X: expected two SVG and PNG pairs; found $(ls "$tmp/drv" | tr '\n' ' ')"
fi

# Six instances pressing X in the same second (issue 33 item 6): six pairs, none replaced.
ok=1
for i in 1 2 3 4 5 6; do up six$i || ok=; done
if [ -n "$ok" ]; then
    for i in 1 2 3 4 5 6; do S=six$i; keys X; done
    for i in 1 2 3 4 5 6; do S=six$i; wait_for 'saved the view as' || ok=; done
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

all_alive cosine driven six1 six2 six3 six4 six5 six6

summary
