#!/bin/sh
# tests/tui-ghost.sh: the ghost (key g) in a real terminal (tmux). At 120x40: g names it
# in the status line ("ghost = live": nothing differs) and in every plot's legend
# (┄ghost); unchanged, it is hidden exactly under the live chain, in the scene and in the
# plots (dropping it changes no dot); after the live damping changes and the chain runs,
# the status names the ghost's damping, its outlined blocks show in the scene and its
# dashed traces in the plots (dropping it changes the plots); g again removes it from the
# status, legends, scene and plots. At 80x24 without UTF-8 or colour, the same names. At
# 60x20, where the status has no room for the ghost's details, it names the ghost whole
# or not at all: never cut mid-word ("│ gho") or mid-number. A new chain (Masses applied,
# a preset) drops the ghost and the message says so.
# Run from the repository root as `sh tests/tui-ghost.sh`, SPRINGSIM naming the binary.
# Ends with "tui-ghost: N passed, M failed".
NAME=tui-ghost
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start ghost 120 40 -- -p 3-mass-chain
start ascii 80 24 LANG=C LC_ALL=C NO_COLOR=1 -- -p 3-mass-chain
start narrow 60 20

# The preset's damping, which the ghost keeps.
c_old=$(sed -n 's/^damping *= *//p' presets/3-mass-chain.ini)

# ghost_in_scene: an outline of the ghost's blocks (box drawing) shows in the scene, the
# frame and the motor's housing apart
ghost_in_scene() {
    awk '/^┌ Chain/ { on = 1; next } on && /^└/ { exit } on' "$scr" |
        sed 's/^│//; s/│$//; s/┌─*┐//; s/┤MOTOR ●│//; s/└─*┘//' | grep -q '[┌┐└┘│]'
}
# plot_dots TITLE: the drawing area of the plot titled TITLE, row by row
plot_dots() {
    plot_awk 'END { if (plot(title)) for (r = axtop; r < axr; r++) { s = ""; for (k = axc + 1; k < right; k++) s = s cell(r, k); print s } }' \
        -v "title=$1"
}
# dots_of FILE: the dots of plots 1 (x) and 4 (x-v) into FILE, once two captures in a
# row agree (a frame may be captured half drawn)
dots_now() { { plot_dots '1 Displacement (m)'; plot_dots '4 x–v (m, m/s)'; } >"$1"; }
dots_again() { cp "$dots_file.new" "$dots_file"; dots_now "$dots_file.new"; cmp -s "$dots_file" "$dots_file.new"; }
dots_of() { dots_file=$1; dots_now "$1.new"; poll 2 dots_again; }
# legends: how many plot legends name the ghost
legends() { grep -o '┄ghost' "$scr" | wc -l | tr -d ' '; }

if up ghost; then
    keys g
    if settle_re '│ ghost = live' && has 'ghost made'; then pass; else
        fail "g at 120x40: the status should say '│ ghost = live' and the message 'ghost made'; screen: $(brief "$scr" 'ghost|springsim')"
    fi
    if [ "$(legends)" -eq 6 ]; then pass; else
        fail "g at 120x40: every one of the six plots' legends should name '┄ghost', $(legends) do; screen: $(brief "$scr" '━1')"
    fi
    # Unchanged, it runs under the live chain, hidden: no outline, no dot of its own.
    keys Space
    wait_t 3
    keys Space
    if settle_for Paused && ! ghost_in_scene && has '│ ghost = live'; then pass; else
        fail "an unchanged ghost should be hidden under the live chain in the scene; screen: $(brief "$scr" 'Chain|▓▓|ghost')"
    fi
    dots_of "$tmp/with"
    keys g
    wait_gone '┄ghost'
    dots_of "$tmp/without"
    if [ -s "$tmp/with" ] && cmp -s "$tmp/with" "$tmp/without"; then pass; else
        fail "an unchanged ghost should draw no dot of its own in plots 1 and 4: dropping it changed them"
    fi
    # A new ghost, then the live damping changed: the two part.
    keys g
    wait_for '│ ghost = live'
    keys Down Down Down Down
    if poll 3 sel_is Damping; then pass; else
        fail "four times Down should select Damping; screen: $(brief "$scr" '▸')"
    fi
    keys Enter C-u
    text 2
    keys Enter
    if settle_all 5 "has_re '│ ghost c $c_old' && has_re '▸Damping +2\.00'"; then pass; else
        fail "with the live damping 2 the status should name the ghost's, '│ ghost c $c_old'; screen: $(brief "$scr" 'ghost|Damping')"
    fi
    keys Space
    wait_t 8 12
    # Running: the two blocks are apart at most instants, together at a few.
    if poll 5 ghost_in_scene; then pass; else
        fail "after 6 s with the damping changed the ghost's outlined blocks should show in the scene; screen: $(brief "$scr" 'Chain|▓▓')"
    fi
    keys Space
    settle_for Paused
    dots_of "$tmp/with"
    keys g
    if settle_gone '┄ghost' && lacks '│ ghost' && has 'ghost dropped' && ! ghost_in_scene; then pass; else
        fail "g again should drop the ghost from the legends, status and scene; screen: $(brief "$scr" 'ghost|Chain')"
    fi
    dots_of "$tmp/without"
    if [ -s "$tmp/with" ] && ! cmp -s "$tmp/with" "$tmp/without"; then pass; else
        fail "the ghost that parted from the live chain should show dots of its own in plots 1 and 4"
    fi
    # Paused, the plots keep their scales however often a key redraws them: 40 keys that
    # move the selection there and back, and the dots are as they were (the scales
    # shrink to the live chain's smaller swing only once it runs again).
    i=0
    while [ $i -lt 20 ]; do
        keys Up
        poll 2 sel_not Damping
        keys Down
        poll 2 sel_is Damping
        i=$((i + 1))
    done
    dots_of "$tmp/again"
    if [ -s "$tmp/again" ] && cmp -s "$tmp/without" "$tmp/again"; then pass; else
        fail "paused, 40 keys that change nothing in the plots rescaled them: plots 1 and 4 differ; screen: $(brief "$scr" '1 Displacement')"
    fi
fi

S=ascii
if up ascii; then
    keys g
    if wait_re '\| ghost = live' && has '~ghost' && lacks '┄'; then pass; else
        fail "g at 80x24 without UTF-8: the status should say '| ghost = live' and a legend '~ghost'; screen: $(brief "$scr" 'ghost')"
    fi
fi

# narrow_status: the status line (trailing blanks off) ends in whole words: the history
# count, "│ ghost", or the ghost's full details
narrow_status() {
    sed -n '1{s/ *$//;p;}' "$scr" | grep -qE '(history [0-9]+|│ ghost|│ ghost dt 0\.01)$'
}
S=narrow
if up narrow; then
    # the live dt one step up (0.011 s): the ghost's own 0.01 is a detail to name
    keys g Down Down Right Space
    if wait_t 10 20 && wait_re '│ history 500' 3 && poll 2 narrow_status; then pass; else
        fail "60x20: with a ghost the status should end in whole words (history N, '│ ghost' or '│ ghost dt 0.01'), not a cut word or number; screen: $(brief "$scr" 'history')"
    fi
    # a new chain (Masses applied, a preset loaded) drops the ghost and says so
    keys Space Up Right Enter
    if wait_for '3 masses, at rest; ghost dropped' 3 && lacks '│ ghost'; then pass; else
        fail "60x20: applying 3 masses should say '3 masses, at rest; ghost dropped ...' and the status lose it; screen: $(brief "$scr" 'mass|ghost')"
    fi
    keys g p Enter
    if wait_re 'preset .+ \(ghost dropped\): ' 3 && lacks '│ ghost'; then pass; else
        fail "60x20: loading a preset should say 'preset NAME (ghost dropped): ...'; screen: $(brief "$scr" 'preset|ghost')"
    fi
fi

summary
