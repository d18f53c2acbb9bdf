#!/bin/sh
# tests/tui-views.sh: the analysis views of the interactive program in a real terminal
# (tmux): m the modes view, n drive at the nearest mode, f the frequency response, w the
# sine sweep (and its end on every route of a frequency change: the arrow keys, n, a
# typed frequency; the response of a chain changed to a wall end is cleared, not left
# standing under the message), e the energy view (its legend and balance above the data, at 120x40
# and 80x24, the balance and drift small, kinetic + potential constant without damping).
# Run from the repository root as `sh tests/tui-views.sh`, SPRINGSIM naming the binary.
# Ends with "tui-views: N passed, M failed".
NAME=tui-views
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start energy 120 40 -- -p 3-mass-chain
start energy80 80 24 -- -p 3-mass-chain
start nodamp 120 40 -- -p no-damping
start forced 120 40 -- -p tuned-mass-damper
start modes 120 40 -- -p 3-mass-chain
start modes80 80 24 -- -p 3-mass-chain
start near 120 40 -- -p 3-mass-chain --frequency 0.9
start resp 120 40 -- -p 3-mass-chain
start wall 120 40 -- -p 3-mass-chain --boundary wall
start to-wall 120 40 -- -p 3-mass-chain
start sweep 120 40 -- -p 3-mass-chain
start sweep-arrow 120 40 -- -p 3-mass-chain
start sweep-n 120 40 -- -p 3-mass-chain
start sweep-typed 120 40 -- -p 3-mass-chain
sessions="energy energy80 nodamp forced modes modes80 near resp wall to-wall sweep sweep-arrow sweep-n sweep-typed"

# the long runs first
for s in energy energy80 nodamp forced; do
    if up $s; then keys e Space; fi
done
# The sweeps that a change of frequency ends play at 0.1x (the sweep's pace 5x): their
# first point lasts about 12 s of wall time, long enough to change the frequency in it.
for s in sweep-arrow sweep-n sweep-typed; do
    if up $s; then keys '[' '[' '[' '['; fi
done

# ---- m: the modes view ----
# modes SIZE: the modes view of -p 3-mass-chain
modes_whole() { # the three frequencies, the mark on mode 2 only, the control's mark, the titles
    has 'mode 1  0.385 Hz' && has 'mode 2  0.712 Hz' && has 'mode 3  0.930 Hz' &&
        has_re 'mode 2 +0\.712 Hz +◆' && ! has_re 'mode [13] +0\.[0-9]+ Hz +◆' &&
        has_re 'Frequency +0\.712 Hz ◆ f2'
}
modes() {
    keys m
    if wait_re '┌─+ Modes'; then
        pass
        # the shapes swing, the screen never stands still: wait for a frame with it all
        poll 3 modes_whole
        missing=
        for f in 'mode 1  0.385 Hz' 'mode 2  0.712 Hz' 'mode 3  0.930 Hz'; do has "$f" || missing="$missing '$f'"; done
        if [ -z "$missing" ]; then pass; else
            fail "modes (m, -p 3-mass-chain, $1): expected the natural frequencies, missing$missing; screen: $(brief "$scr" 'Modes|Hz')"
        fi
        # the driven mark is on mode 2 only
        if has_re 'mode 2 +0\.712 Hz +◆' && ! has_re 'mode [13] +0\.[0-9]+ Hz +◆'; then pass; else
            fail "modes ($1): expected '◆' next to mode 2 (0.712 Hz) only; screen: $(brief "$scr" 'mode ')"
        fi
        if has_re 'Frequency +0\.712 Hz ◆ f2'; then pass; else
            fail "modes ($1): the Frequency control should show '0.712 Hz ◆ f2'; screen: $(brief "$scr" 'Frequency')"
        fi
        # each shape is drawn (braille dots under each title)
        shapes=$(awk '/mode [1-3]  0\.[0-9]+ Hz/ { n++ } END { print n + 0 }' "$scr")
        if [ "$shapes" -eq 2 ] || [ "$shapes" -eq 3 ]; then pass; else
            fail "modes ($1): expected the three modes' titles on two or three rows; screen: $(brief "$scr" 'mode ')"
        fi
        keys m
        if wait_all 3 "has '1 Displacement (m)' && ! has_re '┌─+ Modes'"; then pass; else
            fail "modes ($1): m again should bring back the plots; screen: $(brief "$scr" 'Modes|Displacement')"
        fi
    else
        fail "modes ($1): m should open a frame titled 'Modes'; screen: $(brief)"
    fi
}
if up modes; then modes 120x40; fi
if up modes80; then modes 80x24; fi

# ---- n: drive at the nearest natural frequency ----
if up near; then
    if has_re 'Frequency +0\.900 Hz' && ! has_re 'Frequency +0\.900 Hz ◆'; then pass; else
        fail "n: --frequency 0.9 should show 'Frequency 0.900 Hz' with no mode mark; screen: $(brief "$scr" 'Frequency')"
    fi
    keys n
    if wait_re 'Frequency +0\.930 Hz ◆ f3' 3; then
        if wait_all 3 "sed -n 1p \"\$scr\" | grep -qF ' 0.93 Hz'"; then pass; else
            fail "n: the status line's motor should say 0.93 Hz; screen: $(brief)"
        fi
    else
        fail "n (from 0.9 Hz, -p 3-mass-chain): expected 'Frequency 0.930 Hz ◆ f3'; screen: $(brief "$scr" 'Frequency')"
    fi
fi

# ---- f: the frequency response view ----
if up resp; then
    keys f
    if settle_re '┌─+ Frequency response'; then
        pass
        if has_re ' 1e-1┤' && has_re ' 1e-2┤'; then pass; else
            fail "response (f): expected decade labels 1e-1, 1e-2 on the amplitude axis; screen: $(brief "$scr" '┤')"
        fi
        bad=$(plot_ticks 'Frequency response')
        if [ -z "$bad" ]; then pass; else fail "response: the amplitude axis: $bad"; fi
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
        if wait_all 3 "has '1 Displacement (m)' && lacks 'Frequency response'"; then pass; else
            fail "response: f again should bring back the plots; screen: $(brief)"
        fi
    else
        fail "response: f should open a frame titled 'Frequency response'; screen: $(brief)"
    fi
fi
if up wall; then
    keys f
    if wait_for 'Frequency response' && settle_for 'Nothing drives the chain' 2; then pass; else
        fail "response with --boundary wall: expected 'Nothing drives the chain'; screen: $(brief "$scr" 'drive|response')"
    fi
    keys w
    if settle_for 'a sweep needs a drive' 3 && has Paused && lacks 'sweep 1/'; then pass; else
        fail "w with --boundary wall: no sweep should start, a message should say it needs a drive; screen: $(brief)"
    fi
fi
# amp_frame: the response view's upper frame, from its title to the phase frame
amp_frame() { awk '/Response|Frequency response/ { on = 1 } on && /Phase/ { exit } on' "$scr"; }
if up to-wall; then
    # the curves of the driven chain, then Right end (the 8th control) set to wall
    keys f
    if settle_re '^│ +1e0┤' 3; then
        keys Down Down Down Down Down Down Down Right
        if settle_for 'Nothing drives the chain' 3 && [ "$(amp_frame | grep -c '1e[0-9]')" = 0 ] &&
            ! amp_frame | LC_ALL=C grep -q "$(printf '\342[\240-\243]')"; then pass; else
            fail "response after Right end = wall: the old curves and their 1e.. axis should be cleared, not left under the message; screen: $(brief "$scr" 'drive|1e')"
        fi
    else
        fail "to-wall: f should draw the response with a 1e0 tick; screen: $(brief "$scr" '1e')"
    fi
fi

# ---- w: the sine sweep ----
if up sweep; then
    keys w
    if wait_re 'sweep 1/40 at [0-9.]+ Hz'; then
        pass
        if wait_all 3 "has 'Frequency response' && has Running"; then pass; else
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
            if wait_gone 'sweep 1/40' 3; then pass; else
                fail "sweep: after w the bottom border should no longer show the sweep; screen: $(brief "$scr" sweep)"
            fi
        else
            fail "sweep: w again should stop it with 'sweep stopped after'; screen: $(brief)"
        fi
    else
        fail "sweep: w should start a sweep ('sweep 1/40 at ... Hz'); screen: $(brief "$scr" sweep)"
    fi
fi

# ---- a running sweep ends on every route of a frequency change ----
# sweep_ends HOW WANT: the sweep of $S, changed by HOW, is over (the border offers
# "w: sweep" again, no "sweep k/40"), the motor stays at WANT Hz, and the message says so.
sweep_ends() {
    if ! wait_all 3 "has_re '└.*w: sweep' && ! has_re 'sweep [0-9]+/40'"; then
        fail "sweep, $1: the sweep should end (border 'w: sweep', no 'sweep k/40'); screen: $(brief "$scr" 'sweep')"
        return
    fi
    pass
    msg=$(last_line)
    # half a second of the simulation later (the sweep, were it going, would have set
    # its own frequency again)
    wait_t "$(awk -v t="$(status_t)" 'BEGIN { print t + 0.5 }')" 3
    if sed -n 1p "$scr" | grep -qF " motor sine $2 Hz"; then pass; else
        fail "sweep, $1: the motor should stay at $2 Hz; screen: $(brief)"
    fi
    case $msg in
    *"sweep stopped"* | *"stopped the sweep"* | *"sweep ended"*) pass ;;
    *) fail "sweep, $1: the message should say the sweep stopped, as for → on Frequency; it says '$msg'" ;;
    esac
}
if up sweep-arrow; then
    keys w
    if wait_re 'sweep 1/40 at 0\.19[0-9]* Hz' && has '│ 5x'; then
        if select_control Frequency && wait_re '▸Frequency +0\.19'; then
            keys Right
            sweep_ends "→ on Frequency" 0.20
        else
            fail "sweep, → on Frequency: cannot select Frequency at 0.19 Hz; screen: $(brief "$scr" Frequency)"
        fi
    else
        fail "sweep: w at 0.1x should start a sweep at 0.19 Hz, played at 5x; screen: $(brief "$scr" sweep)"
    fi
fi
if up sweep-n; then
    keys w
    if wait_re 'sweep 1/40 at 0\.19[0-9]* Hz' && has '│ 5x'; then
        keys n
        sweep_ends "n" 0.39
    else
        fail "sweep: w at 0.1x should start a sweep at 0.19 Hz, played at 5x; screen: $(brief "$scr" sweep)"
    fi
fi
if up sweep-typed; then
    keys w
    if wait_re 'sweep 1/40 at 0\.19[0-9]* Hz' && has '│ 5x'; then
        if select_control Frequency; then
            keys Enter
            wait_for 'Frequency = ' 3
            text 0.5
            keys Enter
            sweep_ends "a typed frequency" 0.50
        else
            fail "sweep, typed frequency: cannot select Frequency; screen: $(brief "$scr" Frequency)"
        fi
    else
        fail "sweep: w at 0.1x should start a sweep at 0.19 Hz, played at 5x; screen: $(brief "$scr" sweep)"
    fi
fi

# ---- e: the energy view ----
# energy SIZE: the view of -p 3-mass-chain after 2 s, paused
energy() {
    t=$(settled_t)
    if plot_awk 'END { exit !plot("Energy (J)") }'; then pass; else
        fail "energy (e, $1): expected a frame titled 'Energy (J)' with axes; screen: $(brief)"
        return
    fi
    missing=
    for w in kinetic potential damped motor contact; do
        grep -qE "━ $w -?[0-9]" "$scr" || missing="$missing '$w'"
    done
    if [ -z "$missing" ]; then pass; else
        fail "energy ($1): after $t s the legend ('━ kinetic 0.0212  ━ potential …') lacks$missing; screen: $(brief "$scr" 'kinetic|damped')"
    fi
    wk=$(sed -n 's/.*━ motor \([-0-9][-0-9.e+]*\).*/\1/p' "$scr" | head -n 1)
    if awk -v w="$wk" 'BEGIN { exit !(w != "" && w + 0 > 0) }'; then pass; else
        fail "energy ($1): the motor should have done work after $t s, legend says '$wk'; screen: $(brief "$scr" 'motor [-0-9]')"
    fi
    line=$(grep -E 'balance -?[0-9][-0-9.e+]* J +drift -?[0-9][-0-9.e+]* of the peak' "$scr" | head -n 1)
    if awk -v l="$line" 'BEGIN { n = split(l, w, " ")
            for (i = 1; i < n; i++) { if (w[i] == "balance") b = w[i + 1]; if (w[i] == "drift") d = w[i + 1] }
            exit !(l != "" && b < 1e-4 && b > -1e-4 && d < 1e-4 && d > -1e-4) }'; then pass; else
        fail "energy ($1): after $t s of -p 3-mass-chain expected 'balance X J  drift Y of the peak' with both below 1e-4; screen: $(brief "$scr" 'balance')"
    fi
    # the texts sit above the data: between the frame's top and the highest gridline,
    # on rows with no dots, and neither the title nor the bottom border holds numbers
    where=$(plot_awk 'END {
        if (!plot("Energy (J)")) exit
        for (r = top + 1; r < axr && cell(r, axc) != "┤"; r++) {
            s = ""; for (k = left + 1; k < right; k++) { s = s cell(r, k); if (braille(c[r, k])) dots = 1 }
            if (s ~ /kinetic/) kin = r; if (s ~ /contact/) con = r; if (s ~ /balance/) bal = r
        }
        print (kin && con && bal && !dots) ? "above" : "not above" }')
    if [ "$where" = above ]; then pass; else
        fail "energy ($1): the legend and the balance line should be above the data (under the title, before the first gridline, no dots on their rows); screen: $(brief "$scr" 'kinetic|balance|contact')"
    fi
    if ! grep -E '^┌.*Energy \(J\)' "$scr" | grep -qE '[0-9]' && ! grep -E '^└' "$scr" | grep -qE 'balance|drift|kinetic'; then
        pass
    else
        fail "energy ($1): the title and the bottom border should hold no values; screen: $(brief "$scr" '^(┌|└)')"
    fi
    bad=$(plot_ticks 'Energy (J)')
    if [ -z "$bad" ]; then pass; else fail "energy ($1): the y axis: $bad"; fi
}
for s in energy energy80; do
    S=$s
    case $s in energy) size=120x40 ;; *) size=80x24 ;; esac
    if wait_t 2; then
        keys Space
        energy $size
    else
        fail "energy ($size): expected it to run to t = 2 s; screen: $(brief)"
    fi
done
# A force's work is a term of the balance: named in the legend, and the balance holds.
S=forced
if wait_t 3; then
    keys Space
    t=$(settled_t)
    fw=$(sed -n 's/.*━ force \([-0-9][-0-9.e+]*\).*/\1/p' "$scr" | head -n 1)
    bal=$(sed -n 's/.*balance \([-0-9][-0-9.e+]*\) J.*/\1/p' "$scr" | head -n 1)
    if awk -v f="$fw" -v b="$bal" 'BEGIN { exit !(f != "" && f + 0 > 0.1 && b != "" && b < 1e-6 && b > -1e-6) }'; then
        pass
    else
        fail "energy, -p tuned-mass-damper: after $t s expected '━ force W' (W > 0.1 J) and a balance within 1e-6 J: force '$fw', balance '$bal'; screen: $(brief "$scr" 'kinetic|force|balance')"
    fi
else
    fail "energy, -p tuned-mass-damper: expected it to run to t = 3 s; screen: $(brief)"
fi
S=nodamp
if wait_t 3; then
    keys Space
    t=$(settled_t)
    kp=$(sed -n 's/.*━ kinetic \([-0-9][-0-9.e+]*\) .*━ potential \([-0-9][-0-9.e+]*\).*/\1 \2/p' "$scr" | head -n 1)
    if awk -v kp="$kp" 'BEGIN { n = split(kp, a, " "); s = a[1] + a[2]
                           exit !(n == 2 && s > 39.9 && s < 40.1) }'; then pass; else
        fail "energy, -p no-damping: after $t s kinetic + potential should be 40 J, legend: '$kp'; screen: $(brief "$scr" 'kinetic')"
    fi
else
    fail "energy, -p no-damping: expected it to run to t = 3 s; screen: $(brief)"
fi

all_alive $sessions

summary
