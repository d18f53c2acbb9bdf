#!/bin/sh
# tests/tui-start.sh: the interactive program's first screen (springsim(1), INTERACTIVE PROGRAM) in a real
# terminal (tmux): at 120x40 and the sizes where the plot grid changes, resizing (to the
# too-small message and back, a storm of sizes), tiny sizes, LANG=C (ASCII only),
# NO_COLOR and TERM. Run from the repository root as `sh tests/tui-start.sh`, SPRINGSIM
# naming the binary (default ./springsim). Ends with "tui-start: N passed, M failed".
NAME=tui-start
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

# an SGR colour (foreground or background, 8/16/256/direct), not just attributes or a
# reset to the default colours (39, 49)
COLOUR_RE="$ESC\\[([0-9;]*;)?(3[0-8]|4[0-8]|9[0-7]|10[0-7])(;[0-9;]*)?m"
has_colour() { grep -qE "$COLOUR_RE" "$1"; } # has_colour FILE (from capture-pane -e)
colours_in() { grep -oE "$ESC\\[[0-9;]*m" "$1" | grep -E '\[([0-9;]*;)?(3[0-8]|4[0-8]|9[0-7]|10[0-7])' | sort -u | head -n 5 | tr -d "$ESC" | tr '\n' ' '; }
# a byte outside printable ASCII
has_nonascii() { LC_ALL=C grep -q '[^ -~]' "$scr"; }

start main 120 40
start small 80 24
start mid 100 30
start big 160 48
start resize 120 40
start tiny 20 5
start one 1 1
start ascii 120 40 LANG=C LC_ALL=C
start mono 120 40 NO_COLOR=1
start vt100 100 30 TERM=vt100
start xterm8 100 30 TERM=xterm
start noterm 100 30 TERM=no-such-terminal
start dumb 100 30 TERM=dumb

# ---- the first screen at 120x40 ----
if up main; then
    pass
    for want in Paused 't = 0.00 s' MOTOR '1 Displacement (m)' '2 Velocity (m/s)' '4 x–v'; do
        if has "$want"; then pass; else fail "start 120x40: expected '$want'; screen: $(brief)"; fi
    done
    missing=
    for c in Preset Masses dt Damping 'Spring k' Mass 'Right end' Waveform Amplitude \
        Frequency Speed; do
        # a control is its label at the start of a line of the Controls panel
        grep -qE "│( |▸)$c  " "$scr" || missing="$missing '$c'"
    done
    if [ -z "$missing" ]; then pass; else
        fail "start 120x40: Controls panel lacks$missing; panel: $(brief "$scr" '(Preset|Masses|Speed) ')"
    fi
    if sed -n 1p "$scr" | grep -qE 'N 2 │ dt 0\.010 s │ history 0'; then pass; else
        fail "start 120x40: the status line should show 'N 2 │ dt 0.010 s │ history 0'; screen: $(brief)"
    fi
    # colours are there without NO_COLOR (the half of the NO_COLOR check that finds them)
    tm capture-pane -e -p -t main >"$tmp/main0.e"
    if has_colour "$tmp/main0.e"; then pass; else
        fail "colour: expected colour escapes (ESC[3x / 38;5) in capture-pane -e with TERM=xterm-256color, found none"
    fi
    # a UTF-8 screen has bytes >= 0x80 (the half of the LANG=C check that finds them)
    cap_raw
    if has_nonascii; then pass; else fail "UTF-8: expected braille/box bytes >= 0x80 on the UTF-8 screen, found none"; fi
fi

# ---- the plot grid at 80x24, 100x30 and 160x48 ----
# check_grid SESSION SIZE TITLE...: the titles shown (each with its digit), a legend each,
# no other plot, the status line and the scene.
check_grid() {
    cg_s=$1 cg_size=$2
    shift 2
    up "$cg_s" || return
    missing=
    for title in "$@"; do has " $title " || missing="$missing '$title'"; done
    shown=$(grep -oE '┌─* [1-6] [^ ]' "$scr" | wc -l)
    legends=$(grep -o '━1' "$scr" | wc -l)
    if [ -z "$missing" ] && [ "$shown" -eq $# ] && [ "$legends" -eq $# ]; then pass; else
        fail "$cg_size: expected the plots $*, missing:$missing, plots shown: $shown, legends: $legends; screen: $(brief "$scr" '┌─* [1-6] ')"
    fi
    if has Paused && has MOTOR; then pass; else fail "$cg_size: expected the status line and the scene; screen: $(brief)"; fi
    cp "$scr" "$tmp/$cg_s.0"
}
check_grid small 80x24 '1 Displacement (m)' '4 x–v (m, m/s)'
check_grid mid 100x30 '1 Displacement (m)' '4 x–v (m, m/s)'
check_grid big 160x48 '1 Displacement (m)' '2 Velocity (m/s)' '3 Acceleration (m/s²)' \
    '4 x–v (m, m/s)' '5 x–a (m, m/s²)' '6 v–a (m/s, m/s²)'
# the footer of a fresh start at 80x24 offers the digits that reach the other plots
S=small
if has_re '1-6 enlarge' || has 'space starts; ? lists every key'; then pass; else
    fail "80x24: the bottom line should offer '1-6 enlarge' (or the first hint); screen: $(brief)"
fi

# ---- resize ----
if up resize; then
    cp "$scr" "$tmp/resize.0"
    tm resize-window -t resize -x 80 -y 24
    if [ -f "$tmp/small.0" ]; then
        if wait_same "$tmp/small.0"; then pass; else
            fail "resize 120x40 -> 80x24: expected the same screen as a fresh start at 80x24; $(first_diff "$tmp/small.0" "$scr")"
        fi
    fi
    tm resize-window -t resize -x 40 -y 12
    if settle_all 5 "has 'Terminal too small' && has 'need 60x20, have 40x12'"; then pass; else
        fail "resize to 40x12: expected 'Terminal too small' and 'need 60x20, have 40x12'; screen: $(brief "$scr" 'small|need')"
    fi
    tm resize-window -t resize -x 1 -y 1
    wait_re '^.$' 3
    tm resize-window -t resize -x 100 -y 30
    if settle_all 5 "has Controls && has Paused && has MOTOR && lacks 'too small' &&
        [ \"\$(awk 'END { print NR }' \"\$scr\")\" -eq 30 ]"; then pass; else
        fail "resize 1x1 -> 100x30: expected the normal screen (Paused, MOTOR, Controls); screen: $(brief)"
    fi
    # a storm of sizes, then back to 120x40
    sizes=$(awk 'BEGIN { srand(7); print "1 1"; print "20 5"; print "200 60"
        for (i = 0; i < 47; i++) print int(1 + rand() * 220), int(1 + rand() * 70) }')
    echo "$sizes" | while read -r w h; do
        tm resize-window -t resize -x "$w" -y "$h"
        sleep 0.01 # the pace of the storm, not a wait for the program
    done
    tm resize-window -t resize -x 120 -y 40
    if wait_same "$tmp/resize.0" && alive resize; then pass; else
        fail "resize storm (50 sizes incl. 1x1, 20x5, 200x60, then 120x40): expected the first screen again and the program alive; $(first_diff "$tmp/resize.0" "$scr")"
    fi
    keys Space
    if wait_for Running; then pass; else fail "after the resize storm: space should start it; screen: $(brief)"; fi
fi

# ---- tiny sizes: the message fits, nothing crashes ----
S=tiny
if settle_all 5 "has '60x20' && has_re '(^| )small( |\$)'"; then
    if grep -qE '(^| )60x20( |$)' "$scr"; then pass; else
        fail "20x5: the size needed should be shown whole ('60x20'); screen: $(tr '\n' '|' <"$scr")"
    fi
    # every word on the screen is a whole word of the message
    cut=$(tr -s ' ' '\n' <"$scr" | grep -vxE 'Terminal|too|small|need|60x20,?|have|20x5|' | tr '\n' ' ')
    if [ -z "$cut" ]; then pass; else
        fail "20x5: no word of the message should be cut, found '$cut'; screen: $(tr '\n' '|' <"$scr")"
    fi
else
    fail "20x5: expected a too-small message with '60x20' whole; screen: $(tr '\n' '|' <"$scr")"
fi
tm resize-window -t tiny -x 60 -y 20
if settle_all 5 "has Controls && lacks 'too small'"; then pass; else
    fail "20x5 -> 60x20: expected the normal screen; screen: $(brief)"
fi
S=one
# 1x1: something drawn (the first letter of the message), and still running
if poll 3 has_re '^[^ ]$' && alive one; then pass; else
    fail "1x1: expected one character drawn and the program alive; screen: '$(cat "$scr")'"
fi
tm resize-window -t one -x 80 -y 24
if settle_all 5 "has Controls && has Paused"; then pass; else fail "1x1 -> 80x24: expected the normal screen; screen: $(brief)"; fi

# ---- LANG=C: ASCII only ----
if up ascii; then
    ascii_check() { # ascii_check WHAT
        cap_raw
        if has_nonascii; then
            fail "LANG=C ($1): expected no byte >= 0x80 on screen; lines with some: $(LC_ALL=C grep -n '[^ -~]' "$scr" | head -n 3 | cut -c 1-120 | tr '\n' '|')"
        else
            pass
        fi
    }
    if has Paused && has Chain && has Controls; then pass; else
        fail "LANG=C: expected 'Paused', 'Chain' and 'Controls'; screen: $(brief)"
    fi
    ascii_check "first screen"
    keys Space
    if wait_t 0.5; then ascii_check running; else fail "LANG=C: space should run it; screen: $(brief)"; fi
    keys 1
    if wait_for '0 all plots'; then ascii_check "plot 1 enlarged"; else
        fail "LANG=C: 1 should enlarge plot 1 (footer '0 all plots'); screen: $(brief)"
    fi
    keys '?'
    if wait_for "preset menu"; then ascii_check help; else fail "LANG=C: ? should open the help; screen: $(brief)"; fi
    keys Escape
    wait_gone "preset menu"
    keys p
    if wait_for resonance; then ascii_check "preset menu"; else
        fail "LANG=C: p should open the preset menu; screen: $(brief)"
    fi
    keys Escape
fi

# ---- NO_COLOR, and terminals with no colour, 8 colours, none known ----
# no_colour SESSION WHAT: running, and no colour escape on the screen
no_colour() {
    up "$1" || return
    keys Space
    if wait_for Running; then pass; else fail "$2: expected it to run; screen: $(brief)"; fi
    tm capture-pane -e -p -t "$1" >"$tmp/$1.e"
    if has_colour "$tmp/$1.e"; then
        fail "$2: expected no colour escapes in capture-pane -e, found: $(colours_in "$tmp/$1.e")"
    else
        pass
    fi
}
no_colour mono NO_COLOR=1
no_colour vt100 TERM=vt100
if up xterm8; then
    tm capture-pane -e -p -t xterm8 >"$tmp/xterm8.e"
    if has_colour "$tmp/xterm8.e" && has Paused; then pass; else
        fail "TERM=xterm (8 colours): expected the screen in colour; screen: $(brief)"
    fi
fi
S=noterm
if wait_for 'TERMINAL '; then
    if has 'no-such-terminal' && has 'EXITED 1' && has 'TERMINAL SAME'; then pass; else
        fail "TERM=no-such-terminal: expected a message naming it, exit status 1, the terminal as it was; screen: $(brief "$scr" 'EXITED|TERMINAL|term')"
    fi
else
    fail "TERM=no-such-terminal: expected the program to give up with a message; screen: $(brief)"
fi

# TERM=dumb (Emacs' shell, some CI logs) cannot move the cursor: the plain mode, lines a
# person can read there, no escape sequence drawn
S=dumb
if wait_all 3 "has 'event t=0.00 ready: 2 masses' && has 'status t=0.00 x1=0.0000'"; then pass; else
    fail "TERM=dumb: expected the plain mode's lines; the screen shows only: $(grep -n . "$scr" | cut -c 1-100 | tr '\n' '|')"
fi
if ended && ! has 'TERMINAL SAME'; then fail "TERM=dumb: the terminal modes differ after exit"; fi

# ---- nothing died on the way ----
all_alive main small mid big resize tiny one ascii mono vt100 xterm8

summary
