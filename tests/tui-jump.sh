#!/bin/sh
# tests/tui-jump.sh: the sweep experiment on a chain with cubic springs in a real terminal
# (tmux 120x40 and 80x24, -p duffing, f then w): it sweeps up, says so, then down, says
# so, and ends within 3 minutes of wall time; the response view draws the harmonic
# balance (its title and the branches' dots), the sweep up's points (▲), the sweep down's
# (▼) and the folds, and marks where each sweep jumped: the sweep up down past the upper
# fold, the sweep down up past the lower one, each within one step of the sweep (40
# points, half the mode to 1.5 times it) of the fold that --sweep --meta reports headless.
# At 80x24 the amplitude takes the view's whole height. Run from the repository root as
# `sh tests/tui-jump.sh`, SPRINGSIM naming the binary. Ends with "tui-jump: N passed, M
# failed".
NAME=tui-jump
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start big 120 40 -- -p duffing
start small 80 24 -- -p duffing
sessions="big small"

# The independent answer: the sweep's range (half the linearised mode to 1.5 times it)
# and the folds of harmonic balance, headless.
"$SPRINGSIM" -p duffing --modes >"$tmp/modes.csv"
range=$(awk -F, 'NR == 2 { printf "%.17g:%.17g", 0.5 * $2, 1.5 * $2 }' "$tmp/modes.csv")
"$SPRINGSIM" -p duffing --sweep "$range:40" --meta >"$tmp/hb.csv"
lo=$(sed -n 's/^# fold [0-9]*: \([0-9.e+-]*\) Hz.*/\1/p' "$tmp/hb.csv" | sort -g | head -n 1)
hi=$(sed -n 's/^# fold [0-9]*: \([0-9.e+-]*\) Hz.*/\1/p' "$tmp/hb.csv" | sort -g | tail -n 1)
step=$(echo "$range" | awk -F: '{ printf "%.17g", ($2 - $1) / 39 }')
echo "sweep $range, step $step Hz; folds of harmonic balance: $lo and $hi Hz"
if [ -n "$lo" ] && [ -n "$hi" ] && [ "$lo" != "$hi" ]; then pass; else
    fail "--sweep --meta should report two folds; got: $(grep '^#' "$tmp/hb.csv" | tr '\n' ' ')"
fi
folds=$(awk -v a="$lo" -v b="$hi" 'BEGIN { printf "folds %.3f %.3f Hz", a, b }')

# Both sessions sweep at once, each timed from its w.
for S in $sessions; do
    if wait_for 'space starts' 5; then
        keys f
        wait_for 'w: sweep' 3 || fail "$S: f should show 'w: sweep'; $(brief)"
        keys w
    fi
done
t0=$(date +%s)
S=big
if wait_for 'sweeping up 0.36..1.07 Hz at 50x, then down' 3 && has_re 'sweeping up [0-9]+/40 at' &&
    has 'Harmonic balance: amplitude (m), stable ━ unstable ┅ backbone ┄' && has "$folds"; then
    pass
else
    fail "w: the message 'sweeping up 0.36..1.07 Hz at 50x, then down', the legend's 'sweeping up k/40', the title and '$folds' expected; $(brief "$scr" 'sweep|balance|fold')"
fi
if wait_for 'sweeping down 1.07..0.36 Hz, from the state the sweep up ended in' 150 &&
    has_re 'sweeping down [0-9]+/40 at' && has '▲' && has '↓0.8'; then pass; else
    fail "after the sweep up: 'sweeping down 1.07..0.36 Hz' and the up points (▲) and jump (↓0.8x) expected; $(brief "$scr" 'sweep|▲')"
fi
if wait_for 'sweep done: 40 frequencies measured up and down' 150; then pass; else
    fail "the sweep down should end within 3 minutes of w; $(brief "$scr" 'sweep')"
fi
echo "the sweeps up and down took $(($(date +%s) - t0)) s of wall time"
settle 5 has 'jumped ↓'
# The points of both (◆ where both share a cell), and the branches: braille dots in the
# amplitude chart's rows, the unstable branch among them, more than the points alone.
braille=$(printf '\342[\240-\243]') # the UTF-8 lead bytes of U+2800..U+28FF
dots=$(sed -n '8,26p' "$scr" | LC_ALL=C grep -o "$braille" | wc -l)
if has '▲' && has '▼' && has '◆' && has '▲ up' && has '▼ down' && [ "$dots" -ge 60 ]; then pass; else
    fail "both sweeps' points (▲, ▼, ◆) and the branches (60 braille cells, $dots seen) expected; $(brief "$scr" 'up|down')"
fi
# Where each jumped, as the legend says it, against the theory's folds.
jumps=$(sed -n 's/.*jumped ↓\([0-9.]*\), ↑\([0-9.]*\) Hz.*/\1 \2/p' "$scr" | head -n 1)
echo "jumps seen: $jumps (down past the upper fold, up past the lower)"
if [ -n "$jumps" ] && echo "$jumps" | awk -v lo="$lo" -v hi="$hi" -v s="$step" '{
        exit !($1 > hi && $1 - hi <= s && $2 < lo && lo - $2 <= s) }'; then pass; else
    fail "the sweep up should jump within one step ($step Hz) above $hi Hz and the sweep down within one below $lo Hz; legend: '$jumps'; $(brief "$scr" 'jump')"
fi

S=small
if wait_for 'sweep done: 40 frequencies measured up and down' 60 && has '▲' && has '▼' &&
    has_re '↓0\.8[0-9]+,? ↑0\.7[0-9]+' && lacks 'Phase'; then pass; else
    fail "80x24: the jumps, both sweeps' points and no phase panel expected; $(brief "$scr" 'jump|Phase')"
fi
keys w
if wait_for 'sweeping up 0.36..1.07 Hz' 3; then pass; else fail "80x24: w should sweep again; $(brief)"; fi
keys w
if wait_for 'sweep stopped after' 3; then pass; else fail "80x24: w again should stop it; $(brief)"; fi

all_alive $sessions
summary
