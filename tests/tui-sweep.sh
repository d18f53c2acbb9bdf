#!/bin/sh
# tests/tui-sweep.sh: the sine sweep (w in the frequency response view f) of the default
# chain in a real terminal (tmux, 80x24): it plays faster than real time and says so,
# counts its points, and ends within 2 minutes of wall time with every point steady and
# no contact; at an amplitude whose steady swings would close a gap, the view says from
# which amplitude contacts are expected before w, and w says so again as it starts. That
# amplitude is checked against the linear theory's swings (--sweep's CSV at the same 40
# frequencies, half the first mode to 1.5 times the second) and the gaps at rest.
# Run from the repository root as `sh tests/tui-sweep.sh`, SPRINGSIM naming the binary.
# Ends with "tui-sweep: N passed, M failed".
NAME=tui-sweep
. "$(dirname "$0")/lib/check.sh"
. "$(dirname "$0")/lib/tmux.sh"

start def 80 24
start amp1 80 24 -- --amplitude 1
sessions="def amp1"

now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

# ---- the defaults' sweep, timed from w to its end ----
S=def
if wait_for 'space starts' 5; then
    keys f
    wait_for 'w: sweep' 3
    keys w
    t0=$(now)
    if wait_re 'sweep 1/40 at 0\.25[0-9] Hz' 3 && has 'at 50x, each point once steady to 1 %; w stops it' && has_re '│ 50x'; then
        pass
    else
        fail "w at the defaults: expected 'sweep 1/40 at 0.25x Hz', the message 'at 50x, each point once steady to 1 %; w stops it' and the pace 50x in the status line; screen: $(brief "$scr" 'sweep')"
    fi
    # Once a second until it ends (2 minutes at most): the count only goes up.
    count=1 back=
    while :; do
        cap
        has 'sweep done' && break
        [ "$(since "$t0" | cut -d. -f1)" -ge 120 ] && break
        k=$(sed -n 's/.*sweep \([0-9]*\)\/40 at.*/\1/p' "$scr" | head -n 1)
        [ -n "$k" ] && [ "$k" -lt "$count" ] && back="$back $count->$k"
        [ -n "$k" ] && count=$k
        sleep 1
    done
    took=$(since "$t0")
    echo "the defaults' sweep took $took s of wall time"
    if has 'sweep done: 40 frequencies measured' && has 'back at 1.000 Hz' &&
        has '● measured: 40 points' && lacks 'contact'; then pass; else
        fail "the defaults' sweep should end within 120 s, 40 points, all steady, no contact; after $took s: $(brief "$scr" 'sweep|contact')"
    fi
    if [ -z "$back" ] && [ "$count" -ge 30 ]; then pass; else
        fail "the count should go up to the end (last seen $count/40; went back:$back)"
    fi
    if lacks '50x' && has_re 'Paused|Running'; then pass; else
        fail "after the sweep the pace should be the Speed control's again; $(brief)"
    fi
fi

# ---- contacts expected: the amplitude from the linear theory and the gaps ----
# The gaps at rest of two masses 10/3 m apart, blocks 0.4 m wide: wall and piston 3.1333
# m, between the masses 2.9333 m. Each closes when its swing (|X1|, |X2 - X1|, |X2 - A|
# from the CSV's amplitudes and phases) reaches it; swings scale with A.
"$SPRINGSIM" --modes >"$tmp/modes.csv"
range=$(awk -F, 'NR == 2 { lo = $2 } NR == 3 { hi = $2 } END { printf "%.17g:%.17g", 0.5 * lo, 1.5 * hi }' "$tmp/modes.csv")
"$SPRINGSIM" --sweep "$range:40" --amplitude 1 >"$tmp/sweep.csv"
want=$(awk -F, 'NR > 1 {
        r = atan2(0, -1) / 180; a1 = $2; a2 = $3; p1 = $4 * r; p2 = $5 * r
        x1 = a1 * cos(p1); y1 = a1 * sin(p1); x2 = a2 * cos(p2); y2 = a2 * sin(p2)
        w = 10 / 3 - 0.2; m = 10 / 3 - 0.4
        c = w / sqrt(x1 * x1 + y1 * y1)
        d = m / sqrt((x2 - x1) ^ 2 + (y2 - y1) ^ 2); if (d < c) c = d
        d = w / sqrt((x2 - 1) ^ 2 + y2 * y2); if (d < c) c = d
        if (least == "" || c < least) least = c
    } END { printf "%.2g", least }' "$tmp/sweep.csv")
echo "contacts expected from $want m (the theory's swings against the gaps)"
S=amp1
if wait_for 'space starts' 5; then
    keys f
    if wait_for "w: sweep; contacts expected above $want m" 3; then pass; else
        fail "f at 1 m: the view should say 'contacts expected above $want m' before w; $(brief "$scr" 'sweep')"
    fi
    keys w
    if wait_for "contacts expected above $want m: lower the amplitude; sweeping, w stops it" 3 &&
        has_re 'sweep 1/40 at'; then pass; else
        fail "w at 1 m: the message should say 'contacts expected above $want m: lower the amplitude' and the sweep start; $(brief "$scr" 'sweep|contact')"
    fi
    keys w
    if wait_for 'sweep stopped after' 3; then pass; else fail "w again should stop it; $(brief)"; fi
fi

for s in $sessions; do
    if ! alive "$s"; then
        S=$s
        cap
        fail "$s: the program ended: $(brief)"
    fi
done
summary
