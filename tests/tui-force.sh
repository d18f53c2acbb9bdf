#!/bin/sh
# tests/tui-force.sh: the force input and the dampers beside the springs in a real terminal
# (tmux, 80x24, -p tuned-mass-damper). The Force and Force on controls show the preset's
# force and its mass; the forced mass carries an arrow on the scene's top row the way the
# force pushes (F→ or ←F), and the damped spring a dashpot on its bottom row (=[ without
# UTF-8). A spring selected in the chain (Tab, ↑↓) names its damper; c types it; the
# arrows change the force and move it to the next mass. A recording of all that holds
# set spring-damping, set force and set force-on and replays bit for bit.
# Run from the repository root as `sh tests/tui-force.sh`, SPRINGSIM naming the binary.
# Ends with "tui-force: N passed, M failed".
NAME=tui-force
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start tmd 80 24 -- -p tuned-mass-damper --record "$tmp/rec.lesson"
start ascii 80 24 LANG=C LC_ALL=C NO_COLOR=1 -- -p tuned-mass-damper
start resp 120 40 -- -p tuned-mass-damper
start rigid 100 30 -- -n 2 --mass 1,2 --spring 0,10,0 --boundary free
start missing 80 24 LANG=C LC_ALL=C -- -n 3 --spring 0,10,0,10

# chain_rows: the scene's three rows inside its frame (alternatives, not a bracket: mawk
# reads one byte of └ there)
chain_rows() { awk '/Chain/ { on = 1; next } on && /^(└|\+)/ { exit } on' "$scr"; }

S=ascii
if up ascii; then
    keys Space
    sleep 1.2
    keys Space
    if wait_for Paused 3 && chain_rows | sed -n 1p | grep -qE '<F|F>' &&
        chain_rows | sed -n 3p | grep -q -- '-=\[-'; then pass; else
        fail "ascii: the forced mass should carry <F or F> and the damped spring a dashpot -=[-; screen: $(brief)"
    fi
fi

S=tmd
if up tmd; then
    if has_re 'Force +0\.50 N' && has_re 'Force on +mass 1'; then pass; else
        fail "tmd: the controls should show Force 0.50 N and Force on mass 1; screen: $(brief "$scr" 'Force')"
    fi
    keys Space
    sleep 1
    keys Space
    if wait_for Paused 3 && chain_rows | sed -n 1p | grep -qE 'F→|←F'; then pass; else
        fail "tmd: the forced mass should carry F→ or ←F on the scene's top row; screen: $(brief)"
    fi
    # the absorber's spring: Tab selects mass 1, ↓ the spring to its right, 2 (1–2)
    keys Tab Down
    if wait_for 'spring 2 (1–2): k 0.454 N/m, c 0.0383 N·s/m' 3 && has 'c damper'; then pass; else
        fail "tmd: the selected spring should name its damper and the c key; screen: $(brief)"
    fi
    keys c
    if wait_for 'spring 2 (1–2): c (N·s/m) =' 3; then pass; else
        fail "tmd: c on a spring should ask for its damper; screen: $(brief)"
    fi
    text 0.05
    keys Enter
    if wait_for 'spring 2 (1–2): c = 0.05 N·s/m' 3; then pass; else
        fail "tmd: the damper typed should be said; screen: $(brief)"
    fi
    keys Tab
    if select_control Force && keys Right && wait_re 'Force +0\.60 N' 3 &&
        select_control 'Force on' && keys Right && wait_re 'Force on +mass 2' 3; then pass; else
        fail "tmd: → should raise the force to 0.60 N and move it to mass 2; screen: $(brief "$scr" 'Force')"
    fi
    keys Space
    sleep 1
    keys q
    poll 5 ended
    f=$tmp/rec.lesson
    if grep -qx 'set spring-damping 0,0.05,0' "$f" && grep -qx 'set force 0.6' "$f" &&
        grep -qx 'set force-on 2' "$f"; then pass; else
        fail "tmd: the recording should hold the damper, the force and its mass: $(sed -n '/^end/,$p' "$f" | tr '\n' '|')"
    fi
    "$SPRINGSIM" --plain --replay "$f" </dev/null >"$tmp/replay.out" 2>&1
    if grep -q 'is the one recorded, bit for bit' "$tmp/replay.out"; then pass; else
        fail "tmd: the recording should replay bit for bit: $(tail -n 3 "$tmp/replay.out" | tr '\n' '|')"
    fi
fi

# The force alone drives the tuned-mass damper: the response view draws its curves (the
# primary's two peaks), not a word that nothing drives the chain.
S=resp
if up resp; then
    keys f
    if wait_for 'drive 0.503 Hz' 3 && ! has 'drives the chain' && [ "$(plot_peaks 'Frequency response')" -ge 2 ]; then
        pass
    else
        fail "resp: f should draw the force's response with its two peaks; screen: $(brief)"
    fi
fi

# A chain no spring holds: its rigid-body mode is named, in the modes view and in plain
# modes, never a NaN damping ratio or an unbounded Q.
S=rigid
if up rigid; then
    keys m
    if wait_for 'rigid-body mode' 3 && ! has nan; then pass; else
        fail "rigid: the modes view should name mode 1 a rigid-body mode; screen: $(brief)"
    fi
fi
# Springs of k = 0 are missing from the scene: no coil between the wall and mass 1 or
# between masses 2 and 3, the others drawn.
S=missing
if up missing && wait_for Paused 3; then
    row=$(chain_rows | sed -n 2p)
    if printf '%s\n' "$row" | grep -qE '^\|## +=1=/' && printf '%s\n' "$row" | grep -qE '=2= +=3=/'; then
        pass
    else
        fail "missing: springs of k = 0 should not be drawn: '$row'"
    fi
fi
printf 'modes\nquit\n' | "$SPRINGSIM" --plain -n 2 --mass 1,2 --spring 0,10,0 --boundary free \
    >"$tmp/rigid.out" 2>&1
if grep -q '^ok modes: 1: 0 Hz, a rigid-body mode' "$tmp/rigid.out" &&
    ! grep -q 'unbounded' "$tmp/rigid.out"; then pass; else
    fail "plain modes should name the rigid-body mode: $(grep modes "$tmp/rigid.out")"
fi

summary
