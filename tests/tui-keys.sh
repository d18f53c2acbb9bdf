#!/bin/sh
# tests/tui-keys.sh: the interactive program's keys (springsim(1), KEYS) in a real terminal
# (tmux): space runs and pauses, . and , step, r resets, the help (and its scrolling at
# 80x24: every key of --keys in it, whole), the preset menu and every preset for a
# second, a control adjusted and typed into, the footer's hints as the state changes,
# t and dt with the digits dt needs, moving a mass with the keys, branching from an
# earlier state, and Ctrl-Z with fg. Run from the repository root as
# `sh tests/tui-keys.sh`, SPRINGSIM naming the binary. Ends with
# "tui-keys: N passed, M failed".
NAME=tui-keys
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

# "nan" or "inf" as a number on screen (not inside a word such as "info").
has_nonfinite() { grep -qiE '(^|[^[:alpha:]])[-+]?(nan|inf)([^[:alpha:]]|inity|$)' "$scr"; }
# the keys a terminal (xterm, in keypad mode) sends for Home and End
home() { text "${ESC}OH"; }
end() { text "${ESC}OF"; }

start main 120 40
start ctl 120 40
start chain 120 40
start menu 120 40
start help 80 24
start help60 60 20
start hints 120 40
start hints80 80 24
start dt1 120 40 -- --dt 0.001
start dt75 120 40 -- --dt 0.0075
start branch 120 40
start_shell job 120 40 # Ctrl-Z needs a shell with job control
presets=
for f in presets/*.ini; do
    [ -f "$f" ] || continue
    p=${f##*/}
    p=${p%.ini}
    presets="$presets $p"
    start "pre-$p" 100 30 -- -p "$p"
done
# the ones that run a while start first
started=
for p in $presets; do
    if up "pre-$p"; then
        keys Space
        started="$started $p"
    fi
done
if up branch; then keys Space; fi

# ---- space runs, space pauses ----
if up main; then
    keys Space
    if wait_for Running; then
        pass
        t1=$(status_t) w1=$(date +%s.%N)
        sleep 1 # a second or more of wall clock, measured: w2 - w1
        cap
        t2=$(status_t) w2=$(date +%s.%N)
        if awk -v a="$t1" -v b="$t2" -v w1="$w1" -v w2="$w2" 'BEGIN { d = b - a; w = w2 - w1
                exit !(a != "" && b != "" && d >= w - 0.5 && d <= w + 0.5) }'; then
            pass
        else
            fail "running: expected t to advance as the wall clock did ($(awk -v a="$w1" -v b="$w2" 'BEGIN { printf "%.2f", b - a }') s, within 0.5 s) between two captures, got t = '$t1' then '$t2'; screen: $(brief)"
        fi
    else
        fail "space: expected 'Running' in the status line; screen: $(brief)"
    fi
    keys Space
    if wait_for Paused; then
        pass
        t1=$(status_t)
        sleep 0.5 # half a second in which nothing may move
        cap
        t2=$(status_t)
        if [ -n "$t1" ] && [ "$t1" = "$t2" ] && has Paused; then pass; else
            fail "paused: expected t to stay put over 0.5 s, got t = '$t1' then '$t2'; screen: $(brief)"
        fi
    else
        fail "space again: expected 'Paused' in the status line; screen: $(brief)"
    fi

    # ---- step and step back ----
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

    # ---- reset, and no step back before t = 0 ----
    keys r
    if wait_for 't = 0.00 s' && wait_re 'history 0( |$)'; then pass; else
        fail "reset: expected 't = 0.00 s' and 'history 0' after r; screen: $(brief)"
    fi
    # the help opened and closed clears the message line (the hints show), so the
    # message seen after ',' is its own
    keys '?'
    wait_for 'preset menu' 3
    keys '?'
    wait_gone 'preset menu' 3
    wait_for 'space start' 3
    keys ,
    if poll 3 lacks 'space start'; then
        if has 't = 0.00 s' && has_re 'history 0( |$)'; then pass; else
            fail "step back at t = 0: expected t to stay 0.00 s; screen: $(brief)"
        fi
    else
        fail "step back at t = 0: expected a message on the bottom line, it shows the key hints: $(brief)"
    fi

    # ---- help opens and closes ----
    keys '?'
    if wait_for 'preset menu'; then
        # the first page starts with space and the steps; q quit is the last line (End)
        if has_re 'space {2,}start / pause' && has_re 'step (forward|back)'; then pass; else
            fail "help: expected lines for space and the steps; screen: $(brief "$scr" 'space|step')"
        fi
        end
        if poll 3 has_re '│ q {2,}quit'; then pass; else
            fail "help: End should show the line for q quit; screen: $(brief "$scr" 'quit')"
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
fi

# ---- the help at 80x24 scrolls, and holds every key ----
"$SPRINGSIM" --keys >"$tmp/keys" 2>&1
# help_pos: "FIRST LAST COUNT" of the help's "lines FIRST–LAST of COUNT"
help_pos() { sed -n 's/.*lines \([0-9]*\)–\([0-9]*\) of \([0-9]*\).*/\1 \2 \3/p' "$scr" | head -n 1; }
pos_not() { [ "$(help_pos)" != "$1" ]; }
# page_to_end FILE: PgDn through the help to its end, each page's text appended to FILE
page_to_end() {
    n=0
    while lacks '(end)' && [ $n -lt 30 ]; do
        p=$(help_pos)
        keys PgDn
        poll 3 pos_not "$p" || break
        help_body >>"$1"
        n=$((n + 1))
    done
}
# help_body: the overlay's text lines (inside its frame, above "lines a–b of N")
help_body() {
    awk '/ Keys / { on = 1; next } / lines [0-9]+–[0-9]+ of / { on = 0 } on' "$scr" |
        sed 's/^ *[^ ]*│ //; s/ *│[^ ]*$//'
}
if up help; then
    keys '?'
    if wait_for 'preset menu'; then
        p=$(help_pos)
        rows=$(help_body | wc -l)
        set -- $p
        if [ $# -eq 3 ] && [ "$1" -eq 1 ] && [ "$2" -lt "$3" ] && [ $(($2 - $1 + 1)) -eq "$rows" ] &&
            has '▼ more'; then pass; else
            fail "help at 80x24: expected 'lines 1–B of N' with B < N (the rows shown) and '▼ more'; shows $rows rows: $(brief "$scr" 'lines')"
        fi
        help_body >"$tmp/help.1"
        cp "$tmp/help.1" "$tmp/help.all"
        keys Down
        if poll 3 pos_not "$p" && [ "$(help_pos)" = "2 $(($2 + 1)) $3" ] &&
            [ "$(help_body | sed -n 1p)" = "$(sed -n 2p "$tmp/help.1")" ]; then pass; else
            fail "help: ↓ should scroll one line (lines 2–$(($2 + 1)) of $3); $(brief "$scr" 'lines')"
        fi
        help_body >>"$tmp/help.all"
        page_to_end "$tmp/help.all"
        last=$(help_pos)
        if has '(end)' && [ "${last#* }" = "$3 $3" ] && help_body | grep -qE '^q +quit$'; then pass; else
            fail "help: PgDn to the end should show 'q quit' and 'lines a–$3 of $3 (end)'; screen: $(brief "$scr" 'lines|quit')"
        fi
        # every key of --keys, and what it does, whole
        missing=
        cut=
        shown=
        tr -s ' ' <"$tmp/help.all" | tr '\n' ' ' >"$tmp/help.text"
        tab=$(printf '\t')
        while IFS=$tab read -r k what; do
            ks=$(printf '%s' "$k" | sed 's/, / /g')
            grep -qF -- "$ks " "$tmp/help.all" || missing="$missing '$k'"
            grep -qF -- "$(printf '%s' "$what" | tr -s ' ')" "$tmp/help.text" || {
                cut="$cut | $k: $what"
                shown="$shown | $(grep -F -- "$ks " "$tmp/help.all" | head -n 1)"
            }
        done <"$tmp/keys"
        if [ -s "$tmp/keys" ] && [ -z "$missing" ]; then pass; else
            fail "help at 80x24: scrolled from top to end, these keys of springsim --keys are missing:$missing"
        fi
        if [ -s "$tmp/keys" ] && [ -z "$cut" ]; then pass; else
            fail "help at 80x24: these lines of springsim --keys are not shown whole$cut; the help shows$shown"
        fi
        p=$(help_pos)
        keys PgUp
        if wait_all 3 "pos_not '$p' && lacks '(end)'"; then pass; else
            fail "help: PgUp from the end should scroll back up; screen: $(brief "$scr" 'lines')"
        fi
        home
        if poll 3 has_re 'lines 1–[0-9]+ of' && [ "$(help_body | sed -n 1p)" = "$(sed -n 1p "$tmp/help.1")" ]; then
            pass
        else
            fail "help: Home should go back to the first line; screen: $(brief "$scr" 'lines')"
        fi
        end
        if poll 3 has '(end)' && help_body | grep -qE '^q +quit$'; then pass; else
            fail "help: End should go to the end ('(end)', 'q quit'); screen: $(brief "$scr" 'lines')"
        fi
        keys Up
        if poll 3 lacks '(end)'; then pass; else fail "help: ↑ at the end should scroll up; screen: $(brief "$scr" 'lines')"; fi
        keys Escape
        if settle_all 3 "lacks Keys && has Paused && has_re 'space start'"; then pass; else
            fail "help: Esc should close it, leaving the program as it was (paused); screen: $(brief)"
        fi
    else
        fail "help at 80x24: '?' should open it; screen: $(brief)"
    fi
fi

# ---- at the smallest size, 60x20, the help wraps its lines: every text shown whole ----
if up help60; then
    keys '?'
    if wait_for 'preset menu'; then
        help_body >"$tmp/h60.all"
        page_to_end "$tmp/h60.all"
        tr -s ' ' <"$tmp/h60.all" | tr '\n' ' ' | tr -s ' ' >"$tmp/h60.text"
        cut=
        tab=$(printf '\t')
        while IFS=$tab read -r k what; do
            grep -qF -- "$(printf '%s' "$what" | tr -s ' ')" "$tmp/h60.text" || cut="$cut | $k: $what"
        done <"$tmp/keys"
        if has '(end)' && [ -s "$tmp/keys" ] && [ -z "$cut" ]; then pass; else
            fail "help at 60x20: scrolled to the end, these lines of --keys are not shown whole$cut; screen: $(brief "$scr" 'lines')"
        fi
    else
        fail "help at 60x20: '?' should open it; screen: $(brief)"
    fi
fi

# ---- the footer's hints follow the state ----
# hints SIZE: at the start, running, paused, in a view
footer() { sed -n "$(awk 'END { print NR }' "$scr")p" "$scr"; }
hints() {
    # the first message goes at the first key: the help opened and closed
    keys '?'
    wait_for 'preset menu' 3
    keys '?'
    if wait_re ' space start( |$)'; then
        if footer | grep -qE '(^| )space start( |$)' && ! footer | grep -q 'space pause'; then pass; else
            fail "hints $1: paused, the bottom line should say 'space start'; it says: $(footer)"
        fi
    else
        fail "hints $1: paused, the bottom line should say 'space start'; screen: $(brief)"
    fi
    if footer | grep -qF 'm f e'; then pass; else
        fail "hints $1: the bottom line should name the views, 'm f e'; it says: $(footer)"
    fi
    keys Space
    if wait_re ' space pause( |$)'; then
        if has Running && ! footer | grep -q 'space start'; then pass; else
            fail "hints $1: running, the bottom line should say 'space pause'; it says: $(footer)"
        fi
        if footer | grep -qF 'm f e'; then pass; else
            fail "hints $1: running, the bottom line should name the views, 'm f e'; it says: $(footer)"
        fi
    else
        fail "hints $1: running, the bottom line should say 'space pause'; screen: $(brief)"
    fi
    keys 1
    if wait_for '0 all plots'; then pass; else
        fail "hints $1: with plot 1 enlarged the bottom line should offer '0 all plots'; it says: $(footer)"
    fi
    keys m
    if wait_for 'Modes' && footer | grep -qF 'm f e'; then pass; else
        fail "hints $1: in the modes view the bottom line should name 'm f e' (back to plots); it says: $(footer)"
    fi
}
if up hints; then hints 120x40; fi
if up hints80; then hints 80x24; fi

# ---- t and dt with the digits dt needs ----
if up dt1; then
    if has 't = 0.000 s' && has 'dt 0.001 s'; then pass; else
        fail "--dt 0.001: the status line should show 't = 0.000 s' and 'dt 0.001 s'; screen: $(brief)"
    fi
    keys . . .
    if wait_for 't = 0.003 s' 3; then pass; else
        fail "--dt 0.001: three '.' should show 't = 0.003 s'; screen: $(brief)"
    fi
fi
if up dt75; then
    if has 'dt 0.0075 s' && has 't = 0.0000 s'; then pass; else
        fail "--dt 0.0075: the status line should show 'dt 0.0075 s' (and t = 0.0000 s); screen: $(brief)"
    fi
    keys .
    if wait_for 't = 0.0075 s' 3; then pass; else
        fail "--dt 0.0075: '.' should show 't = 0.0075 s'; screen: $(brief)"
    fi
fi

# ---- the preset menu ----
if up menu; then
    keys p
    if wait_for ' Presets ' && wait_for resonance; then
        missing=
        for p in $presets; do
            grep -qE "│ $p( |\$)" "$scr" || missing="$missing $p"
        done
        if [ -z "$missing" ]; then pass; else
            fail "preset menu: expected every built-in preset listed, missing:$missing; screen: $(brief "$scr" 'Presets')"
        fi
        # move down from the first entry to resonance
        first=$(grep -n 'Presets' "$scr" | head -n 1 | cut -d: -f1)
        row=$(grep -nE '│ resonance( |$)' "$scr" | head -n 1 | cut -d: -f1)
        if [ -n "$first" ] && [ -n "$row" ]; then
            n=$((row - first - 1))
            while [ "$n" -gt 0 ]; do
                keys Down
                n=$((n - 1))
            done
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
fi

# ---- a control: fine step, typed value, bad typed value ----
if up ctl; then
    if select_control Frequency; then
        pass
        keys Right
        if wait_re 'Frequency +1\.010 Hz'; then pass; else
            fail "Frequency: → should raise 1.000 Hz to 1.010 Hz; screen: $(brief "$scr" 'Frequency')"
        fi
        keys Enter
        wait_for 'Frequency = ' 3
        text 0.5
        keys Enter
        if wait_re 'Frequency +0\.500 Hz'; then pass; else
            fail "Frequency: Enter, 0.5, Enter should set 0.500 Hz; screen: $(brief "$scr" 'Frequency')"
        fi
        keys Enter
        wait_for 'Frequency = ' 3
        text abc
        keys Enter
        if wait_for "'abc'"; then
            if has_re 'Frequency +0\.500 Hz'; then pass; else
                fail "Frequency: a bad value must change nothing (0.500 Hz); screen: $(brief "$scr" 'Frequency')"
            fi
        else
            fail "Frequency: typing abc should give a message naming 'abc'; screen: $(brief "$scr" 'Frequency')"
        fi
        keys PgUp
        if wait_re 'Frequency +0\.600 Hz'; then pass; else
            fail "Frequency: PgUp (coarse) should raise 0.500 Hz to 0.600 Hz; screen: $(brief "$scr" 'Frequency')"
        fi
    else
        fail "controls: ↓ from Preset should reach Frequency; screen: $(brief "$scr" 'Frequency|Speed')"
    fi
fi

# ---- Tab to the chain, move mass 1 ----
if up chain; then
    sed -n '3,5p' "$scr" >"$tmp/scene0"
    keys Tab
    if wait_for 'mass 1'; then
        pass
        keys Right Right Right
        if wait_for 'mass 1 starts at +0.'; then pass; else
            fail "chain: → should move mass 1 ('mass 1 starts at +0.…'); screen: $(brief)"
        fi
        sed -n '3,5p' "$scr" >"$tmp/scene1"
        if cmp -s "$tmp/scene0" "$tmp/scene1"; then
            fail "chain: the scene rows did not change after moving mass 1; scene: $(brief "$tmp/scene1")"
        else
            pass
        fi
        keys r
        # any key clears the message line, so r has been handled once this one is gone
        if wait_all 3 "lacks 'mass 1 starts at' && has 't = 0.00 s'"; then
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
fi

# ---- every preset runs a second: no crash, no nan/inf ----
bad=
for p in $started; do
    S=pre-$p
    # looked at every 0.1 s until t = 1 s; a screen with nan/inf is a failure
    if poll 6 eval 'has_nonfinite || t_at_least 1'; then
        if has_nonfinite; then
            fail "preset $p: nan/inf on screen while running; screen: $(brief "$scr" '[Nn][Aa][Nn]|[Ii][Nn][Ff]')"
        elif has Running && alive "pre-$p"; then
            pass
        else
            fail "preset $p (-p $p): expected it running at t = 1 s; screen: $(brief)"
        fi
    else
        fail "preset $p (-p $p): expected it running to t = 1 s; screen: $(brief)"
    fi
done

# ---- branch from history: step back, change a parameter, go on ----
S=branch
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

# ---- Ctrl-Z and fg ----
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
all_alive main ctl chain menu help hints hints80 dt1 dt75 branch

summary
