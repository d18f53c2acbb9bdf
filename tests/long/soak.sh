#!/bin/sh
# tests/long/soak.sh: 1e8 steps of a one-mass chain at resonance with collisions, at
# dt = 0.001 (1e5 s of simulated time): no non-finite value, and memory flat (the peak
# resident size at the end is the one after the first second). Ends "soak: N passed, M failed".
NAME=soak
. "$(dirname "$0")/../lib/check.sh"

# The run, with its peak resident size (VmHWM) read after one second and just before
# it ends: flat memory means the two agree.
args="--headless -p resonance --amplitude 0.6 --dt 0.001 --sample 100 --duration 100000"
"$SPRINGSIM" $args >"$tmp/out.csv" 2>"$tmp/err" &
pid=$!
sleep 1
short=$(awk '/^VmHWM/ { print $2 }' "/proc/$pid/status" 2>/dev/null)
long=$short
while kill -0 "$pid" 2>/dev/null; do
    h=$(awk '/^VmHWM/ { print $2 }' "/proc/$pid/status" 2>/dev/null)
    [ -n "$h" ] && long=$h
    sleep 0.2
done
wait "$pid"
rc=$?
rows=$(($(wc -l <"$tmp/out.csv") - 1))
echo "soak: 1e8 steps, exit $rc, $rows rows, peak RSS $short KB after 1 s, $long KB at the end"
if [ "$rc" -eq 0 ]; then pass; else fail "the soak exited $rc: $(head -c 200 "$tmp/err")"; fi
if [ "$rows" -eq 1001 ]; then pass; else fail "expected 1001 rows, got $rows"; fi
if grep -qi 'nan\|inf' "$tmp/out.csv"; then fail "non-finite values in the output"; else pass; fi
# Collisions really happened: the mass reached the walls (|x| near 4.8 m).
if awk -F, 'NR > 1 && ($2 > 4.5 || $2 < -4.5) { hit = 1 } END { exit !hit }' "$tmp/out.csv"; then
    pass
else
    fail "the soak never reached the walls: no collisions were tested"
fi
if [ "${short:-0}" -gt 0 ] && [ "$long" -le $((short + 64)) ]; then pass; else
    fail "memory grew: $short KB after 1 s, $long KB after 1e8 steps"
fi
summary
