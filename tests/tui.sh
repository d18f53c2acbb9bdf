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
# each and are started together, so the whole run takes about 15 seconds.
#
# Cases: the first screen; run and pause; step and step back; reset; help; the preset
# menu; every preset for 1 s (no nan/inf); typing and adjusting a control; q, Ctrl-C,
# SIGTERM, SIGHUP and a crash restore the terminal; resizing (down to 1x1, a storm of
# sizes); all six plots at 80x24 and 160x48; LANG=C sends no byte >= 0x80; NO_COLOR;
# moving a mass with the keys; Ctrl-Z and fg.

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

summary
