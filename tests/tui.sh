#!/bin/sh
# tests/tui.sh: end-to-end tests of the interactive program (SPEC section 4): the real
# binary runs in tmux at several sizes, keys are sent to it, and the assertions are on the
# captured screens, on what a person would see. Run from the repository root as
# `sh tests/tui.sh`, with SPRINGSIM naming the binary (default ./springsim). Prints one line
# per failed check, then exactly one summary line "tui: N passed, M failed"; exits non-zero
# if anything failed.
#
# Everything runs on a private tmux server (tmux -L springsim-test-PID -f /dev/null), killed
# at exit; the user's own tmux server is never touched. Independent cases get a session
# each and are started together, so the whole run takes about 20 seconds.
#
# Cases: the first screen; run and pause; step and step back; reset; help; the preset
# menu; every preset for 1 s (no nan/inf); typing and adjusting a control; q, Ctrl-C,
# SIGTERM, SIGHUP and a crash restore the terminal; resizing (down to 1x1, a storm of
# sizes); all six plots at 80x24 and 160x48; LANG=C sends no byte >= 0x80; NO_COLOR;
# moving a mass with the keys; Ctrl-Z and fg; the analysis views (m modes, n nearest mode,
# f response, w sweep, e energy), s save with its confirmation and bad names, per-element
# editing saved and reloaded, x export, and branching from an earlier state.

SPRINGSIM=${SPRINGSIM:-./springsim}
case $SPRINGSIM in /*) ;; */*) SPRINGSIM=$PWD/$SPRINGSIM ;; esac

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() {
    failed=$((failed + 1))
    printf 'FAIL: %s\n' "$*"
}
summary() {
    echo "tui: $passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}

# A UTF-8 locale for the program's UTF-8 runs and for tmux itself.
U8=$(locale -a 2>/dev/null | grep -iE '^(C|en_US)\.utf-?8$' | head -n 1)
[ -n "$U8" ] || U8=C.UTF-8
LC_ALL=$U8
export LC_ALL

tmp=$(mktemp -d) || exit 1
SOCK=springsim-test-$$
# every tmux call goes to the private server
tm() { LC_ALL=$U8 LANG=$U8 tmux -u -L "$SOCK" -f /dev/null "$@"; }

sockpath=
cleanup() {
    tm kill-server >/dev/null 2>&1
    [ -n "$sockpath" ] && rm -f "$sockpath"
    rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' HUP INT TERM

if ! command -v tmux >/dev/null 2>&1; then
    fail "tmux is not installed (mk/deps.sh test installs it); no end-to-end test of the interactive program ran"
    summary
    exit
fi
if ! [ -x "$SPRINGSIM" ] && ! command -v "$SPRINGSIM" >/dev/null 2>&1; then
    fail "no program at SPRINGSIM=$SPRINGSIM"
    summary
    exit
fi


# The program never sees the user's presets or tmux.
mkdir -p "$tmp/xdg"
unset SPRINGSIM_PRESETS NO_COLOR COLORTERM TMUX TMUX_PANE

ESC=$(printf '\033')

# What every program pane runs: pane.sh DIR BINARY NAME [VAR=VALUE]... -- [ARG]...
# It records the terminal modes, runs the program in the foreground (its pid in
# DIR/NAME.pid), then shows "EXITED status" and whether the terminal modes came back.
cat >"$tmp/pane.sh" <<'EOF'
dir=$1 bin=$2 name=$3
shift 3
unset SPRINGSIM_PRESETS LC_CTYPE LC_MESSAGES LC_NUMERIC LANGUAGE NO_COLOR COLORTERM
while [ $# -gt 0 ] && [ "$1" != -- ]; do
    export "$1"
    shift
done
shift
trap : INT # a Ctrl-C meant for the program must not end this script
stty -g >"$dir/$name.before"
sh -c 'echo $$ >"$0"; exec "$@"' "$dir/$name.pid" "$bin" "$@"
echo "EXITED $?"
stty -g >"$dir/$name.after"
if cmp -s "$dir/$name.before" "$dir/$name.after"; then
    echo "TERMINAL SAME"
else
    echo "TERMINAL CHANGED"
fi
exec sleep 120
EOF

# start NAME COLS ROWS [VAR=VALUE]... [-- ARG...]: a session running the program in a
# UTF-8 locale with TERM=xterm-256color; later VAR=VALUE override those.
start() {
    s_name=$1 s_cols=$2 s_rows=$3
    shift 3
    case " $* " in *" -- "*) ;; *) set -- "$@" -- ;; esac
    tm new-session -d -s "$s_name" -x "$s_cols" -y "$s_rows" sh "$tmp/pane.sh" "$tmp" \
        "$SPRINGSIM" "$s_name" "LANG=$U8" "LC_ALL=$U8" TERM=xterm-256color \
        "XDG_CONFIG_HOME=$tmp/xdg" "$@"
}

# ---- looking at the screen; S is the session the helpers work on ----

# cap: the screen of session S into $scr as a person sees it. capture-pane -p shows cells
# drawn in the terminal's line-drawing character set (smacs, as ncurses uses for boxes
# with TERM=xterm-256color) as the letters sent (q for ─, x for │); with -e it marks them
# with SO/SI, so they are taken from there and turned into the characters they show, and
# the colour escapes are dropped.
S=
scr=$tmp/screen
ACS_AWK='BEGIN {
    from = "jklmnqtuvwx`afg~yz{|}"
    split("┘ ┐ ┌ └ ┼ ─ ├ ┤ ┴ ┬ │ ◆ ▒ ° ± · ≤ ≥ π ≠ £", to, " ")
}
{
    gsub(/\033\[[0-9;:?]*[A-Za-z]/, "")
    gsub(/\033\][^\007\033]*(\007|\033\\)/, "")
    out = ""
    len = length($0)
    for (i = 1; i <= len; i++) {
        c = substr($0, i, 1)
        if (c == "\016") { acs = 1; continue }
        if (c == "\017") { acs = 0; continue }
        if (acs && c != " " && (k = index(from, c)) > 0) c = to[k]
        out = out c
    }
    sub(/ +$/, "", out)
    print out
}'
cap() {
    tm capture-pane -e -p -t "$S" 2>/dev/null | awk "$ACS_AWK" >"$scr"
}
# cap_raw: the plain capture (for the check that no byte >= 0x80 reaches the terminal)
cap_raw() { tm capture-pane -p -t "$S" >"$scr" 2>/dev/null || : >"$scr"; }
has() { grep -qF -- "$1" "$scr"; }
has_re() { grep -qE -- "$1" "$scr"; }
keys() { tm send-keys -t "$S" "$@"; }
text() { tm send-keys -t "$S" -l "$1"; }

# brief [FILE] [REGEX]: a few lines of a screen in one line, for failure messages: the
# first line, up to three lines matching REGEX, and the last non-blank line.
brief() {
    b_f=${1:-$scr}
    {
        sed -n 1p "$b_f"
        [ -n "$2" ] && grep -E -- "$2" "$b_f" | head -n 3
        awk 'NF { l = $0 } END { print l }' "$b_f"
    } | sed 's/  */ /g; s/^ //; s/ $//' | awk '{ printf "%s%s", (NR > 1 ? " | " : ""), $0 }' |
        cut -c 1-600
}

# wait_for TEXT [SECONDS]: captures the screen every 0.1 s until it shows TEXT (a fixed
# string); false after the timeout (default 5 s), or at once if the program has exited.
wait_for() {
    w_n=$(awk -v s="${2:-5}" 'BEGIN { print int(s * 10 + 0.5) }')
    while :; do
        cap
        has "$1" && return 0
        case $1 in EXITED* | TERMINAL*) ;; *) has 'EXITED ' && return 1 ;; esac
        [ "$w_n" -le 0 ] && return 1
        w_n=$((w_n - 1))
        sleep 0.1
    done
}
wait_re() { # wait_re REGEX [SECONDS]
    w_n=$(awk -v s="${2:-5}" 'BEGIN { print int(s * 10 + 0.5) }')
    while :; do
        cap
        has_re "$1" && return 0
        has 'EXITED ' && return 1
        [ "$w_n" -le 0 ] && return 1
        w_n=$((w_n - 1))
        sleep 0.1
    done
}
wait_gone() { # wait_gone TEXT [SECONDS]
    w_n=$(awk -v s="${2:-5}" 'BEGIN { print int(s * 10 + 0.5) }')
    while :; do
        cap
        has "$1" || return 0
        [ "$w_n" -le 0 ] && return 1
        w_n=$((w_n - 1))
        sleep 0.1
    done
}
# first_diff EXPECTED ACTUAL: the first line where two screens differ, for messages.
first_diff() {
    awk 'NR == FNR { a[FNR] = $0; n = FNR; next }
         { b[FNR] = $0; m = FNR }
         END { for (i = 1; i <= (n > m ? n : m); i++) if (a[i] != b[i]) {
                   gsub(/  +/, " ", a[i]); gsub(/  +/, " ", b[i])
                   printf "line %d is \"%s\", expected \"%s\"", i, b[i], a[i]; exit } }' "$1" "$2"
}
# wait_same FILE [SECONDS]: until the screen is exactly FILE.
wait_same() {
    w_n=$(awk -v s="${2:-5}" 'BEGIN { print int(s * 10 + 0.5) }')
    while :; do
        cap
        cmp -s "$1" "$scr" && return 0
        [ "$w_n" -le 0 ] && return 1
        w_n=$((w_n - 1))
        sleep 0.1
    done
}

# The t of the status line (first line), "" if none.
status_t() { sed -n '1s/.* t = \(-\{0,1\}[0-9][0-9.]*\) s.*/\1/p' "$scr"; }
# t plus steps*0.01, formatted as the status line does
t_plus() { awk -v t="$1" -v k="$2" 'BEGIN { printf "%.2f", t + k * 0.01 }'; }
alive() { [ -s "$tmp/$1.pid" ] && kill -0 "$(cat "$tmp/$1.pid")" 2>/dev/null; }

# "nan" or "inf" as a number on screen (not inside a word such as "info").
has_nonfinite() { grep -qiE '(^|[^[:alpha:]])[-+]?(nan|inf)([^[:alpha:]]|inity|$)' "$scr"; }
# a byte outside printable ASCII
has_nonascii() { LC_ALL=C grep -q '[^ -~]' "$scr"; }
# an SGR colour (foreground or background, 8/16/256/direct), not just attributes or a
# reset to the default colours (39, 49)
COLOUR_RE="$ESC\\[([0-9;]*;)?(3[0-8]|4[0-8]|9[0-7]|10[0-7])(;[0-9;]*)?m"
has_colour() { grep -qE "$COLOUR_RE" "$1"; } # has_colour FILE (from capture-pane -e)

# ---- start everything at once ----

start main 120 40
start ctl 120 40
start chain 120 40
start menu 120 40
start resize 120 40
start small 80 24
start mid 100 30
start big 160 48
start ascii 120 40 LANG=C LC_ALL=C
start mono 120 40 NO_COLOR=1
for sig in q TERM HUP INT SEGV; do start "sig-$sig" 120 40; done
# the Ctrl-Z case needs a shell with job control
tm new-session -d -s job -x 120 -y 40 env "PS1=PROMPT\$ " ENV=/dev/null sh -i
presets=
for f in presets/*.ini; do
    [ -f "$f" ] || continue
    p=${f##*/}
    p=${p%.ini}
    presets="$presets $p"
    start "pre-$p" 120 40 -- -p "$p"
done
sockpath=$(tm display-message -p -t main '#{socket_path}' 2>/dev/null)

# ---- 1. the first screen at 120x40 ----
S=main
if wait_for Controls; then
    pass
    cp "$scr" "$tmp/main0"
    for want in Paused 't = 0.00 s' MOTOR 'Displacement (m)' 'Velocity (m/s)' 'x–v'; do
        if has "$want"; then pass; else fail "start 120x40: expected '$want'; screen: $(brief)"; fi
    done
    missing=
    for c in Preset Masses dt Damping 'Spring k' Mass 'Right end' Waveform Amplitude \
        Frequency Speed; do
        # a control is its label at the start of a line of the Controls panel
        grep -qE "(x|\\||│)( |>|▸)$c  " "$scr" || missing="$missing '$c'"
    done
    if [ -z "$missing" ]; then pass; else
        fail "start 120x40: Controls panel lacks$missing; panel: $(brief "$scr" '(Preset|Masses|Speed) ')"
    fi
    # 13 (the half that must find colour): colours are there without NO_COLOR
    tm capture-pane -e -p -t main >"$tmp/main0.e"
    if has_colour "$tmp/main0.e"; then pass; else
        fail "colour: expected colour escapes (ESC[3x / 38;5) in capture-pane -e with TERM=xterm-256color, found none"
    fi
    # 12 (the half that must find them): a UTF-8 screen has bytes >= 0x80
    cap_raw
    if has_nonascii; then pass; else fail "UTF-8: expected braille/box bytes >= 0x80 on the UTF-8 screen, found none"; fi
else
    fail "start 120x40: expected the Controls panel within 5 s; screen: $(brief)"
fi

# ---- 2. space runs, space pauses ----
S=main
keys Space
if wait_for Running; then
    pass
    t1=$(status_t)
    sleep 1
    cap
    t2=$(status_t)
    if awk -v a="$t1" -v b="$t2" 'BEGIN { d = b - a; exit !(a != "" && b != "" && d >= 0.5 && d <= 1.5) }'; then
        pass
    else
        fail "running: expected t to advance by about 1 s in 1 s of wall clock, got t = '$t1' then '$t2'; screen: $(brief)"
    fi
else
    fail "space: expected 'Running' in the status line; screen: $(brief)"
fi
keys Space
if wait_for Paused; then
    pass
    t1=$(status_t)
    sleep 0.5
    cap
    t2=$(status_t)
    if [ -n "$t1" ] && [ "$t1" = "$t2" ] && has Paused; then pass; else
        fail "paused: expected t to stay put over 0.5 s, got t = '$t1' then '$t2'; screen: $(brief)"
    fi
else
    fail "space again: expected 'Paused' in the status line; screen: $(brief)"
fi

# ---- 3. step and step back ----
S=main
cap
t0=$(status_t)
if [ -z "$t0" ]; then
    fail "step: no 't = X s' in the status line; screen: $(brief)"
else
    ok=1
    for k in 1 2 3; do
        keys .
        want=$(t_plus "$t0" "$k")
        if ! wait_for "t = $want s" 3; then
            fail "step: '.' number $k from t = $t0 s should show t = $want s; screen: $(brief)"
            ok=0
            break
        fi
    done
    [ $ok = 1 ] && pass
    cap
    t3=$(status_t)
    ok=1
    for k in 1 2 3; do
        keys ,
        want=$(t_plus "$t3" "-$k")
        if ! wait_for "t = $want s" 3; then
            fail "step back: ',' number $k from t = $t3 s should show t = $want s; screen: $(brief)"
            ok=0
            break
        fi
    done
    [ $ok = 1 ] && pass
fi

# ---- 4. reset ----
S=main
keys r
if wait_for 't = 0.00 s' && wait_re 'history 0( |$)'; then pass; else
    fail "reset: expected 't = 0.00 s' and 'history 0' after r; screen: $(brief)"
fi
# 3, continued: no step back before t = 0. Help opened and closed clears the message
# line (the hints show), so the message seen after ',' is its own.
S=main
keys '?'
wait_for 'preset menu' 3
keys '?'
wait_gone 'preset menu' 3
keys ,
n=20
while :; do
    cap
    last=$(awk 'NF { l = $0 } END { print l }' "$scr")
    case $last in *"space start"*) ;; *) break ;; esac
    [ $n -le 0 ] && break
    n=$((n - 1))
    sleep 0.1
done
case $last in
*"space start"*) fail "step back at t = 0: expected a message on the bottom line, it shows the key hints: $(brief)" ;;
*) if has 't = 0.00 s' && has_re 'history 0( |$)'; then pass; else
    fail "step back at t = 0: expected t to stay 0.00 s; screen: $(brief)"
fi ;;
esac

# ---- 5. help ----
S=main
keys '?'
if wait_for 'preset menu'; then
    # (the hints line has "space start" and the status line "q quit", with one space)
    if has_re 'space {2,}[a-z]' && has_re 'q {2,}quit' && has_re 'step (forward|back)'; then pass; else
        fail "help: expected lines for space, q quit and the steps; screen: $(brief "$scr" 'space|quit')"
    fi
    keys '?'
    if wait_gone 'preset menu' 3; then pass; else fail "help: '?' should close it; screen: $(brief "$scr" 'preset menu')"; fi
    keys '?'
    if wait_for 'preset menu' 3; then
        keys Escape
        if wait_gone 'preset menu' 3; then pass; else fail "help: Esc should close it; screen: $(brief "$scr" 'preset menu')"; fi
    else
        fail "help: '?' should open it a second time; screen: $(brief)"
    fi
else
    fail "help: '?' should open an overlay listing 'preset menu'; screen: $(brief)"
fi

# ---- 6. the preset menu ----
S=menu
if wait_for Controls; then
    keys p
    if wait_for ' Presets ' && wait_for resonance; then
        missing=
        for p in $presets; do
            grep -qE "(x|\\||│) $p( |\$)" "$scr" || missing="$missing $p"
        done
        if [ -z "$missing" ]; then pass; else
            fail "preset menu: expected every built-in preset listed, missing:$missing; screen: $(brief "$scr" 'Presets')"
        fi
        # move down from the first entry to resonance
        first=$(grep -n 'Presets' "$scr" | head -n 1 | cut -d: -f1)
        row=$(grep -nE '(x|\||│) resonance( |$)' "$scr" | head -n 1 | cut -d: -f1)
        if [ -n "$first" ] && [ -n "$row" ]; then
            n=$((row - first - 1))
            while [ "$n" -gt 0 ]; do
                keys Down
                n=$((n - 1))
            done
            sleep 0.2
            keys Enter
            if wait_re '(Preset) +Resonance'; then pass; else
                fail "preset menu: choosing resonance should show it in the Preset control; screen: $(brief "$scr" 'Preset ')"
            fi
            if wait_re '^.*0\.71 Hz.*N 1( |$)'; then pass; else
                fail "preset menu: after resonance the status line should show '0.71 Hz' and 'N 1'; screen: $(brief)"
            fi
        else
            fail "preset menu: cannot find the menu's title and resonance; screen: $(brief)"
        fi
    else
        fail "preset menu: 'p' should open a menu listing the presets; screen: $(brief)"
    fi
else
    fail "preset menu: the program did not start; screen: $(brief)"
fi

# ---- 8. a control: fine step, typed value, bad typed value ----
S=ctl
if wait_for Controls; then
    n=9 # Preset is first, Frequency tenth
    while [ "$n" -gt 0 ]; do
        keys Down
        n=$((n - 1))
    done
    if wait_re '(▸|>) ?Frequency'; then
        pass
        keys Right
        if wait_re 'Frequency +1\.010 Hz'; then pass; else
            fail "Frequency: → should raise 1.000 Hz to 1.010 Hz; screen: $(brief "$scr" 'Frequency')"
        fi
        keys Enter
        sleep 0.2
        text 0.5
        keys Enter
        if wait_re 'Frequency +0\.500 Hz'; then pass; else
            fail "Frequency: Enter, 0.5, Enter should set 0.500 Hz; screen: $(brief "$scr" 'Frequency')"
        fi
        keys Enter
        sleep 0.2
        text abc
        keys Enter
        if wait_for "'abc'"; then
            if has_re 'Frequency +0\.500 Hz'; then pass; else
                fail "Frequency: a bad value must change nothing (0.500 Hz); screen: $(brief "$scr" 'Frequency')"
            fi
        else
            fail "Frequency: typing abc should give a message naming 'abc'; screen: $(brief "$scr" 'Frequency')"
        fi
    else
        fail "controls: 9 × ↓ from Preset should select Frequency; screen: $(brief "$scr" 'Frequency|Speed')"
    fi
else
    fail "controls: the program did not start; screen: $(brief)"
fi

# ---- 14. Tab to the chain, move mass 1 ----
S=chain
if wait_for Controls; then
    sed -n '3,5p' "$scr" >"$tmp/scene0"
    keys Tab
    if wait_for 'mass 1'; then
        pass
        keys Right Right Right
        if wait_for 'mass 1 starts at +0.'; then pass; else
            fail "chain: → should move mass 1 ('mass 1 starts at +0.…'); screen: $(brief)"
        fi
        cap
        sed -n '3,5p' "$scr" >"$tmp/scene1"
        if cmp -s "$tmp/scene0" "$tmp/scene1"; then
            fail "chain: the scene rows did not change after moving mass 1; scene: $(brief "$tmp/scene1")"
        else
            pass
        fi
        keys r
        # any key clears the message line, so r has been handled once this one is gone
        if wait_gone 'mass 1 starts at' 3 && has 't = 0.00 s'; then
            cap
            sed -n '3,5p' "$scr" >"$tmp/scene2"
            if cmp -s "$tmp/scene1" "$tmp/scene2"; then pass; else
                fail "chain: r should restart from the moved position (scene as right after the move); scene: $(brief "$tmp/scene2")"
            fi
        else
            fail "chain: r should reset; screen: $(brief)"
        fi
    else
        fail "chain: Tab should select a mass ('mass 1 selected'); screen: $(brief)"
    fi
else
    fail "chain: the program did not start; screen: $(brief)"
fi

# ---- 11. 80x24 and 160x48 draw all six plots ----
check_plots() { # check_plots SESSION SIZE
    S=$1
    if wait_for Controls; then
        missing=
        for i in 1 2 3 4 5 6; do
            case $i in
            1) full='Displacement (m)' short='x (m)' ;;
            2) full='Velocity (m/s)' short='v (m/s)' ;;
            3) full='Acceleration (m/s²)' short='a (m/s²)' ;;
            4) full='x–v' short='x–v' ;;
            5) full='x–a' short='x–a' ;;
            6) full='v–a' short='v–a' ;;
            esac
            has " $full " || has " $short " || missing="$missing '$short'"
        done
        legends=$(grep -o '━1' "$scr" | wc -l)
        if [ -z "$missing" ] && [ "$legends" -ge 6 ]; then pass; else
            fail "$2: expected six plots (titles and a legend each), missing:$missing, legends: $legends; screen: $(brief "$scr" '(m/s|–)')"
        fi
        if has Paused && has MOTOR; then pass; else fail "$2: expected the status line and the scene; screen: $(brief)"; fi
        cp "$scr" "$tmp/$1.0"
    else
        fail "$2: the program did not start; screen: $(brief)"
    fi
}
check_plots small 80x24
check_plots big 160x48
check_plots mid 100x30

# ---- 10. resize ----
S=resize
if wait_for Controls; then
    cp "$scr" "$tmp/resize.0"
    tm resize-window -t resize -x 80 -y 24
    if [ -f "$tmp/small.0" ]; then
        if wait_same "$tmp/small.0"; then pass; else
            fail "resize 120x40 -> 80x24: expected the same screen as a fresh start at 80x24; $(first_diff "$tmp/small.0" "$scr")"
        fi
    fi
    tm resize-window -t resize -x 40 -y 12
    if wait_for 'Terminal too small' && has_re 'need [0-9]+x[0-9]+'; then pass; else
        fail "resize to 40x12: expected 'Terminal too small' and the size needed; screen: $(brief "$scr" 'small|need')"
    fi
    tm resize-window -t resize -x 1 -y 1
    sleep 0.3
    tm resize-window -t resize -x 100 -y 30
    if wait_for Controls && has Paused && has MOTOR && ! has 'too small' &&
        [ "$(awk 'END { print NR }' "$scr")" -eq 30 ]; then pass; else
        fail "resize 1x1 -> 100x30: expected the normal screen (Paused, MOTOR, Controls); screen: $(brief)"
    fi
    # a storm of sizes, then back to 120x40
    sizes=$(awk 'BEGIN { srand(7); print "1 1"; print "20 5"; print "200 60"
        for (i = 0; i < 47; i++) print int(1 + rand() * 220), int(1 + rand() * 70) }')
    echo "$sizes" | while read -r w h; do
        tm resize-window -t resize -x "$w" -y "$h"
        sleep 0.01
    done
    tm resize-window -t resize -x 120 -y 40
    if wait_same "$tmp/resize.0" && alive resize; then pass; else
        fail "resize storm (50 sizes incl. 1x1, 20x5, 200x60, then 120x40): expected the first screen again and the program alive; screen: $(brief)"
    fi
    keys Space
    if wait_for Running; then pass; else fail "after the resize storm: space should start it; screen: $(brief)"; fi
else
    fail "resize: the program did not start; screen: $(brief)"
fi

# ---- 12. LANG=C: ASCII only ----
S=ascii
if wait_for Controls; then
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
    sleep 0.8
    cap
    ascii_check running
    keys '?'
    if wait_for "preset menu"; then ascii_check help; else fail "LANG=C: ? should open the help; screen: $(brief)"; fi
    keys Escape
    sleep 0.2
    keys p
    if wait_for resonance; then ascii_check "preset menu"; else
        fail "LANG=C: p should open the preset menu; screen: $(brief)"
    fi
    keys Escape
else
    fail "LANG=C: the program did not start; screen: $(brief)"
fi

# ---- 13. NO_COLOR ----
S=mono
if wait_for Controls; then
    keys Space
    sleep 0.8
    tm capture-pane -e -p -t mono >"$tmp/mono.e"
    cap
    if has_colour "$tmp/mono.e"; then
        fail "NO_COLOR=1: expected no colour escapes in capture-pane -e, found: $(grep -oE "$ESC\\[[0-9;]*m" "$tmp/mono.e" | grep -E '\[([0-9;]*;)?(3[0-8]|4[0-8]|9[0-7]|10[0-7])' | sort -u | head -n 5 | tr -d "$ESC" | tr '\n' ' ')"
    else
        pass
    fi
    if has Running; then pass; else fail "NO_COLOR=1: expected it to run; screen: $(brief)"; fi
else
    fail "NO_COLOR: the program did not start; screen: $(brief)"
fi

# ---- 7. every preset runs 1 s: no crash, no nan/inf ----
started=
for p in $presets; do
    S=pre-$p
    if wait_for Controls 3; then
        keys Space
        started="$started $p"
    else
        fail "preset $p (-p $p): the program did not start; screen: $(brief)"
    fi
done
bad=
for _ in 1 2 3 4; do
    sleep 0.25
    for p in $started; do
        S=pre-$p
        cap
        if has_nonfinite; then
            case $bad in *" $p "*) ;; *)
                bad="$bad $p "
                fail "preset $p: nan/inf on screen while running; screen: $(brief "$scr" '[Nn][Aa][Nn]|[Ii][Nn][Ff]')"
                ;;
            esac
        fi
    done
done
for p in $started; do
    S=pre-$p
    cap
    t=$(status_t)
    if has Running && alive "pre-$p" && awk -v t="$t" 'BEGIN { exit !(t != "" && t >= 0.5) }'; then
        case $bad in *" $p "*) ;; *) pass ;; esac
    else
        fail "preset $p (-p $p): expected it running with t >= 0.5 s after 1 s; screen: $(brief)"
    fi
done

# ---- 9. quitting, signals and a crash restore the terminal ----
sent=
for sig in q TERM HUP INT SEGV; do
    S=sig-$sig
    if ! wait_for Controls; then
        fail "quit by $sig: the program did not start; screen: $(brief)"
        continue
    fi
    sent="$sent $sig"
    case $sig in
    q) keys q ;;
    INT) keys C-c ;;
    *) kill "-$sig" "$(cat "$tmp/sig-$sig.pid")" ;;
    esac
done
for sig in $sent; do
    S=sig-$sig
    case $sig in q) how="q" ;; INT) how="Ctrl-C" ;; SEGV) how="a crash (SIGSEGV)" ;; *) how="SIG$sig" ;; esac
    if wait_for 'TERMINAL ' 5; then
        if [ "$sig" = q ] && ! has 'EXITED 0'; then
            fail "quit by q: expected 'EXITED 0'; screen: $(brief "$scr" 'EXITED|TERMINAL')"
        elif [ "$sig" = INT ] && ! has 'EXITED 130'; then
            fail "quit by Ctrl-C: expected it to die of SIGINT (status 130); screen: $(brief "$scr" 'EXITED|TERMINAL')"
        elif [ "$sig" = TERM ] && ! has 'EXITED 143'; then
            fail "quit by SIGTERM: expected status 143; screen: $(brief "$scr" 'EXITED|TERMINAL')"
        elif [ "$sig" = HUP ] && ! has 'EXITED 129'; then
            fail "quit by SIGHUP: expected status 129; screen: $(brief "$scr" 'EXITED|TERMINAL')"
        elif [ "$sig" = SEGV ] && ! has_re 'EXITED [1-9]'; then
            fail "a crash (SIGSEGV): expected it to die with a non-zero status; screen: $(brief "$scr" 'EXITED|TERMINAL')"
        elif ! has 'TERMINAL SAME'; then
            fail "quit by $how: the terminal modes (stty -g) differ after exit; screen: $(brief "$scr" 'EXITED|TERMINAL')"
        else
            pass
        fi
    else
        fail "quit by $how: expected the program to exit within 5 s; screen: $(brief)"
    fi
done

# ---- 15. Ctrl-Z and fg ----
S=job
if wait_for 'PROMPT$' 3; then
    keys "stty -g >$tmp/job.before" Enter
    keys "LANG=$U8 LC_ALL=$U8 TERM=xterm-256color XDG_CONFIG_HOME=$tmp/xdg '$SPRINGSIM'" Enter
    if wait_for Controls; then
        keys C-z
        if wait_re 'Stopped|Suspended'; then
            pass
            keys "stty -g >$tmp/job.mid; cmp -s $tmp/job.before $tmp/job.mid && echo MID\"\"SAME" Enter
            if wait_for 'MIDSAME' 3; then pass; else
                fail "Ctrl-Z: the terminal modes while stopped should be the shell's again; screen: $(brief)"
            fi
            keys fg Enter
            if wait_for Controls; then
                keys Space
                if wait_for Running; then pass; else
                    fail "fg: expected the program to respond to space; screen: $(brief)"
                fi
                keys q
                if wait_gone Controls 3; then
                    keys "stty -g >$tmp/job.after; cmp -s $tmp/job.before $tmp/job.after && echo END\"\"SAME" Enter
                    if wait_for ENDSAME 3; then pass; else
                        fail "Ctrl-Z, fg, q: the terminal modes should be restored; screen: $(brief)"
                    fi
                else
                    fail "Ctrl-Z, fg: q should quit; screen: $(brief)"
                fi
            else
                fail "fg: expected the program's screen back; screen: $(brief)"
            fi
        else
            fail "Ctrl-Z: expected the shell to report the program stopped; screen: $(brief)"
        fi
    else
        fail "Ctrl-Z: the program did not start from the shell; screen: $(brief)"
    fi
else
    fail "Ctrl-Z: the shell in the pane did not start; screen: $(brief)"
fi

# ---- nothing died on the way ----
for s in main ctl chain menu resize small mid big ascii mono; do
    if alive "$s"; then pass; else
        S=$s
        cap
        fail "session $s: the program is no longer running; screen: $(brief "$scr" 'EXITED')"
    fi
done

# ---- 16. analysis views, per-element editing, save, export, branching (issue 4) ----
# Sessions of their own, started together; the ones that must run a while (energy, export,
# branching) are started first and looked at after the quick checks.

# start_in DIR NAME COLS ROWS [VAR=VALUE]... [-- ARG...]: start, with the program's working
# directory DIR.
start_in() {
    si_dir=$1
    shift
    s_name=$1 s_cols=$2 s_rows=$3
    shift 3
    case " $* " in *" -- "*) ;; *) set -- "$@" -- ;; esac
    tm new-session -d -s "$s_name" -c "$si_dir" -x "$s_cols" -y "$s_rows" sh "$tmp/pane.sh" \
        "$tmp" "$SPRINGSIM" "$s_name" "LANG=$U8" "LC_ALL=$U8" TERM=xterm-256color \
        "XDG_CONFIG_HOME=$tmp/xdg" "$@"
}
# wait_t SECONDS [TIMEOUT]: until the status line shows t >= SECONDS
wait_t() {
    w_n=$(awk -v s="${2:-6}" 'BEGIN { print int(s * 10 + 0.5) }')
    while :; do
        cap
        awk -v t="$(status_t)" -v m="$1" 'BEGIN { exit !(t != "" && t + 0 >= m) }' && return 0
        has 'EXITED ' && return 1
        [ "$w_n" -le 0 ] && return 1
        w_n=$((w_n - 1))
        sleep 0.1
    done
}
# the message line (the last non-blank line of the screen)
last_line() { awk 'NF { l = $0 } END { print l }' "$scr"; }
# history N of the status line
status_hist() { sed -n '1s/.*history \([0-9][0-9]*\).*/\1/p' "$scr"; }
# the status line's t after it has stayed put, i.e. once the program has paused
settled_t() {
    st_n=30
    st_a=
    while [ $st_n -gt 0 ]; do
        cap
        st_b=$(status_t)
        [ -n "$st_b" ] && [ "$st_b" = "$st_a" ] && has Paused && break
        st_a=$st_b
        st_n=$((st_n - 1))
        sleep 0.15
    done
    echo "$st_b"
}
# select_control NAME: from the first control (Preset), ↓ until NAME is selected
select_control() {
    sc_n=0
    while [ $sc_n -lt 12 ]; do
        cap
        has_re "(▸|>) ?$1 " && return 0
        keys Down
        sc_n=$((sc_n + 1))
        sleep 0.05
    done
    wait_re "(▸|>) ?$1 " 2
}

mkdir -p "$tmp/exp"
start an-energy 120 40 -- -p 3-mass-chain
start an-nodamp 120 40 -- -p no-damping
start_in "$tmp/exp" an-export 120 40
start an-branch 120 40
start an-sweep 120 40 -- -p 3-mass-chain
start an-modes 120 40 -- -p 3-mass-chain
start an-near 120 40 -- -p 3-mass-chain --frequency 0.9
start an-resp 120 40 -- -p 3-mass-chain
start an-wall 120 40 -- -p 3-mass-chain --boundary wall
start an-save 120 40 "XDG_CONFIG_HOME=$tmp/xdg-save" -- -p 3-mass-chain
start an-edit 120 40 "XDG_CONFIG_HOME=$tmp/xdg-edit" -- -p 3-mass-chain
an_sessions="an-energy an-nodamp an-export an-branch an-sweep an-modes an-near an-resp an-wall an-save an-edit"

# the long runs first
an_running=
for s in an-energy an-nodamp an-export an-branch; do
    S=$s
    if wait_for Controls; then
        case $s in an-energy | an-nodamp) keys e ;; esac
        keys Space
        an_running="$an_running $s "
    else
        fail "$s: the program did not start; screen: $(brief)"
    fi
done
an_up() { # an_up SESSION: S=SESSION, true if it started
    S=$1
    wait_for Controls && return 0
    fail "$1: the program did not start; screen: $(brief)"
    return 1
}

# ---- 16a. m: the modes view ----
if an_up an-modes; then
    keys m
    if wait_re '┌─+ Modes'; then
        pass
        missing=
        for f in '0.385 Hz' '0.712 Hz' '0.930 Hz'; do has "$f" || missing="$missing '$f'"; done
        if [ -z "$missing" ]; then pass; else
            fail "modes (m, -p 3-mass-chain): expected the natural frequencies, missing$missing; screen: $(brief "$scr" 'Modes|Hz')"
        fi
        # the driven mark is on mode 2 only
        if has_re '(^|[^0-9])1 +0\.385 Hz +2 +0\.712 Hz +◆ driven +3 +0\.930 Hz' &&
            [ "$(grep -o '◆ driven' "$scr" | wc -l)" -eq 1 ]; then pass; else
            fail "modes: expected '◆ driven' once, next to mode 2 (0.712 Hz); screen: $(brief "$scr" 'driven|0\.385')"
        fi
        if has_re 'Frequency +0\.712 Hz ◆ f2'; then pass; else
            fail "modes: the Frequency control should show '0.712 Hz ◆ f2'; screen: $(brief "$scr" 'Frequency')"
        fi
        keys m
        if wait_for 'Displacement (m)' 3 && ! has_re '┌─+ Modes'; then pass; else
            fail "modes: m again should bring back the six plots; screen: $(brief "$scr" 'Modes|Displacement')"
        fi
    else
        fail "modes: m should open a frame titled 'Modes'; screen: $(brief)"
    fi
fi

# ---- 16b. n: drive at the nearest natural frequency ----
if an_up an-near; then
    if has_re 'Frequency +0\.900 Hz' && ! has_re 'Frequency +0\.900 Hz ◆'; then pass; else
        fail "n: --frequency 0.9 should show 'Frequency 0.900 Hz' with no mode mark; screen: $(brief "$scr" 'Frequency')"
    fi
    keys n
    if wait_re 'Frequency +0\.930 Hz ◆ f3' 3; then
        if sed -n 1p "$scr" | grep -qF ' 0.93 Hz'; then pass; else
            fail "n: the status line's motor should say 0.93 Hz; screen: $(brief)"
        fi
    else
        fail "n (from 0.9 Hz, -p 3-mass-chain): expected 'Frequency 0.930 Hz ◆ f3'; screen: $(brief "$scr" 'Frequency')"
    fi
fi

# ---- 16c. f: the frequency response view ----
if an_up an-resp; then
    keys f
    if wait_re '┌─+ Frequency response'; then
        pass
        if has_re ' 1e-1┤' && has_re ' 1e-2┤'; then pass; else
            fail "response (f): expected decade labels 1e-1, 1e-2 on the amplitude axis; screen: $(brief "$scr" '┤')"
        fi
        if has_re '^│ Hz .* 5 *│'; then pass; else
            fail "response: the frequency axis should end at 5 (Hz); screen: $(brief "$scr" '^│ Hz')"
        fi
        if has_re '└.*drive 0\.712 Hz'; then pass; else
            fail "response: the bottom border should mention 'drive 0.712 Hz'; screen: $(brief "$scr" 'drive')"
        fi
        if has_re '━1.*━2.*━3'; then pass; else
            fail "response: expected a legend for masses 1-3; screen: $(brief "$scr" '━')"
        fi
        keys f
        if wait_for 'Displacement (m)' 3 && ! has 'Frequency response'; then pass; else
            fail "response: f again should bring back the six plots; screen: $(brief)"
        fi
    else
        fail "response: f should open a frame titled 'Frequency response'; screen: $(brief)"
    fi
fi
if an_up an-wall; then
    keys f
    if wait_for 'Frequency response' && wait_for 'does not drive the chain' 2; then pass; else
        fail "response with --boundary wall: expected 'does not drive the chain'; screen: $(brief "$scr" 'drive|response')"
    fi
    keys w
    sleep 0.4
    cap
    if has Paused && ! has 'sweep 1/'; then pass; else
        fail "w with --boundary wall: no sweep should start (nothing drives the chain); screen: $(brief)"
    fi
fi

# ---- 16d. w: the sine sweep ----
if an_up an-sweep; then
    keys w
    if wait_re 'sweep 1/40 at [0-9.]+ Hz'; then
        pass
        if has 'Frequency response' && has Running; then pass; else
            fail "sweep (w from the plots): expected the response view, running; screen: $(brief)"
        fi
        # the motor runs at the frequency the sweep says
        f=$(sed -n 's/.*sweep 1\/40 at \([0-9.]*\) Hz.*/\1/p' "$scr" | head -n 1)
        want=$(awk -v f="$f" 'BEGIN { printf "%.2f Hz", f }')
        if sed -n 1p "$scr" | grep -qF " $want "; then pass; else
            fail "sweep: the status line's motor should run at the sweep's $f Hz ($want); screen: $(brief)"
        fi
        keys w
        if wait_for 'sweep stopped after' 3; then
            if ! has 'sweep 1/40'; then pass; else
                fail "sweep: after w the bottom border should no longer show the sweep; screen: $(brief "$scr" sweep)"
            fi
        else
            fail "sweep: w again should stop it with 'sweep stopped after'; screen: $(brief)"
        fi
    else
        fail "sweep: w should start a sweep ('sweep 1/40 at ... Hz'); screen: $(brief "$scr" sweep)"
    fi
fi

# ---- 16e. e: the energy view (running since the start of this section) ----
S=an-energy
case $an_running in *" an-energy "*)
    if wait_t 2; then
        keys Space
        t=$(settled_t)
        if has_re '┌─+ Energy \(J\): balance'; then pass; else
            fail "energy (e): expected a frame titled 'Energy (J): balance'; screen: $(brief)"
        fi
        drift=$(sed -n 's/.*Energy (J): balance .*drift \([-+0-9.e]*\) J.*/\1/p' "$scr" | head -n 1)
        if awk -v d="$drift" 'BEGIN { exit !(d ~ /^[-+]?[0-9]/ && d + 0 < 1e-4 && d + 0 > -1e-4) }'; then pass; else
            fail "energy: after $t s of -p 3-mass-chain the drift should be below 1e-4 J, title says '$drift'; screen: $(brief "$scr" 'Energy')"
        fi
        missing=
        for w in kinetic potential dissipated 'motor work' collisions; do
            grep -qE "^└.* $w [-0-9]" "$scr" || missing="$missing '$w'"
        done
        if [ -z "$missing" ]; then pass; else
            fail "energy: after $t s at 120x40 the legend lacks$missing; legend: $(brief "$scr" '^└.*kinetic')"
        fi
        wk=$(sed -n 's/^└.* motor work \([-0-9][-0-9.e+]*\) .*/\1/p' "$scr")
        if awk -v w="$wk" 'BEGIN { exit !(w != "" && w + 0 > 0) }'; then pass; else
            fail "energy: the motor should have done work after $t s, legend says '$wk'; legend: $(brief "$scr" '^└.*kinetic')"
        fi
    else
        fail "energy: expected it to run to t = 2 s; screen: $(brief)"
    fi
    ;;
esac
S=an-nodamp
case $an_running in *" an-nodamp "*)
    if wait_t 3; then
        keys Space
        t=$(settled_t)
        kp=$(sed -n 's/^└.* kinetic \([-0-9][-0-9.e+]*\) .*potential \([-0-9][-0-9.e+]*\) .*/\1 \2/p' "$scr")
        if awk -v kp="$kp" 'BEGIN { n = split(kp, a, " "); s = a[1] + a[2]
                               exit !(n == 2 && s > 39.9 && s < 40.1) }'; then pass; else
            fail "energy, -p no-damping: after $t s kinetic + potential should be 40 J, legend: '$kp'; screen: $(brief "$scr" '^└.*kinetic')"
        fi
    else
        fail "energy, -p no-damping: expected it to run to t = 3 s; screen: $(brief)"
    fi
    ;;
esac

# ---- 16f. x: export CSV into the working directory ----
S=an-export
case $an_running in *" an-export "*)
    if wait_t 1; then
        keys Space
        t=$(settled_t)
        keys x
        if wait_re 'exported [0-9]+ rows to \./springsim-[0-9]{8}-[0-9]{6}\.csv'; then
            pass
            n=$(sed -n 's/.*exported \([0-9][0-9]*\) rows to .*/\1/p' "$scr" | head -n 1)
            f=$(sed -n 's/.*exported [0-9]* rows to \.\/\(springsim-[0-9]*-[0-9]*\.csv\).*/\1/p' "$scr" | head -n 1)
            if [ -f "$tmp/exp/$f" ] && [ "$(ls -A "$tmp/exp" | wc -l)" -eq 1 ]; then
                pass
                if awk -F, -v n="$n" -v t="$t" '
                    NR == 1 { ok = ($0 == "t,x1,x2,v1,v2,a1,a2,motor"); next }
                    { rows++
                      if (NF != 8 || tolower($0) ~ /nan|inf/) ok = 0
                      for (i = 1; i <= NF; i++) if ($i !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) ok = 0
                      if (rows > 1 && $1 + 0 <= last) ok = 0
                      last = $1 + 0 }
                    END { exit !(ok && rows == n && rows > 50 && last > t - 0.005 && last < t + 0.005) }' \
                    "$tmp/exp/$f"; then pass; else
                    fail "export: $f should have the header t,x1,x2,v1,v2,a1,a2,motor, $n rows of 8 numbers, t increasing to $t; it has $(($(wc -l <"$tmp/exp/$f") - 1)) rows: $(sed -n '1p;2p;$p' "$tmp/exp/$f" | tr '\n' '|')"
                fi
            else
                fail "export: expected only $f in the working directory; found: $(ls -A "$tmp/exp" | tr '\n' ' ')"
            fi
        else
            fail "export: x should say 'exported N rows to ./springsim-YYYYmmdd-HHMMSS.csv'; screen: $(brief)"
        fi
    else
        fail "export: expected it to run to t = 1 s; screen: $(brief)"
    fi
    ;;
esac

# ---- 16g. branch from history: step back, change a parameter, go on ----
S=an-branch
case $an_running in *" an-branch "*)
    if wait_t 2; then
        keys Space
        t0=$(settled_t)
        h0=$(status_hist)
        k=0
        while [ $k -lt 50 ]; do
            keys ,
            k=$((k + 1))
        done
        tb=$(t_plus "$t0" -50)
        if wait_for "t = $tb s" 3; then
            hb=$(status_hist)
            if [ -n "$h0" ] && [ "$hb" = "$((h0 - 50))" ]; then pass; else
                fail "branch: 50 × ',' from history $h0 should leave history $((h0 - 50)); screen: $(brief)"
            fi
            if select_control Amplitude; then
                keys Right
                wait_re 'Amplitude +1\.05 m' 2
                keys .
                want=$(t_plus "$tb" 1)
                if wait_for "t = $want s" 3 && [ "$(status_hist)" = "$((hb + 1))" ]; then pass; else
                    fail "branch: after stepping back to t = $tb s (history $hb), → on Amplitude and '.', expected t = $want s and history $((hb + 1)); screen: $(brief)"
                fi
            else
                fail "branch: cannot select Amplitude; screen: $(brief "$scr" Amplitude)"
            fi
        else
            fail "branch: 50 × ',' from t = $t0 s should show t = $tb s; screen: $(brief)"
        fi
    else
        fail "branch: expected it to run to t = 2 s; screen: $(brief)"
    fi
    ;;
esac

# ---- 16h. s: save a preset ----
xs=$tmp/xdg-save
pdir=$xs/springsim/presets
save_as() { # save_as NAME: s, NAME, Enter; true once the prompt is gone
    keys s
    wait_for 'save preset as' 3 || return 1
    [ -n "$1" ] && text "$1"
    keys Enter
    wait_gone 'save preset as' 3
}
if an_up an-save; then
    if save_as mychain && wait_for 'saved ' 3 && has 'springsim/presets/mychain.ini'; then pass; else
        fail "save: s, mychain, Enter should say 'saved' and the path; screen: $(brief)"
    fi
    if [ -f "$pdir/mychain.ini" ]; then
        pass
        cp "$pdir/mychain.ini" "$tmp/mychain.1"
        XDG_CONFIG_HOME=$xs "$SPRINGSIM" -p mychain --modes >"$tmp/modes.saved" 2>&1
        "$SPRINGSIM" -p 3-mass-chain --modes >"$tmp/modes.orig" 2>&1
        if [ "$(awk -F, 'NR > 1 { printf "%.3f ", $2 }' "$tmp/modes.saved")" = "0.385 0.712 0.930 " ] &&
            cmp -s "$tmp/modes.saved" "$tmp/modes.orig"; then pass; else
            fail "save: -p mychain --modes should print what -p 3-mass-chain --modes does; got: $(head -n 4 "$tmp/modes.saved" | tr '\n' '|')"
        fi
    else
        fail "save: expected the file \$XDG_CONFIG_HOME/springsim/presets/mychain.ini; found: $(find "$xs" 2>/dev/null | tr '\n' ' ')"
    fi
    # change a value, save under the same name: n keeps the file, y replaces it
    if select_control Amplitude; then
        keys Right
        if wait_re 'Amplitude +0\.10 m' 2; then
            keys s
            wait_for 'save preset as' 3
            text mychain
            keys Enter
            if wait_for 'replace it? (y/n)' 3; then
                pass
                keys n
                if wait_gone 'replace it?' 3 && cmp -s "$tmp/mychain.1" "$pdir/mychain.ini"; then pass; else
                    fail "save: n to 'replace it?' should keep the old file; screen: $(brief)"
                fi
                keys s
                wait_for 'save preset as' 3
                text mychain
                keys Enter
                wait_for 'replace it? (y/n)' 3
                keys y
                if wait_for 'saved ' 3 && ! cmp -s "$tmp/mychain.1" "$pdir/mychain.ini" &&
                    grep -qE '^amplitude *= *0\.1$' "$pdir/mychain.ini"; then pass; else
                    fail "save: y to 'replace it?' should write the new amplitude 0.1; file: $(grep amplitude "$pdir/mychain.ini"); screen: $(brief)"
                fi
            else
                fail "save: saving mychain again should ask 'replace it? (y/n)'; screen: $(brief)"
            fi
        else
            fail "save: → on Amplitude should make it 0.10 m; screen: $(brief "$scr" Amplitude)"
        fi
    else
        fail "save: cannot select the Amplitude control; screen: $(brief "$scr" Amplitude)"
    fi
    # bad names: a message, nothing written
    find "$xs" 2>/dev/null | sort >"$tmp/xs.before"
    long=$(awk 'BEGIN { while (i++ < 65) printf "a" }')
    for nm in ../x '' a/b "$long"; do
        case $nm in '') what="an empty name" ;; "$long") what="a 65-character name" ;; *) what="'$nm'" ;; esac
        if save_as "$nm"; then
            l=$(last_line)
            case $l in
            *saved* | *"space start"* | '') fail "save with $what: expected a message saying why not; message line: '$l'" ;;
            *) pass ;;
            esac
        else
            fail "save with $what: the prompt did not come and go; screen: $(brief)"
            break
        fi
        find "$xs" 2>/dev/null | sort >"$tmp/xs.after"
        if cmp -s "$tmp/xs.before" "$tmp/xs.after"; then pass; else
            fail "save with $what: nothing should be written, new: $(comm -13 "$tmp/xs.before" "$tmp/xs.after" | sed "s|^$xs/||" | tr '\n' ' ')"
            cp "$tmp/xs.after" "$tmp/xs.before"
        fi
    done
fi

# ---- 16i. per-element editing ----
xe=$tmp/xdg-edit
if an_up an-edit; then
    keys Tab
    if wait_re '└─ mass 1: m 1 kg'; then
        pass
        sed -n '3,5p' "$scr" >"$tmp/edit.scene0"
        keys Enter
        text 2.5
        keys Enter
        if wait_for 'mass 1: m = 2.5 kg' 3; then
            if has_re 'Mass +mixed kg'; then pass; else
                fail "per-element: after mass 1 = 2.5 kg the Mass control should show 'mixed kg'; screen: $(brief "$scr" 'Mass ')"
            fi
            sed -n '3,5p' "$scr" >"$tmp/edit.scene1"
            if cmp -s "$tmp/edit.scene0" "$tmp/edit.scene1"; then
                fail "per-element: mass 1 at 2.5 kg should look different from the 1 kg ones; scene unchanged: $(brief "$tmp/edit.scene1")"
            else
                pass
            fi
        else
            fail "per-element: Enter, 2.5, Enter on mass 1 should say 'mass 1: m = 2.5 kg'; screen: $(brief)"
        fi
        keys Down
        if wait_re '└─ spring 1: k 10 N/m' 3; then
            keys Enter
            text 22
            keys Enter
            if wait_for 'spring 1: k = 22 N/m' 3 && has_re 'Spring k +mixed N/m'; then pass; else
                fail "per-element: spring 1 Enter 22 Enter should say 'spring 1: k = 22 N/m' and Spring k 'mixed N/m'; screen: $(brief "$scr" 'Spring k')"
            fi
        else
            fail "per-element: ↓ from mass 1 should select spring 1; screen: $(brief "$scr" '└─ (mass|spring)')"
        fi
        keys Up
        if wait_re '└─ mass 1: m 2\.5 kg' 3; then
            keys c
            text 0.3
            keys Enter
            if wait_for 'mass 1: c = 0.3 N·s/m' 3 && has_re 'Damping +mixed'; then pass; else
                fail "per-element: c, 0.3, Enter on mass 1 should set its damping ('mass 1: c = 0.3 N·s/m', Damping 'mixed'); screen: $(brief "$scr" 'Damping')"
            fi
        else
            fail "per-element: ↑ from spring 1 should select mass 1 again; screen: $(brief "$scr" '└─ (mass|spring)')"
        fi
        # the modes view follows the edits
        "$SPRINGSIM" -n 3 --mass 2.5,1,1 --spring 10,22,10,10 --modes >"$tmp/modes.cli" 2>&1
        fl=$(awk -F, 'NR > 1 { printf "%.3f ", $2 }' "$tmp/modes.cli")
        keys m
        if wait_for Modes 3; then
            missing=
            for f in $fl; do has "$f Hz" || missing="$missing $f"; done
            if [ -n "$fl" ] && [ -z "$missing" ]; then pass; else
                fail "per-element: the modes view should show the edited chain's frequencies ($fl), missing$missing; screen: $(brief "$scr" 'Hz')"
            fi
            keys m
            wait_for 'Displacement (m)' 3
        else
            fail "per-element: m should open the modes view; screen: $(brief)"
        fi
        keys s
        wait_for 'save preset as' 3
        text pe
        keys Enter
        f=$xe/springsim/presets/pe.ini
        if wait_for 'saved ' 3 && [ -f "$f" ]; then
            if grep -qE '^mass *= *2\.5, *1, *1$' "$f" &&
                grep -qE '^damping *= *0\.3, *0\.1, *0\.1$' "$f" &&
                awk -F'[=,]' '/^spring *=/ { n = NF - 1; k2 = $3 + 0 } END { exit !(n == 4 && k2 == 22) }' "$f"; then
                pass
            else
                fail "per-element: pe.ini should have mass = 2.5, 1, 1, damping 0.3, 0.1, 0.1 and four springs with 22 second; it has: $(grep -E '^(mass|spring|damping) *=' "$f" | tr '\n' '|')"
            fi
            XDG_CONFIG_HOME=$xe "$SPRINGSIM" -p pe --modes >"$tmp/modes.pe" 2>&1
            if cmp -s "$tmp/modes.pe" "$tmp/modes.cli" && ! cmp -s "$tmp/modes.pe" "$tmp/modes.orig"; then pass; else
                fail "per-element: -p pe --modes should match --mass 2.5,1,1 --spring 10,22,10,10 --modes and differ from the uniform chain; got: $(head -n 2 "$tmp/modes.pe" | tr '\n' '|')"
            fi
        else
            fail "per-element: s, pe, Enter should save \$XDG_CONFIG_HOME/springsim/presets/pe.ini; screen: $(brief)"
        fi
    else
        fail "per-element: Tab should select mass 1 ('mass 1: m 1 kg' on the scene's border); screen: $(brief "$scr" 'mass 1')"
    fi
fi

for s in $an_sessions; do
    if alive "$s"; then pass; else
        S=$s
        cap
        fail "session $s: the program is no longer running; screen: $(brief "$scr" 'EXITED')"
    fi
done

summary
