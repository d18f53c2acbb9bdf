#!/bin/sh
# tests/tui-style.sh: --glyphs and --color (issue 13) in a real terminal (tmux), in a
# UTF-8 locale: ascii sends no byte >= 0x80, blocks draws the plots in block characters
# and no braille, never sends no colour, always colours with NO_COLOR=1 set; the same from
# a preset's [run] section; bad values. The bytes the program sends are recorded from its
# first (tmux pipe-pane on a shell that then runs it), the screen read with capture-pane.
# Run from the repository root as `sh tests/tui-style.sh`, SPRINGSIM naming the binary.
# Ends with "tui-style: N passed, M failed".
NAME=tui-style
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

# an SGR colour (foreground or background, 8/16/256/direct), not attributes or a reset
COLOUR_RE="$ESC\\[([0-9;]*;)?(3[0-8]|4[0-8]|9[0-7]|10[0-7])(;[0-9;:]*)?m"
# bytes >= 0x80 in FILE
high_bytes() { LC_ALL=C tr -d '\000-\177' <"$1" | wc -c; }
# braille (U+2800..U+28FF: E2 A0..A3 xx) in FILE, and the quadrant blocks (U+2596..U+259F:
# E2 96 96..9F), which only a canvas drawn in blocks uses
has_braille() { LC_ALL=C grep -q "$(printf '\342[\240-\243]')" "$1"; }
has_quadrant() { LC_ALL=C grep -q "$(printf '\342\226[\226-\237]')" "$1"; }

# run_recorded NAME COLS ROWS [VAR=VALUE]... -- ARG...: the program in a shell whose
# output from the first byte goes to $tmp/NAME.raw, in the UTF-8 locale, TERM=xterm-256color.
run_recorded() {
    rr_name=$1
    start_shell "$1" "$2" "$3"
    shift 3
    tm pipe-pane -t "$rr_name" "cat >$tmp/$rr_name.raw"
    rr_env=
    while [ $# -gt 0 ] && [ "$1" != -- ]; do rr_env="$rr_env $1"; shift; done
    [ $# -gt 0 ] && shift
    S=$rr_name
    poll 5 has 'PROMPT$' || fail "$rr_name: the shell did not start"
    text "exec env -u NO_COLOR -u COLORTERM LANG=$U8 LC_ALL=$U8 TERM=xterm-256color XDG_CONFIG_HOME=$tmp/xdg$rr_env $SPRINGSIM $*"
    keys Enter
}

# A preset asking for ASCII and no colour from its [run] section.
cat >"$tmp/plain.ini" <<'EOF'
[preset]
name = Plain
description = resonance in ASCII without colour
[system]
masses = 1
[motor]
frequency = 0.712
[run]
glyphs = ascii
color = never
EOF

run_recorded ascii 120 40 -- --glyphs ascii -p resonance
run_recorded blocks 120 40 -- --glyphs blocks -p resonance
run_recorded braille 120 40 -- -p resonance
run_recorded never 120 40 -- --color never -p resonance
run_recorded always 120 40 NO_COLOR=1 -- --color always -p resonance
run_recorded mono 120 40 NO_COLOR=1 -- -p resonance
run_recorded preset 120 40 -- -p "$tmp/plain.ini"

# exercise SESSION: runs it for a second of simulated time, a plot enlarged, the help
# shown and closed, so every part of the screen has been drawn, then pauses; the screen
# as seen after (standing still, drawn whole) in $scr, and as capture-pane -e gives it in
# $tmp/SESSION.e.
exercise() {
    up "$1" || return 1
    keys Space
    wait_t 1 || { fail "$1: space should run it; screen: $(brief)"; return 1; }
    keys 4
    wait_for '0 all plots' || fail "$1: 4 should enlarge the x-v plot; screen: $(brief)"
    keys '?'
    # the whole help, to its coarse keys (a slow build draws it in pieces)
    wait_all 5 "has 'preset menu' && has 'increase, coarse' && has 'decrease, coarse'" ||
        fail "$1: ? should show the help; screen: $(brief)"
    cp "$scr" "$tmp/$1.help"
    keys Escape
    wait_gone 'preset menu'
    keys 0 Space
    settle_all 5 "lacks '0 all plots' && has_re '(▸|>) Paused'" ||
        fail "$1: 0 and space should show all the plots, paused; screen: $(brief)"
    tm capture-pane -e -p -t "$1" >"$tmp/$1.e"
}

# ---- --glyphs ascii in a UTF-8 locale: not one byte >= 0x80 ----
for s in ascii preset; do
    if exercise "$s"; then
        cap_raw
        n=$(high_bytes "$tmp/$s.raw")
        if [ "$n" = 0 ] && [ "$(high_bytes "$scr")" = 0 ] && has Controls; then pass; else
            fail "$s: $n bytes >= 0x80 sent; lines with some: $(LC_ALL=C grep -n '[^ -~]' "$scr" | head -n 3 | cut -c 1-100 | tr '\n' '|')"
        fi
        # "m/s²" spelled "m/s^2" is a column wider: the plots' titles are measured as
        # drawn, not cut at the frame ("3 Acceleration (m/s^2 ---").
        grep -qF 'Acceleration (m/s^2) ' "$scr" && grep -qF 'x-a (m, m/s^2) ' "$scr" && pass ||
            fail "$s: a plot title spelled in ASCII is cut: $(grep -o '[0-9] [A-Za-z-]* ([^-]*' "$scr" | tr '\n' '|')"
        # ... and the help's keys: the column is as wide as the widest spelled in ASCII
        grep -qF '| PgDn Shift+Left H decrease, coarse' "$tmp/$s.help" &&
            grep -qF '| PgUp Shift+Right  increase, coarse' "$tmp/$s.help" && pass ||
            fail "$s: the help's keys cut in ASCII: $(grep -F 'coarse' "$tmp/$s.help" | tr '\n' '|')"
    fi
done

# ---- the default (braille): the half of each check that finds what it looks for ----
if exercise braille; then
    if [ "$(high_bytes "$tmp/braille.raw")" -gt 0 ] && has_braille "$tmp/braille.raw" &&
        has_braille "$scr"; then pass; else
        fail "braille: expected braille on the screen and in the bytes sent"
    fi
    grep -qE "$COLOUR_RE" "$tmp/braille.raw" && grep -qE "$COLOUR_RE" "$tmp/braille.e" && pass ||
        fail "braille: expected colour without NO_COLOR"
fi

# ---- --glyphs blocks: the plots and springs in quadrant blocks, no braille ----
if exercise blocks; then
    if has_braille "$tmp/blocks.raw" || has_braille "$scr"; then
        fail "blocks: braille (U+2800..U+28FF) was sent; screen: $(brief)"
    else
        pass
    fi
    has_quadrant "$scr" && has_quadrant "$tmp/blocks.raw" && pass ||
        fail "blocks: expected quadrant blocks (U+2596..U+259F) in the plots; screen: $(brief)"
    # the x-v plot's trace is there, drawn in blocks: its area holds block characters
    PLOT_SCR=$tmp/blocks.plot
    keys 4
    if settle_for '0 all plots'; then
        cp "$scr" "$PLOT_SCR"
        cells=$(plot_awk 'END { if (!plot("4 x")) { print -1; exit }
            for (r = axtop; r < axr; r++) for (k = axc + 1; k < right; k++)
                if (length(c[r, k]) == 3 && substr(c[r, k], 1, 2) == "\342\226") n++
            print n + 0 }')
        [ "$cells" -gt 20 ] && pass || fail "blocks: the enlarged x-v plot has $cells block cells (expected its trace)"
    fi
    unset PLOT_SCR
fi

# ---- --color never: no colour escape sent, even on a 256-colour terminal ----
for s in never preset; do
    [ -s "$tmp/$s.e" ] || exercise "$s" || continue
    if grep -qE "$COLOUR_RE" "$tmp/$s.raw" || grep -qE "$COLOUR_RE" "$tmp/$s.e"; then
        fail "$s: colour escapes were sent: $(grep -oE "$COLOUR_RE" "$tmp/$s.raw" | sort -u | head -n 3 | tr -d "$ESC" | tr '\n' ' ')"
    else
        pass
    fi
done

# ---- NO_COLOR=1: none by default, colour with --color always ----
if exercise mono; then
    grep -qE "$COLOUR_RE" "$tmp/mono.raw" && fail "NO_COLOR=1: colour was sent" || pass
fi
if exercise always; then
    grep -qE "$COLOUR_RE" "$tmp/always.raw" && grep -qE "$COLOUR_RE" "$tmp/always.e" && pass ||
        fail "--color always with NO_COLOR=1: expected colour escapes, found none"
fi

# ---- bad values: one line naming the option, the value and what is allowed; exit 2 ----
bad() { # bad NEEDLE... -- ARG...
    needles=
    while [ "$1" != -- ]; do needles="$needles|$1"; shift; done
    shift
    "$SPRINGSIM" "$@" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    miss=
    old_ifs=$IFS
    IFS='|'
    for n in ${needles#|}; do grep -qF -- "$n" "$tmp/err" || miss="$miss '$n'"; done
    IFS=$old_ifs
    if [ "$rc" = 2 ] && ! [ -s "$tmp/out" ] && [ "$(awk 'END { print NR }' "$tmp/err")" = 1 ] &&
        [ -z "$miss" ]; then pass; else
        fail "springsim $*: exit $rc, stderr '$(head -c 200 "$tmp/err")' (missing$miss)"
    fi
}
bad "--color: 'sometimes'" "auto, always or never" -- --color sometimes
bad "--glyphs: 'emoji'" "braille, blocks or ascii" -- --glyphs emoji
bad "--color" "needs a value" -- --color
printf '[run]\nglyphs = Braille\n' >"$tmp/bad.ini"
bad "bad.ini:2: glyphs: 'Braille'" "braille, blocks or ascii" -- -p "$tmp/bad.ini"
printf '[system]\ncolor = never\n' >"$tmp/wrong.ini"
bad "wrong.ini:2" "color" "[run]" -- -p "$tmp/wrong.ini"

summary
